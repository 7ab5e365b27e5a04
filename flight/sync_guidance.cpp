#include "flight/sync_guidance.hpp"

#include <algorithm>
#include <cmath>

#include "core/rotation.hpp"
#include "flight/target_frame.hpp"

namespace chaser::flight {

Eigen::Vector3d rest_to_rest_quintic(double tau) {
  if (tau <= 0.0) return Eigen::Vector3d(0.0, 0.0, 0.0);
  if (tau >= 1.0) return Eigen::Vector3d(1.0, 0.0, 0.0);
  const double t2 = tau * tau, t3 = t2 * tau;
  return Eigen::Vector3d(t3 * (10.0 - 15.0 * tau + 6.0 * t2), 30.0 * t2 * (1.0 - 2.0 * tau + t2),
                         60.0 * tau * (1.0 - 3.0 * tau + 2.0 * t2));
}

Quat transfer_attitude(const Quat& q_target_from_body, const Vec3& p_target_m, double s) {
  const double s2 = s * s, s4 = s2 * s2;
  const Vec3 boresight = q_target_from_body * Vec3::UnitX();
  return (rotation_towards(boresight, -p_target_m.normalized(), 1.0 - s4 * s4) * q_target_from_body).normalized();
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
  // The attitude's own turn in the target's frame, by a central difference of the progress s
  // (h = 1e-4 of the profile: the turn's second derivative is below 1 rad per unit s^2, so the
  // difference's error, h^2/6 of the third, is far below the rate loops' noise).
  const Quat q_target_from_body = transfer_attitude(params.q_target_from_body, p, s[0]);
  constexpr double kH = 1e-4;
  const double s_lo = std::max(0.0, s[0] - kH), s_hi = std::min(1.0, s[0] + kH);
  const Vec3 turn_per_s =
      s_hi > s_lo ? Vec3(rotation_vector_from_quat(
                             transfer_attitude(params.q_target_from_body, params.start_target_m + leg * s_lo, s_lo)
                                 .conjugate() *
                             transfer_attitude(params.q_target_from_body, params.start_target_m + leg * s_hi, s_hi)) /
                         (s_hi - s_lo))
                  : Vec3::Zero();
  ref.q_inertial_from_body = (target.q_inertial_from_target * q_target_from_body).normalized();
  ref.omega_body_radps = q_target_from_body.conjugate() * target.omega_target_radps + turn_per_s * (s[1] / duration);
  return ref;
}

}  // namespace chaser::flight
