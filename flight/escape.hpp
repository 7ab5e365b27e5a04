#pragma once
// The escape on board (COMRADE 2018, sec. 4: "a trajectory planning part as well as a combined
// controller as the feed-back part"; model/capture.hpp's EscapeParams): a trajectory for the
// chaser and the arm, planned from the relative pose and the joints when the escape is triggered,
// tracked by the capture's combined controller (flight/reach.hpp) in place of the reach's path.
//
// The plan, its steps in turn (times from the trigger):
//   retract        the tool from where it is to its stowed pose in the hub's frame (a straight line
//                  and one turn, flight/pose_path.hpp: the reach's path flown back when the escape
//                  starts at the pre-grasp pose), the chaser holding the capture point;
//   withdraw       the chaser from the capture point to the target's angular-momentum axis at the
//                  distance the synchronised transfer started from (the axis point the approach
//                  synchronised on), the axis fixed at the trigger from the target's estimate:
//                    r = R(t) [(1 - s)^2 p_c + 2 s (1 - s) c] + s^2 d h
//                  (world axes from the target's centre, R the target's attitude, s the quintic's
//                  progress): a quadratic Bezier curve whose first two points turn with the target
//                  and whose last is fixed in inertial space. Its control point c is
//                  withdraw_backoff_m beyond p_c on its line of sight, so the chaser backs away
//                  first and the stowed arm's tool (2.8 m ahead of the chaser's CoM in COMRADE's
//                  layout) clears the target's face, which the transfer's straight line flown back
//                  does not. The attitude turns with the target and by the least rotation that keeps
//                  the boresight's angle to the target's centre; on the axis the boresight lies
//                  along it, so the chaser's rate there is a roll about it;
//   desynchronise  on the axis point (it does not move with the spin, a tumble's included), the roll
//                  brought to rest: q = exp(h w_roll u) q_d, u = int (1 - s) dt;
//   retreat        along the axis out to safe_distance_m, the attitude fixed, then a hold there.
// With brake_when_stowed (the default) the arm's brakes engage once the retraction has ended (the
// arm as good as stowed) at the first joint step at which every joint turns slower than
// brake_rate_degps (the brakes stop the joints within a few steps: their catch loads them by the
// joints' inertia times that rate over ~2 ms), and the joint loop stops driving it: the chaser
// and its braked arm are then one rigid body, the free chaser the platform's own loops were designed on, and they fly the
// rest of the plan (escape_guidance's reference) at the control period, the combined law idle.
// The stowed arm and the fixed relation of tool and hub from the retraction on keep the arm clear
// of the hub (the stowed pose is the launch one) and the camera looking where the boresight looks.
//
// The poses are closed forms of time; velocities, accelerations and rates come from central
// differences over +-h (flight/sync_approach.hpp's method and error budget), in the law's world
// (inertial axes from the target's estimated CoM, flight/carried_target.hpp).
#include <optional>

#include "core/types.hpp"
#include "flight/arm/servicer_arm.hpp"
#include "flight/arm/task_space.hpp"
#include "flight/grasp.hpp"
#include "flight/guidance.hpp"
#include "flight/target_estimator.hpp"
#include "model/capture.hpp"
#include "model/target_orbit.hpp"

