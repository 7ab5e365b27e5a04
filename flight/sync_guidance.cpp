#include "flight/sync_guidance.hpp"

#include <algorithm>

#include "flight/target_frame.hpp"

namespace chaser::flight {

Eigen::Vector3d rest_to_rest_quintic(double tau) {
  if (tau <= 0.0) return Eigen::Vector3d(0.0, 0.0, 0.0);
  if (tau >= 1.0) return Eigen::Vector3d(1.0, 0.0, 0.0);
  const double t2 = tau * tau, t3 = t2 * tau;
  return Eigen::Vector3d(t3 * (10.0 - 15.0 * tau + 6.0 * t2), 30.0 * t2 * (1.0 - 2.0 * tau + t2),
                         60.0 * tau * (1.0 - 3.0 * tau + 2.0 * t2));
}

GuidanceRef sync_reference(const SyncTransferParams& params, const TargetEstimate& target, const model::LvlhFrame& lvlh,
                           double t_s) {
  const double duration = std::max(params.duration_s, 1e-9);
  const Eigen::Vector3d s = rest_to_rest_quintic((t_s - params.start_s) / duration);
  const Vec3 leg = params.capture_target_m - params.start_target_m;
  const Vec3 p = params.start_target_m + leg * s[0];
  const Vec3 p_dot = leg * (s[1] / duration);
  const Vec3 p_ddot = leg * (s[2] / (duration * duration));
  const TargetFrameMotion frame =
      target_frame_motion(lvlh.q_inertial_from_lvlh, lvlh.omega_lvlh_radps, lvlh.omega_dot_lvlh_radps2,
                          target.q_inertial_from_target, target.omega_target_radps, target.omega_dot_target_radps2);
  const LvlhPoint point = target_point_in_lvlh(frame, p, p_dot, p_ddot);
  GuidanceRef ref;
  ref.r_lvlh_m = point.r_m;
  ref.v_lvlh_mps = point.v_mps;
  ref.a_lvlh_mps2 = point.a_mps2;
  ref.q_inertial_from_body = (target.q_inertial_from_target * params.q_target_from_body).normalized();
  ref.omega_body_radps = params.q_target_from_body.conjugate() * target.omega_target_radps;
  return ref;
}

}  // namespace chaser::flight
