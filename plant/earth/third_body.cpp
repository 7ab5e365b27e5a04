#include "plant/earth/third_body.hpp"

#include <cmath>

#include "core/battin.hpp"

namespace chaser::plant::earth {

Vec3 third_body_acceleration_eci(double mu3_m3ps2, const Vec3& r_eci_m, const Vec3& body_eci_m) {
  // Battin 1999, sec. 8.4: |s - r|^3 / |s|^3 = (1 + q)^(3/2), q = r.(r - 2 s) / |s|^2.
  const double q = r_eci_m.dot(r_eci_m - 2.0 * body_eci_m) / body_eci_m.squaredNorm();
  const double d = (body_eci_m - r_eci_m).norm();
  return -mu3_m3ps2 / (d * d * d) * (r_eci_m + battin_f(q) * body_eci_m);
}

Vec3 differential_third_body_eci(double mu3_m3ps2, const Vec3& r_target_eci_m, const Vec3& dr_eci_m,
                                 const Vec3& body_eci_m) {
  // d from the target to the body, e from the chaser: |e|^2 = |d|^2 (1 + q), q = dr.(dr - 2 d) / |d|^2.
  const Vec3 d = body_eci_m - r_target_eci_m;
  const double q = dr_eci_m.dot(dr_eci_m - 2.0 * d) / d.squaredNorm();
  const double e = (d - dr_eci_m).norm();
  return -mu3_m3ps2 / (e * e * e) * (dr_eci_m + battin_f(q) * d);
}

}  // namespace chaser::plant::earth
