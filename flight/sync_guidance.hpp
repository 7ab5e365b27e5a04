#pragma once
// The synchronised reference (COMRADE 2018's synchronisation phase): once the chaser's
// rotation is synchronised with the tumbling target's, its reference is a point of the target's
// frame, moved from where the synchronisation started to the capture point and then held there,
// turning with the target:
//
//   p(t) = p_start + (p_capture - p_start) s(tau),  tau = (t - start_s) / duration_s in [0, 1],
//   s(tau) = 10 tau^3 - 15 tau^4 + 6 tau^5   (rest to rest: s' = s'' = 0 at both ends),
//
// seen in LVLH through the target's estimated motion (flight/target_frame.hpp), and the attitude
// q_inertial_from_body = q_inertial_from_target (x) q_target_from_body(s) (transfer_attitude: the
// LIDAR's boresight, body +x, held on the target's CoM along the way, the capture attitude
// q_target_from_body reached at the end), its rate the target's in body axes plus the turn of
// q_target_from_body(s). Before start_s the point is p_start (a hold in the target frame), after
// the end p_capture. The jerk is left at zero: the feed-forward's mid-period term it feeds is ~w^3 |r| T/2,
// 3e-5 m/s^2 at ENVISAT's 2.5 deg/s and 7 m, against an authority of 0.055 m/s^2.
// Flown with guidance.synchronised (flight_software.cpp; docs/gnc.md, "Synchronised final
// approach"); the steps before it (fly-around to the angular-momentum axis, approach along it, the
// rotation's synchronisation) are flight/sync_approach.hpp's.
#include "core/types.hpp"
#include "flight/guidance.hpp"
#include "flight/target_estimator.hpp"
#include "model/target_orbit.hpp"

namespace chaser::flight {

struct SyncTransferParams {
  Vec3 start_target_m = Vec3::Zero();    // [m] p_start, target axes from its CoM
  Vec3 capture_target_m = Vec3::Zero();  // [m] p_capture (target.body.capture_point_target_m)
  double start_s = 0.0;                  // [s]
  double duration_s = 1.0;               // [s] > 0
  Quat q_target_from_body = Quat::Identity();  // the chaser's attitude in the target's frame
};

// s(tau), s'(tau), s''(tau) of the quintic rest-to-rest profile, tau clamped to [0, 1].
Eigen::Vector3d rest_to_rest_quintic(double tau);

// The chaser's attitude in the target's frame at p_target_m on the transfer, at progress s in [0, 1]:
// the capture attitude turned by the share 1 - s^8 of the least rotation that puts its +x (the
// LIDAR's and the pose sensor's boresight) on the target's CoM, so that the sensors keep the target
// in view while the line of sight turns (90 deg from the angular-momentum axis to the capture point
// on ENVISAT's +x face); at s = 1, q_target_from_body itself, whose boresight is then off the CoM
// by the capture point's own angle (4.6 deg for ENVISAT's). The share's s^8 keeps the boresight's
// miss, s^8 times the angle, under 5 deg there.
Quat transfer_attitude(const Quat& q_target_from_body, const Vec3& p_target_m, double s);

GuidanceRef sync_reference(const SyncTransferParams& params, const TargetEstimate& target, const model::LvlhFrame& lvlh,
                           double t_s);

}  // namespace chaser::flight
