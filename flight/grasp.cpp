#include "flight/grasp.hpp"

#include <cmath>
#include <numbers>

#include "core/rotation.hpp"

namespace chaser::flight {

GraspParams make_grasp(const model::CaptureParams& c) {
  GraspParams p;
  p.approach_start_s = c.approach_start_s();
  p.approach_end_s = p.approach_start_s + c.approach_duration_s;
  p.timeout_s = c.grasp_timeout_s;
  p.closure_samples = c.closure_samples;
  p.lock_dwell_s = c.lock_dwell_s;
  if (c.berthing) {
    p.berthing = true;
    p.retraction_m = c.berthing->retraction_m;
    p.retraction_duration_s = c.berthing->retraction_duration_s;
  }
  return p;
}

bool inside_grappling_envelope(const model::RelativePoseMeasurement& sample) {
  if (!sample.valid) return false;
  // The camera reports the fixture in the tool's axes: the tool from the fixture, in the fixture's
  // axes, is -R_fixture_from_camera r, and the tool's attitude error the inverse rotation.
  const Quat q_fixture_from_camera = sample.q_camera_from_fixture.conjugate();
  const Vec3 tool_from_fixture_m = -(q_fixture_from_camera * sample.r_camera_m);
  const Vec3 attitude_rad = rotation_vector_from_quat(q_fixture_from_camera);
  const double attitude_limit_rad = model::kGrapplingEnvelopeDeg * std::numbers::pi / 180.0;
  for (int i = 0; i < 3; ++i)
    if (!(std::abs(tool_from_fixture_m(i)) < model::kGrapplingEnvelopeM[i]) ||
        !(std::abs(attitude_rad(i)) < attitude_limit_rad))
      return false;
  return true;
}

void grasp_camera_sample(const GraspParams& params, GraspState& state, const model::RelativePoseMeasurement& sample,
                         double t_s) {
  if (params.berthing || state.step != GraspStep::kApproach || t_s < params.approach_end_s) return;
  state.inside_samples = inside_grappling_envelope(sample) ? state.inside_samples + 1 : 0;
  if (state.inside_samples >= params.closure_samples) {
    state.step = GraspStep::kClosing;
    state.closure_s = t_s;
  }
}

namespace {

// The berthing's steps: the latches close by themselves on a tip at the socket; the flight
// software then commands the retraction and waits for the pins.
void berth_joint_step(const GraspParams& params, GraspState& state, const model::ArmMeasurements& arm, double t_s,
                      model::ArmCommand& command) {
  switch (state.step) {
    case GraspStep::kReach:
      if (t_s >= params.approach_start_s) state.step = GraspStep::kApproach;
      break;
    case GraspStep::kApproach:
      if (arm.probe_latched) {
        state.step = GraspStep::kLocking;
        state.closure_s = state.lock_s = t_s;
      } else if (t_s >= params.approach_end_s + params.timeout_s) {
        state.step = GraspStep::kAbandoned;
      }
      break;
    case GraspStep::kLocking:
      if (arm.probe_hard_docked) {
        state.step = GraspStep::kCaptured;
        state.captured_s = t_s;
      }
      break;
    case GraspStep::kClosing:
    case GraspStep::kCaptured:
    case GraspStep::kAbandoned:
      break;
  }
  command.retract_probe = state.step == GraspStep::kLocking || state.step == GraspStep::kCaptured;
}

}  // namespace

void grasp_joint_step(const GraspParams& params, GraspState& state, const model::ArmMeasurements& arm, double t_s,
                      model::ArmCommand& command) {
  if (params.berthing) {
    berth_joint_step(params, state, arm, t_s, command);
    return;
  }
  switch (state.step) {
    case GraspStep::kReach:
      if (t_s >= params.approach_start_s) state.step = GraspStep::kApproach;
      break;
    case GraspStep::kApproach:
      if (t_s >= params.approach_end_s + params.timeout_s) state.step = GraspStep::kAbandoned;
      break;
    case GraspStep::kClosing:
      if (!arm.gripper_closed) {
        state.holding_since_s = -1.0;
      } else if (state.holding_since_s < 0.0) {
        state.holding_since_s = t_s;
      } else if (t_s - state.holding_since_s >= params.lock_dwell_s) {
        state.step = GraspStep::kLocking;
        state.lock_s = t_s;
      }
      break;
    case GraspStep::kLocking:
      if (arm.gripper_locked) {
        state.step = GraspStep::kCaptured;
        state.captured_s = t_s;
      }
      break;
    case GraspStep::kCaptured:
    case GraspStep::kAbandoned:
      break;
  }
  command.close_gripper = state.step == GraspStep::kClosing || state.step == GraspStep::kLocking ||
                          state.step == GraspStep::kCaptured;
  command.lock_gripper = state.step == GraspStep::kLocking || state.step == GraspStep::kCaptured;
}

const char* to_string(GraspStep step) {
  switch (step) {
    case GraspStep::kReach: return "reach";
    case GraspStep::kApproach: return "approach";
    case GraspStep::kClosing: return "closing";
    case GraspStep::kLocking: return "locking";
    case GraspStep::kCaptured: return "captured";
    case GraspStep::kAbandoned: return "abandoned";
  }
  return "?";
}

}  // namespace chaser::flight
