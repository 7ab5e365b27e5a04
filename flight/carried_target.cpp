#include "flight/carried_target.hpp"

#include "core/rotation.hpp"

namespace chaser::flight {

arm::FrameMotion estimated_target_frame(const TargetEstimate& e, double t_s) {
  const double dt = t_s - e.t_s;
  const Vec3 omega_target = e.omega_target_radps + e.omega_dot_target_radps2 * dt;
  arm::FrameMotion f;
  f.q_world_from_frame =
      (e.q_inertial_from_target * quat_from_rotation_vector(0.5 * (e.omega_target_radps + omega_target) * dt)).normalized();
  f.omega_radps = f.q_world_from_frame * omega_target;
  f.alpha_radps2 = f.q_world_from_frame * e.omega_dot_target_radps2;
  return f;
}

arm::FrameMotion corrected_target_frame(const TargetEstimate& e, const Vec3& offset_m, const Vec3& rotation_rad,
                                        double t_s) {
  arm::FrameMotion f = estimated_target_frame(e, t_s);
  f.r_m = offset_m;
  f.q_world_from_frame = (f.q_world_from_frame * quat_from_rotation_vector(rotation_rad)).normalized();
  return f;
}

}  // namespace chaser::flight
