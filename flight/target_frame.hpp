#pragma once
// A point fixed to, or moving in, the tumbling target's frame, as the LVLH frame sees it (in the
// synchronisation phase the chaser's reference is the capture point, which turns with the
// target, and the guidance needs its velocity and acceleration in LVLH for the feed-forward).
//
// With R = R_lvlh_from_target and the target frame's angular velocity relative to LVLH,
//   w = R omega_t - omega_L                                   (LVLH axes)
//   w' = R omega_t' - omega_L x R omega_t - omega_L'           (its derivative seen in LVLH)
// a point p(t) given in target axes is at r = R p, and (Coriolis' theorem, twice)
//   r'  = w x r + R p'
//   r'' = w' x r + w x (w x r) + 2 w x R p' + R p''.
// omega_t, omega_t' are the target's inertial rate and its derivative in target axes (the
// estimator's, flight/target_estimator.hpp); omega_L, omega_L' LVLH's (model/target_orbit.hpp).
#include "core/types.hpp"

namespace chaser::flight {

struct TargetFrameMotion {
  Quat q_lvlh_from_target = Quat::Identity();
  Vec3 omega_rel_lvlh_radps = Vec3::Zero();       // [rad/s] w above, LVLH axes
  Vec3 omega_rel_dot_lvlh_radps2 = Vec3::Zero();  // [rad/s^2] w' above, LVLH axes
};

TargetFrameMotion target_frame_motion(const Quat& q_inertial_from_lvlh, const Vec3& omega_lvlh_radps,
                                      const Vec3& omega_dot_lvlh_radps2, const Quat& q_inertial_from_target,
                                      const Vec3& omega_target_radps, const Vec3& omega_dot_target_radps2);

struct LvlhPoint {
  Vec3 r_m = Vec3::Zero();
  Vec3 v_mps = Vec3::Zero();
  Vec3 a_mps2 = Vec3::Zero();
};

// p, p', p'' in target axes [m, m/s, m/s^2] -> r, r', r'' in LVLH.
LvlhPoint target_point_in_lvlh(const TargetFrameMotion& frame, const Vec3& p_target_m, const Vec3& p_dot_target_mps,
                               const Vec3& p_ddot_target_mps2);

}  // namespace chaser::flight
