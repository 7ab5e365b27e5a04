#include "plant/lvlh_eci.hpp"

namespace chaser::plant {

Mat3 lvlh_axes_from_eci(const Vec3& r_eci_m, const Vec3& v_eci_mps) {
  const Vec3 h = r_eci_m.cross(v_eci_mps);
  const Vec3 x = r_eci_m / r_eci_m.norm();
  const Vec3 z = h / h.norm();
  Mat3 lvlh_from_eci;
  lvlh_from_eci.row(0) = x.transpose();
  lvlh_from_eci.row(1) = z.cross(x).transpose();
  lvlh_from_eci.row(2) = z.transpose();
  return lvlh_from_eci;
}

LvlhOfTarget lvlh_of_target(const Vec3& r_eci_m, const Vec3& v_eci_mps, const Vec3& a_eci_mps2) {
  const double h_norm = r_eci_m.cross(v_eci_mps).norm();
  const double r_norm = r_eci_m.norm();
  LvlhOfTarget f;
  f.lvlh_from_eci = lvlh_axes_from_eci(r_eci_m, v_eci_mps);
  const Vec3 z = f.lvlh_from_eci.row(2).transpose();
  f.omega_lvlh_radps = Vec3(r_norm / h_norm * a_eci_mps2.dot(z), 0.0, h_norm / (r_norm * r_norm));
  return f;
}

RelativeLvlh relative_lvlh_from_eci(const LvlhOfTarget& frame, const RelativeEci& rel) {
  const Vec3 r = frame.lvlh_from_eci * rel.dr_eci_m;
  return {r, frame.lvlh_from_eci * rel.dv_eci_mps - frame.omega_lvlh_radps.cross(r)};
}

RelativeEci relative_eci_from_lvlh(const LvlhOfTarget& frame, const RelativeLvlh& rel) {
  const Mat3 eci_from_lvlh = frame.lvlh_from_eci.transpose();
  return {eci_from_lvlh * rel.r_lvlh_m,
          eci_from_lvlh * (rel.v_lvlh_mps + frame.omega_lvlh_radps.cross(rel.r_lvlh_m))};
}

}  // namespace chaser::plant