namespace chaser::flight {

enum class EscapeTrigger { kNone, kCommand, kFailedGrasp };
enum class EscapeStep { kNone, kRetract, kWithdraw, kDesynchronise, kRetreat, kHold };

struct EscapeLawParams {
  model::EscapeParams escape;
  Vec3 capture_point_target_m = Vec3::Zero();  // [m] the chaser's CoM held there, target axes
  Quat q_target_from_body = Quat::Identity();  // its attitude there
  // [m] the synchronised transfer's start when the flight software has not fixed one (target axes):
  // its distance is the axis point's, its side of the target the axis's sign
  Vec3 withdraw_point_target_m = Vec3::Zero();
  Mat3 target_inertia_kgm2 = Mat3::Identity();     // the angular momentum's (the estimator's model)
  Vec3 hub_from_chaser_com_body_m = Vec3::Zero();  // [m] the hub's CoM from the chaser's (arm stowed)
  Vec3 tool_stowed_hub_m = Vec3::Zero();           // [m] the tool point stowed, hub frame
  Quat q_hub_from_tool_stowed = Quat::Identity();
  double joint3_stowed_rad = 0.0;                  // [rad] the redundancy joint stowed
};

struct EscapeState {
  EscapeTrigger trigger = EscapeTrigger::kNone;
  double start_s = -1.0;    // [s] triggered (-1: not yet)
  double refused_s = -1.0;  // [s] commanded with the jaws closed: not flown (-1: never)
  double brakes_s = -1.0;   // [s] the brakes engaged, retracted and quiet (-1: not)
  // Fixed each period by the flight software until the trigger: the transfer's start point as the
  // synchronised approach fixed it (flight/sync_approach.hpp's latch), if it did.
  std::optional<Vec3> withdraw_point_target_m;
  // Fixed at the trigger: the axis (unit, inertial axes) and the distance the withdrawal ends at,
  // the tool's pose (target axes) and the redundancy joint's angle.
  Vec3 axis_inertial = Vec3::UnitZ();
  double axis_distance_m = 0.0;
  Vec3 tool_start_target_m = Vec3::Zero();
  Quat q_target_from_tool_start = Quat::Identity();
  double joint3_start_rad = 0.0;
  // Fixed when the desynchronisation begins: the chaser's attitude and its roll rate about the axis.
  bool desynchronise_fixed = false;
  Quat q_world_from_body_desync = Quat::Identity();
  double roll_rate_desync_radps = 0.0;
  bool started() const { return start_s >= 0.0; }
  bool braked() const { return brakes_s >= 0.0; }
};

// The step at t_s (kNone before the trigger).
EscapeStep escape_step(const EscapeLawParams& params, const EscapeState& state, double t_s);
// When the desynchronisation begins and the hold begins [s] (NaN before the trigger).
double escape_desynchronise_s(const EscapeLawParams& params, const EscapeState& state);
double escape_hold_s(const EscapeLawParams& params, const EscapeState& state);

// What the escape's plan is fixed from at its trigger: the target's estimate and the frame the joint
// loop carries (world axes), the tool's pose in the target's axes and the redundancy joint's angle.
struct EscapeStart {
  const TargetEstimate& target;
  const arm::FrameMotion& target_frame;
  Vec3 tool_target_m;
  Quat q_target_from_tool;
  double joint3_rad;
};

// At a joint step at t_s, before the escape: whether it starts now (commanded, and the jaws open; or
// the grasp abandoned). A command with the jaws closed is refused (once, recorded). On a start, the
// plan's axis and distance, the tool's pose and the redundancy joint's angle are fixed.
bool escape_trigger(const EscapeLawParams& params, EscapeState& state, GraspStep grasp, double t_s,
                    const EscapeStart& start);

// At a joint step at t_s once triggered, the joints' rates in hand: whether the arm is braked from
// now on (brake_when_stowed, the retraction ended, every joint slower than brake_rate_degps;
// recorded in state.brakes_s the first time).
bool escape_brakes(const EscapeLawParams& params, EscapeState& state, const model::ArmMeasurements& joints,
                   double t_s);

// The combined law's references at t_s once triggered: hub, tool and redundancy joint, in the law's
// world, from the target's estimate as the joint loop carries it (offset and rotation: the camera's
// correction). Fixes the desynchronisation's attitude and roll the first time they are needed.
arm::TaskReference escape_reference(const EscapeLawParams& params, EscapeState& state, const TargetEstimate& target,
                                    const Vec3& frame_offset_m, const Vec3& frame_rotation_rad, double t_s);

// The chaser's reference in LVLH (its CoM, as the guidance gives it) at t_s once triggered, for the
// flight software's period (the mission monitor and telemetry judge against it).
GuidanceRef escape_guidance(const EscapeLawParams& params, EscapeState& state, const TargetEstimate& target,
                            const Vec3& frame_offset_m, const Vec3& frame_rotation_rad, const model::LvlhFrame& lvlh,
                            double t_s);

const char* to_string(EscapeTrigger trigger);
const char* to_string(EscapeStep step);

}  // namespace chaser::flight
