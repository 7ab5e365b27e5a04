// The escape's trigger and plan (flight/escape.hpp) against closed forms: a target spinning about a
// fixed principal axis, so that the axis point, the rates and the frame motion are known exactly.
#include "flight/escape.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/rotation.hpp"

namespace chaser::flight {
namespace {

constexpr double kSpinRadps = 2.5 * std::numbers::pi / 180.0;

// ENVISAT-like: the chaser 3.5 m beyond the fixture on the target's +x, facing it; the transfer
// started 12 m up the spin axis (target z); the tool stowed 2.8 m ahead of the chaser's CoM.
EscapeLawParams plan() {
  EscapeLawParams p;
  p.escape.command_s = 100.0;
  p.escape.retract_duration_s = 30.0;
  p.escape.withdraw_duration_s = 300.0;
  p.escape.desynchronise_duration_s = 200.0;
  p.escape.retreat_duration_s = 400.0;
  p.escape.safe_distance_m = 30.0;
  p.capture_point_target_m = Vec3(7.4, 0.0, 0.6);
  p.q_target_from_body = Quat(0.0, 0.0, 0.0, 1.0);  // body +x along target -x
  p.withdraw_point_target_m = Vec3(0.0, 0.0, 12.0);
  p.target_inertia_kgm2 = Vec3(17000.0, 125000.0, 129000.0).asDiagonal();
  p.hub_from_chaser_com_body_m = Vec3(0.05, 0.0, 0.02);
  p.tool_stowed_hub_m = Vec3(2.78, 0.89, -0.6);
  p.q_hub_from_tool_stowed = Quat::Identity();
  p.joint3_stowed_rad = 0.0;
  return p;
}

// A flat spin about target z, the target's frame turned 30 deg about x at t = 0.
TargetEstimate spinning_target() {
  TargetEstimate e;
  e.t_s = 0.0;
  e.q_inertial_from_target = Quat(Eigen::AngleAxisd(0.5236, Vec3::UnitX()));
  e.omega_target_radps = Vec3(0.0, 0.0, kSpinRadps);
  return e;
}

// Triggered at 100 s by command, the tool where the pre-grasp pose puts it.
EscapeState triggered(const EscapeLawParams& p, const TargetEstimate& target) {
  EscapeState state;
  arm::FrameMotion frame;
  frame.q_world_from_frame = target.q_inertial_from_target * quat_from_rotation_vector(target.omega_target_radps * 100.0);
  EXPECT_TRUE(escape_trigger(p, state, GraspStep::kApproach, 100.0,
                             {.target = target,
                              .target_frame = frame,
                              .tool_target_m = Vec3(4.05, 0.0, 0.6),
                              .q_target_from_tool = p.q_target_from_body,
                              .joint3_rad = 0.3}));
  return state;
}

arm::FrameMotion chaser_at(const EscapeLawParams& p, EscapeState& s, const TargetEstimate& target, double t_s) {
  // The hub's reference less its offset from the chaser's CoM: the chaser's CoM.
  const arm::TaskReference ref = escape_reference(p, s, target, Vec3::Zero(), Vec3::Zero(), t_s);
  arm::FrameMotion chaser = ref.hub;
  const Vec3 d = ref.hub.q_world_from_frame * p.hub_from_chaser_com_body_m;
  const Vec3& w = ref.hub.omega_radps;
  chaser.r_m -= d;
  chaser.v_mps -= w.cross(d);
  chaser.a_mps2 -= ref.hub.alpha_radps2.cross(d) + w.cross(w.cross(d));
  return chaser;
}

TEST(Escape, ACommandStartsItWhileTheJawsAreOpenAndIsRefusedOnceTheyClose) {
  const EscapeLawParams p = plan();
  const TargetEstimate target = spinning_target();
  arm::FrameMotion frame;
  const EscapeStart start{.target = target, .target_frame = frame, .tool_target_m = Vec3::Zero(),
                          .q_target_from_tool = Quat::Identity(), .joint3_rad = 0.0};
  EscapeState before;
  EXPECT_FALSE(escape_trigger(p, before, GraspStep::kApproach, 99.999, start));  // not yet commanded
  EXPECT_TRUE(escape_trigger(p, before, GraspStep::kApproach, 100.0, start));
  EXPECT_EQ(before.trigger, EscapeTrigger::kCommand);
  EXPECT_DOUBLE_EQ(before.start_s, 100.0);

  for (const GraspStep closed : {GraspStep::kClosing, GraspStep::kLocking, GraspStep::kCaptured}) {
    EscapeState held;
    EXPECT_FALSE(escape_trigger(p, held, closed, 100.5, start));
    EXPECT_FALSE(held.started());
    EXPECT_DOUBLE_EQ(held.refused_s, 100.5);
    EXPECT_FALSE(escape_trigger(p, held, GraspStep::kApproach, 101.0, start));  // refused for good
  }
  EscapeLawParams failed = p;  // a failed grasp
  failed.escape.command_s.reset();
  EscapeState abandoned;
  EXPECT_FALSE(escape_trigger(failed, abandoned, GraspStep::kApproach, 500.0, start));
  EXPECT_TRUE(escape_trigger(failed, abandoned, GraspStep::kAbandoned, 500.0, start));
  EXPECT_EQ(abandoned.trigger, EscapeTrigger::kFailedGrasp);
  failed.escape.on_failed_grasp = false;
  EscapeState kept;
  EXPECT_FALSE(escape_trigger(failed, kept, GraspStep::kAbandoned, 500.0, start));
}

// The brakes engage once the retraction has ended (triggered at 100 s, 30 s long) at the first step
// with every joint slower than brake_rate_degps, and stay engaged; not before the trigger, and never
// with brake_when_stowed off.
TEST(Escape, TheBrakesEngageOnceRetractedAndQuietOnlyWhenAsked) {
  const EscapeLawParams p = plan();
  model::ArmMeasurements quiet;
  quiet.joints = model::kArmJoints;
  model::ArmMeasurements moving = quiet;
  moving.q_dot_radps[4] = -0.021 * std::numbers::pi / 180.0;  // one joint over the 0.02 deg/s
  quiet.q_dot_radps[4] = -0.019 * std::numbers::pi / 180.0;
  EscapeState idle;
  EXPECT_FALSE(escape_brakes(p, idle, quiet, 500.0));  // not triggered
  EXPECT_FALSE(idle.braked());
  EscapeState s = triggered(p, spinning_target());
  EXPECT_FALSE(escape_brakes(p, s, quiet, 129.999));  // retracting
  EXPECT_FALSE(escape_brakes(p, s, moving, 130.0));
  EXPECT_FALSE(s.braked());
  EXPECT_TRUE(escape_brakes(p, s, quiet, 130.001));
  EXPECT_DOUBLE_EQ(s.brakes_s, 130.001);
  EXPECT_TRUE(escape_brakes(p, s, moving, 700.0));  // engaged for good
  EXPECT_DOUBLE_EQ(s.brakes_s, 130.001);            // the first time kept
  EscapeLawParams driven = p;
  driven.escape.brake_when_stowed = false;
  EscapeState d = triggered(driven, spinning_target());
  EXPECT_FALSE(escape_brakes(driven, d, quiet, 130.0));
  EXPECT_FALSE(escape_brakes(driven, d, quiet, 1e4));
  EXPECT_FALSE(d.braked());
}

// The axis: the target's angular momentum I w, on the transfer start's side, at its distance.
TEST(Escape, TheAxisPointIsTheAngularMomentumsAtTheTransferStartsDistance) {
  const EscapeLawParams p = plan();
  const TargetEstimate target = spinning_target();
  const EscapeState s = triggered(p, target);
  const Vec3 h = (target.q_inertial_from_target * Vec3::UnitZ()).normalized();
  EXPECT_LT((s.axis_inertial - h).norm(), 1e-12);
  EXPECT_NEAR(s.axis_distance_m, 12.0, 1e-12);
  EscapeLawParams below = p;  // the start point on the other side: the other sign
  below.withdraw_point_target_m = Vec3(0.0, 0.0, -12.0);
  EXPECT_LT((triggered(below, target).axis_inertial + h).norm(), 1e-12);
}

// While the tool retracts, the chaser holds the capture point turning with the target: the central
// differences against w x r and w x (w x r): over +-h a turn at w reads |v| (w h)^2 / 6 short,
// 2.6e-7 m/s at the capture point's 0.32 m/s, and the acceleration (w h)^2 / 12 of its 0.014 m/s^2.
TEST(Escape, TheRetractionHoldsTheCapturePointTurningWithTheTarget) {
  const EscapeLawParams p = plan();
  const TargetEstimate target = spinning_target();
  EscapeState s = triggered(p, target);
  for (const double t : {100.0, 110.0, 129.9}) {
    const arm::FrameMotion c = chaser_at(p, s, target, t);
    const Quat q_target = target.q_inertial_from_target * quat_from_rotation_vector(target.omega_target_radps * t);
    const Vec3 r = q_target * p.capture_point_target_m, w = q_target * target.omega_target_radps;
    EXPECT_LT((c.r_m - r).norm(), 1e-12) << t;
    EXPECT_LT((c.v_mps - w.cross(r)).norm(), 5e-7) << t;
    EXPECT_LT((c.a_mps2 - w.cross(w.cross(r))).norm(), 1e-8) << t;
    EXPECT_LT((c.omega_radps - w).norm(), 1e-9) << t;
  }
  // The tool from its start pose (at the trigger) to its stowed pose in the hub's frame (at the end).
  const arm::TaskReference at_start = escape_reference(p, s, target, Vec3::Zero(), Vec3::Zero(), 100.0);
  const Quat q_target = target.q_inertial_from_target * quat_from_rotation_vector(target.omega_target_radps * 100.0);
  EXPECT_LT((at_start.tool.r_m - q_target * Vec3(4.05, 0.0, 0.6)).norm(), 1e-12);
  EXPECT_NEAR(at_start.joint_rad, 0.3, 1e-12);
  const arm::TaskReference at_end = escape_reference(p, s, target, Vec3::Zero(), Vec3::Zero(), 130.0);
  EXPECT_LT((at_end.tool.r_m - (at_end.hub.r_m + at_end.hub.q_world_from_frame * p.tool_stowed_hub_m)).norm(), 1e-9);
  EXPECT_NEAR(at_end.joint_rad, 0.0, 1e-12);
}

// Each step starts where the last ended, at the same velocity and rate (to the differences' error);
// the withdrawal ends on the axis point with the boresight's angle to the target's centre as at the
// capture point; the desynchronisation stops the roll there; the retreat ends at the safe distance.
TEST(Escape, ThePlanIsContinuousAndEndsAtRestAtTheSafeDistanceOnTheAxis) {
  const EscapeLawParams p = plan();
  const TargetEstimate target = spinning_target();
  EscapeState s = triggered(p, target);
  for (const double boundary : {130.0, 430.0, 630.0, 1030.0}) {
    const arm::FrameMotion before = chaser_at(p, s, target, boundary - 1e-4), after = chaser_at(p, s, target, boundary + 1e-4);
    EXPECT_LT((after.r_m - before.r_m).norm(), 1e-4) << boundary;  // |v| < 0.5 m/s over 2e-4 s
    EXPECT_LT((after.v_mps - before.v_mps).norm(), 1e-5) << boundary;
    EXPECT_LT((after.omega_radps - before.omega_radps).norm(), 1e-5) << boundary;
  }
  const Vec3& h = s.axis_inertial;
  const arm::FrameMotion on_axis = chaser_at(p, s, target, 430.0);
  EXPECT_LT((on_axis.r_m - 12.0 * h).norm(), 1e-9);
  EXPECT_LT(on_axis.v_mps.norm(), 1e-7);  // the quintic's r''' h^2 / 6 at its end
  const Vec3 boresight = on_axis.q_world_from_frame * Vec3::UnitX();
  const double angle_at_capture = std::acos((p.q_target_from_body * Vec3::UnitX()).dot(-p.capture_point_target_m.normalized()));
  EXPECT_NEAR(std::acos(boresight.dot(-h)), angle_at_capture, 1e-9);
  EXPECT_LT(on_axis.omega_radps.cross(h).norm(), 1e-9);  // a roll about the axis ...
  EXPECT_NEAR(on_axis.omega_radps.dot(h), kSpinRadps, 1e-7);  // ... at the target's spin
  const arm::FrameMotion at_rest = chaser_at(p, s, target, 630.0);
  EXPECT_LT((at_rest.r_m - 12.0 * h).norm(), 1e-9);
  EXPECT_LT(at_rest.omega_radps.norm(), 1e-12);
  EXPECT_NEAR(std::acos((at_rest.q_world_from_frame * Vec3::UnitX()).dot(-h)), angle_at_capture, 1e-9);
  const arm::FrameMotion held = chaser_at(p, s, target, 1100.0);
  EXPECT_LT((held.r_m - 30.0 * h).norm(), 1e-9);
  EXPECT_LT(held.v_mps.norm(), 1e-12);
  EXPECT_LT(held.omega_radps.norm(), 1e-12);
  EXPECT_EQ(escape_step(p, s, 129.0), EscapeStep::kRetract);
  EXPECT_EQ(escape_step(p, s, 431.0), EscapeStep::kDesynchronise);
  EXPECT_EQ(escape_step(p, s, 1030.0), EscapeStep::kHold);
}

// The withdrawal's curve bent outwards keeps the stowed tool (2.8 m ahead of the chaser) outside
// the target's bus throughout; the straight line takes it through the bus's face.
// The stowed tool's least distance outside the 10 x 4 x 4 m bus (x <= 3.9 m, |y|, |z| <= 2 m) over
// the withdrawal [m] (negative: inside).
double least_tool_outside_bus_m(const EscapeLawParams& p) {
  const TargetEstimate target = spinning_target();
  EscapeState s = triggered(p, target);
  double least_m = 1e9;
  for (double t = 130.0; t <= 430.0; t += 1.0) {
    const arm::TaskReference ref = escape_reference(p, s, target, Vec3::Zero(), Vec3::Zero(), t);
    const Quat q_target = target.q_inertial_from_target * quat_from_rotation_vector(target.omega_target_radps * t);
    const Vec3 tool = q_target.conjugate() * ref.tool.r_m;
    least_m = std::min(least_m, std::max({tool.x() - 3.9, std::abs(tool.y()) - 2.0, std::abs(tool.z()) - 2.0}));
  }
  return least_m;
}

TEST(Escape, TheWithdrawalBacksAwayBeforeTurningUpTheAxis) {
  EscapeLawParams p = plan();
  EXPECT_GT(least_tool_outside_bus_m(p), 0.5);  // measured 0.67 m with the 4 m backoff
  p.escape.withdraw_backoff_m = 0.0;            // the straight line: through the bus's face
  EXPECT_LT(least_tool_outside_bus_m(p), 0.0);
}

// The chaser's reference in LVLH: its position differenced in time is the velocity given (the frame
// turning at n about z), to the difference's error.
TEST(Escape, TheGuidanceReferenceIsTheSameMotionSeenFromLvlh) {
  const EscapeLawParams p = plan();
  const TargetEstimate target = spinning_target();
  EscapeState s = triggered(p, target);
  const double n = 1.05e-3;
  const auto lvlh_at = [n](double t) {
    model::LvlhFrame f;
    f.q_inertial_from_lvlh = Quat(Eigen::AngleAxisd(n * t, Vec3::UnitZ()));
    f.omega_lvlh_radps = Vec3(0.0, 0.0, n);
    return f;
  };
  for (const double t : {200.0, 500.0, 800.0}) {
    const double dt = 1e-3;
    const GuidanceRef now = escape_guidance(p, s, target, Vec3::Zero(), Vec3::Zero(), lvlh_at(t), t);
    const GuidanceRef before = escape_guidance(p, s, target, Vec3::Zero(), Vec3::Zero(), lvlh_at(t - dt), t - dt);
    const GuidanceRef after = escape_guidance(p, s, target, Vec3::Zero(), Vec3::Zero(), lvlh_at(t + dt), t + dt);
    EXPECT_LT((now.v_lvlh_mps - (after.r_lvlh_m - before.r_lvlh_m) / (2.0 * dt)).norm(), 1e-6) << t;
    EXPECT_LT((now.a_lvlh_mps2 - (after.v_lvlh_mps - before.v_lvlh_mps) / (2.0 * dt)).norm(), 1e-5) << t;
    const Vec3 omega_body = rotation_vector_from_quat(before.q_inertial_from_body.conjugate() * after.q_inertial_from_body) / (2.0 * dt);
    EXPECT_LT((now.omega_body_radps - omega_body).norm(), 1e-8) << t;
  }
}

}  // namespace
}  // namespace chaser::flight
