#include "flight/target_frame.hpp"

namespace chaser::flight {

TargetFrameMotion target_frame_motion(const Quat& q_inertial_from_lvlh, const Vec3& omega_lvlh_radps,
                                      const Vec3& omega_dot_lvlh_radps2, const Quat& q_inertial_from_target,
                                      const Vec3& omega_target_radps, const Vec3& omega_dot_target_radps2) {
  TargetFrameMotion out;
  out.q_lvlh_from_target = q_inertial_from_lvlh.conjugate() * q_inertial_from_target;
  const Vec3 omega_t_lvlh = out.q_lvlh_from_target * omega_target_radps;
  out.omega_rel_lvlh_radps = omega_t_lvlh - omega_lvlh_radps;
  out.omega_rel_dot_lvlh_radps2 =
      out.q_lvlh_from_target * omega_dot_target_radps2 - omega_lvlh_radps.cross(omega_t_lvlh) - omega_dot_lvlh_radps2;
  return out;
}

LvlhPoint target_point_in_lvlh(const TargetFrameMotion& frame, const Vec3& p, const Vec3& p_dot, const Vec3& p_ddot) {
  const Vec3& w = frame.omega_rel_lvlh_radps;
  const Vec3& w_dot = frame.omega_rel_dot_lvlh_radps2;
  LvlhPoint out;
  out.r_m = frame.q_lvlh_from_target * p;
  const Vec3 p_dot_lvlh = frame.q_lvlh_from_target * p_dot;
  out.v_mps = w.cross(out.r_m) + p_dot_lvlh;
  out.a_mps2 = w_dot.cross(out.r_m) + w.cross(w.cross(out.r_m)) + 2.0 * w.cross(p_dot_lvlh) +
               frame.q_lvlh_from_target * p_ddot;
  return out;
}

}  // namespace chaser::flight
