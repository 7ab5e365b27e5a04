#pragma once
// COMRADE's synchronisation phase before the transfer (COMRADE 2018, sec. 2.1): from the
// end of the V-bar line (radius R = guidance.capture_distance_m on the line's axis u0) the chaser
//   1. flies around the sphere of radius R to the target's angular-momentum axis a (LVLH),
//   2. approaches along that axis to the distance d (guidance.synchronised.approach.axis_distance_m),
//   3. synchronises its rotation with the target's: the attitude turns from pointing at the target
//      to turning with it, the position from the axis point to the same point fixed in the target,
//   4. then transfers to the capture point in the target's frame and holds (flight/sync_guidance.hpp).
// Each step's progress is the rest-to-rest quintic s(tau) (sync_guidance.hpp), so position, speed
// and acceleration are continuous across the steps.
//
// The axis: the target's angular momentum h = R_it I omega_t is fixed in inertial space while the
// target is torque-free, so the flight software fixes its direction once, from its own estimate, when
// the fly-around starts; in LVLH it is a(t) = R_lvlh_from_inertial(t) h / |h| (it turns about the
// orbit normal at -n unless it lies along it, as in spin cases S1 and S2). A point on it does not
// move with the spin, only with the orbit: the chaser can wait there for as long as the estimator
// needs. At the start of step 3 the axis point d a is fixed in the target's frame (p_start, target
// axes), and the transfer starts from there.
//
//   step 1:  r = R g(s),  g = u0 turned towards a(t) by s theta about u0 x a (the great circle)
//   step 2:  r = (R + (d - R) s) a(t)
//   step 3:  r = (1 - s) d a(t) + s R_lvlh_from_target(t) p_start
// Attitude while pointing (line, steps 1-2): the line's target-pointing attitude turned by the
// least rotation that takes -u0 onto -r/|r| (in LVLH), so that body +x stays on the target and the
// roll follows smoothly from the line's; in step 3 the attitude is slerp(pointing, turning with the
// target, s), the latter q_inertial_from_target q_target_from_body.
//
// Velocity, acceleration and the body rate come from central differences of these closed-form
// poses over +-h (h = 0.05 s), with the target's estimated attitude carried to t +- h by its rate and
// rate derivative (second order: the odd error terms cancel in the central difference). Error of the
// difference: h^2/12 r'''' -- with the target's 2.5 deg/s and d = 12 m, w^4 d h^2/12 ~ 1e-8 m/s^2
// against an authority of 0.055 m/s^2 -- and rounding 2 eps |r| / h^2 ~ 3e-12 m/s^2 at 30 m. The
// test checks them against the closed forms of a fixed axis (tests/flight/sync_approach_test.cpp).
#include <optional>

#include "flight/guidance.hpp"
#include "flight/sync_guidance.hpp"
#include "flight/target_estimator.hpp"
#include "model/gnc.hpp"
#include "model/target_orbit.hpp"

namespace chaser::flight {

enum class SyncStep { kLine, kFlyAround, kAxisApproach, kRotationSync, kTransfer };

struct SyncApproachPlan {
  model::GuidanceParams line;            // the V-bar line before the fly-around (and its attitude)
  model::SyncApproachParams approach;    // the steps' times and the axis distance
  SyncTransferParams transfer;           // the transfer; its start_target_m is p_start, fixed in flight
  Mat3 target_inertia_kgm2 = Mat3::Identity();  // what h = I omega is computed with (the estimator's)
};

// What the flight software fixes once from its own estimate (and the truth's judgement reuses).
struct SyncApproachLatch {
  std::optional<Vec3> axis_inertial;    // unit a in inertial axes, fixed when the fly-around starts
  std::optional<Vec3> start_target_m;   // [m] p_start, fixed when the rotation's synchronisation starts
  std::optional<Quat> sync_offset;      // the pointing attitude in the target's frame then
};

SyncStep sync_step(const SyncApproachPlan& plan, double t_s);

// The reference at t_s. Fixes the axis (and p_start) the first time it is asked at or after its step's
// start with a target estimate; until the axis is fixed it is the line's reference (which holds at its
// end). The target estimate is needed from the rotation's synchronisation on; without one the
// reference stays on the axis.
GuidanceRef sync_approach_reference(const SyncApproachPlan& plan, SyncApproachLatch& latch,
                                    const std::optional<TargetEstimate>& target, const model::TargetOrbit& orbit,
                                    double t_s);

// The target's angular-momentum direction in inertial axes from an estimate (unit; nullopt when the
// target hardly turns, |omega| < 1e-6 rad/s: no axis to fly to).
std::optional<Vec3> angular_momentum_axis(const TargetEstimate& target, const Mat3& inertia_kgm2);

}  // namespace chaser::flight
