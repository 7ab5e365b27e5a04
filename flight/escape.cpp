#include "flight/escape.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/rotation.hpp"
#include "flight/carried_target.hpp"
#include "flight/joints_quiet.hpp"
#include "flight/pose_path.hpp"
#include "flight/sync_approach.hpp"

namespace chaser::flight {

namespace {

constexpr double kDifferenceStep_s = 0.05;  // h of the central differences (flight/sync_approach.hpp's)

struct Times {
  double retract_end_s, withdraw_end_s, desynchronise_end_s, retreat_end_s;
};

Times times(const EscapeLawParams& p, const EscapeState& s) {
  const model::EscapeParams& e = p.escape;
  const double withdraw = s.start_s + e.retract_duration_s;
  const double desynchronise = withdraw + e.withdraw_duration_s;
  const double retreat = desynchronise + e.desynchronise_duration_s;
  return {withdraw, desynchronise, retreat, retreat + e.retreat_duration_s};
}

// u(t) = int_0^(t - t_d) (1 - s) dt over the desynchronisation of length D: the roll's angle is
// w_roll u. With s the quintic, int_0^tau s = tau^4 (5/2 - 3 tau + tau^2) (its integral),
// so u = D (tau - that); u' = 1 - s runs from 1 to 0 with zero slope at both ends.
double spun_time_s(double elapsed_s, double duration_s) {
  const double tau = std::clamp(elapsed_s / duration_s, 0.0, 1.0);
  return duration_s * (tau - tau * tau * tau * tau * (2.5 - 3.0 * tau + tau * tau));
}

struct Pose {
  Vec3 r_m = Vec3::Zero();
  Quat q = Quat::Identity();
};

// The chaser's CoM and attitude in the law's world at t_s (the header's plan).
class EscapePoses {
 public:
  EscapePoses(const EscapeLawParams& params, const EscapeState& state, const TargetEstimate& target,
              const Vec3& frame_offset_m, const Vec3& frame_rotation_rad)
      : p_(params), s_(state), times_(times(params, state)), target_(target), offset_(frame_offset_m),
        rotation_(frame_rotation_rad) {}

  Pose at(double t_s) const {
    if (t_s < times_.withdraw_end_s) return withdrawing(t_s);
    const arm::FrameMotion target = corrected_target_frame(target_, offset_, rotation_, t_s);
    const double u = spun_time_s(t_s - times_.withdraw_end_s, p_.escape.desynchronise_duration_s);
    const Quat q_body =
        (quat_from_rotation_vector(s_.roll_rate_desync_radps * u * s_.axis_inertial) * s_.q_world_from_body_desync)
            .normalized();
    const double s = quintic(t_s - times_.desynchronise_end_s, p_.escape.retreat_duration_s).s;
    const double distance_m = s_.axis_distance_m + s * (p_.escape.safe_distance_m - s_.axis_distance_m);
    return {target.r_m + distance_m * s_.axis_inertial, q_body};
  }

  // The retraction's hold and the withdrawal (also past its end, where it rests on the axis point).
  Pose withdrawing(double t_s) const {
    const arm::FrameMotion target = corrected_target_frame(target_, offset_, rotation_, t_s);
    const Quat& q_target = target.q_world_from_frame;
    const Vec3& p_c = p_.capture_point_target_m;
    const double s = t_s < times_.retract_end_s ? 0.0 : quintic(t_s - times_.retract_end_s, p_.escape.withdraw_duration_s).s;
    const Vec3 control = p_c + p_.escape.withdraw_backoff_m * p_c.normalized();
    const Vec3 from_target_m =
        q_target * ((1.0 - s) * (1.0 - s) * p_c + 2.0 * s * (1.0 - s) * control) + s * s * s_.axis_distance_m * s_.axis_inertial;
    // The boresight's angle to the target's centre kept: the least rotation (target axes) from the
    // capture point's line of sight to this one.
    const Quat sighted = rotation_towards(-p_c.normalized(), -(q_target.conjugate() * from_target_m).normalized(), 1.0);
    return {target.r_m + from_target_m, (q_target * sighted * p_.q_target_from_body).normalized()};
  }

 private:
  const EscapeLawParams& p_;
  const EscapeState& s_;
  Times times_;
  const TargetEstimate& target_;
  Vec3 offset_, rotation_;
};

// Velocity, acceleration, rate and its derivative by central differences, world axes.
arm::FrameMotion differentiate(const EscapePoses& poses, double t_s) {
  const double h = kDifferenceStep_s;
  const Pose before = poses.at(t_s - h), now = poses.at(t_s), after = poses.at(t_s + h);
  arm::FrameMotion f;
  f.r_m = now.r_m;
  f.v_mps = (after.r_m - before.r_m) / (2.0 * h);
  f.a_mps2 = (after.r_m - 2.0 * now.r_m + before.r_m) / (h * h);
  f.q_world_from_frame = now.q;
  f.omega_radps = rotation_vector_from_quat(after.q * before.q.conjugate()) / (2.0 * h);
  f.alpha_radps2 =
      (rotation_vector_from_quat(after.q * now.q.conjugate()) - rotation_vector_from_quat(now.q * before.q.conjugate())) /
      (h * h);
  return f;
}

// The desynchronisation's start: the withdrawal's attitude at its end and its roll rate about the
// axis there (the rate is along the axis: the boresight stays on it).
void fix_desynchronisation(const EscapeLawParams& params, EscapeState& state, const TargetEstimate& target,
                           const Vec3& frame_offset_m, const Vec3& frame_rotation_rad) {
  if (state.desynchronise_fixed) return;
  const EscapePoses poses(params, state, target, frame_offset_m, frame_rotation_rad);
  const double t_d = times(params, state).withdraw_end_s, h = kDifferenceStep_s;
  state.q_world_from_body_desync = poses.withdrawing(t_d).q;
  const Vec3 omega_world = rotation_vector_from_quat(poses.withdrawing(t_d + h).q * poses.withdrawing(t_d - h).q.conjugate()) / (2.0 * h);
  state.roll_rate_desync_radps = state.axis_inertial.dot(omega_world);
  state.desynchronise_fixed = true;
}

arm::FrameMotion chaser_motion(const EscapeLawParams& params, EscapeState& state, const TargetEstimate& target,
                               const Vec3& frame_offset_m, const Vec3& frame_rotation_rad, double t_s) {
  if (t_s + kDifferenceStep_s >= times(params, state).withdraw_end_s)
    fix_desynchronisation(params, state, target, frame_offset_m, frame_rotation_rad);
  return differentiate(EscapePoses(params, state, target, frame_offset_m, frame_rotation_rad), t_s);
}

}  // namespace

EscapeStep escape_step(const EscapeLawParams& params, const EscapeState& state, double t_s) {
  if (!state.started()) return EscapeStep::kNone;
  const Times t = times(params, state);
  if (t_s < t.retract_end_s) return EscapeStep::kRetract;
  if (t_s < t.withdraw_end_s) return EscapeStep::kWithdraw;
  if (t_s < t.desynchronise_end_s) return EscapeStep::kDesynchronise;
  if (t_s < t.retreat_end_s) return EscapeStep::kRetreat;
  return EscapeStep::kHold;
}

double escape_desynchronise_s(const EscapeLawParams& params, const EscapeState& state) {
  return state.started() ? times(params, state).withdraw_end_s : std::numeric_limits<double>::quiet_NaN();
}

double escape_hold_s(const EscapeLawParams& params, const EscapeState& state) {
  return state.started() ? times(params, state).retreat_end_s : std::numeric_limits<double>::quiet_NaN();
}

bool escape_trigger(const EscapeLawParams& params, EscapeState& state, GraspStep grasp, double t_s,
                    const EscapeStart& start) {
  if (state.started()) return false;
  const model::EscapeParams& e = params.escape;
  EscapeTrigger trigger = EscapeTrigger::kNone;
  if (e.on_failed_grasp && grasp == GraspStep::kAbandoned) {
    trigger = EscapeTrigger::kFailedGrasp;
  } else if (e.command_s && t_s >= *e.command_s && state.refused_s < 0.0) {
    // The jaws open: before they close, or the grasp abandoned. Closed, the target is held.
    if (grasp == GraspStep::kReach || grasp == GraspStep::kApproach || grasp == GraspStep::kAbandoned)
      trigger = EscapeTrigger::kCommand;
    else
      state.refused_s = t_s;
  }
  if (trigger == EscapeTrigger::kNone) return false;
  state.trigger = trigger;
  state.start_s = t_s;
  // The axis point: the transfer's start's distance, on its side of the target; without a spin to
  // give an axis, that start point itself, fixed in inertial space.
  const Vec3 start_world = start.target_frame.q_world_from_frame *
                           state.withdraw_point_target_m.value_or(params.withdraw_point_target_m);
  state.axis_distance_m = start_world.norm();
  const std::optional<Vec3> axis = angular_momentum_axis(start.target, params.target_inertia_kgm2);
  state.axis_inertial = !axis ? start_world.normalized() : axis->dot(start_world) < 0.0 ? Vec3(-*axis) : *axis;
  state.tool_start_target_m = start.tool_target_m;
  state.q_target_from_tool_start = start.q_target_from_tool;
  state.joint3_start_rad = start.joint3_rad;
  return true;
}

bool escape_brakes(const EscapeLawParams& params, EscapeState& state, const model::ArmMeasurements& joints,
                   double t_s) {
  if (state.braked()) return true;
  constexpr double kTimeTolS = 1e-9;  // the joint steps' times are sums of the period
  if (!state.started() || !params.escape.brake_when_stowed ||
      t_s + kTimeTolS < state.start_s + params.escape.retract_duration_s)
    return false;
  if (!joints_slower_than(joints, params.escape.brake_rate_degps)) return false;
  state.brakes_s = t_s;
  return true;
}

arm::TaskReference escape_reference(const EscapeLawParams& params, EscapeState& state, const TargetEstimate& target,
                                    const Vec3& frame_offset_m, const Vec3& frame_rotation_rad, double t_s) {
  const arm::FrameMotion chaser = chaser_motion(params, state, target, frame_offset_m, frame_rotation_rad, t_s);
  arm::FrameMotion hub_in_chaser;
  hub_in_chaser.r_m = params.hub_from_chaser_com_body_m;
  arm::TaskReference reference;
  reference.hub = arm::compose(chaser, hub_in_chaser);
  const double elapsed_s = t_s - state.start_s;
  const double retract_s = params.escape.retract_duration_s;
  if (elapsed_s < retract_s) {  // the tool to its stowed pose, the hub at the capture point (target axes)
    const Vec3 stowed_m = params.capture_point_target_m +
                          params.q_target_from_body * (params.hub_from_chaser_com_body_m + params.tool_stowed_hub_m);
    const Quat q_stowed = (params.q_target_from_body * params.q_hub_from_tool_stowed).normalized();
    reference.tool = arm::compose(corrected_target_frame(target, frame_offset_m, frame_rotation_rad, t_s),
                                  pose_path(state.tool_start_target_m, state.q_target_from_tool_start, stowed_m, q_stowed,
                                            elapsed_s, retract_s));
    const Blend b = quintic(elapsed_s, retract_s);
    const double travel = params.joint3_stowed_rad - state.joint3_start_rad;
    reference.joint_rad = state.joint3_start_rad + b.s * travel;
    reference.joint_rate_radps = b.rate * travel;
    reference.joint_acceleration_radps2 = b.acceleration * travel;
    return reference;
  }
  arm::FrameMotion tool_in_hub;
  tool_in_hub.r_m = params.tool_stowed_hub_m;
  tool_in_hub.q_world_from_frame = params.q_hub_from_tool_stowed;
  reference.tool = arm::compose(reference.hub, tool_in_hub);
  reference.joint_rad = params.joint3_stowed_rad;
  return reference;
}

GuidanceRef escape_guidance(const EscapeLawParams& params, EscapeState& state, const TargetEstimate& target,
                            const Vec3& frame_offset_m, const Vec3& frame_rotation_rad, const model::LvlhFrame& lvlh,
                            double t_s) {
  const arm::FrameMotion chaser = chaser_motion(params, state, target, frame_offset_m, frame_rotation_rad, t_s);
  // Inertial to LVLH (the frame turning at w_L about the target's orbit point, the world's origin):
  // r_L = R r, v_L = R v - w_L x r_L, a_L = R a - 2 w_L x v_L - w_L x (w_L x r_L) - w_L' x r_L.
  const Quat q_lvlh_from_inertial = lvlh.q_inertial_from_lvlh.conjugate();
  const Vec3& w = lvlh.omega_lvlh_radps;
  GuidanceRef ref;
  ref.r_lvlh_m = q_lvlh_from_inertial * chaser.r_m;
  ref.v_lvlh_mps = q_lvlh_from_inertial * chaser.v_mps - w.cross(ref.r_lvlh_m);
  ref.a_lvlh_mps2 = q_lvlh_from_inertial * chaser.a_mps2 - 2.0 * w.cross(ref.v_lvlh_mps) -
                    w.cross(w.cross(ref.r_lvlh_m)) - lvlh.omega_dot_lvlh_radps2.cross(ref.r_lvlh_m);
  ref.q_inertial_from_body = chaser.q_world_from_frame;
  ref.omega_body_radps = chaser.q_world_from_frame.conjugate() * chaser.omega_radps;
  return ref;
}

const char* to_string(EscapeTrigger trigger) {
  switch (trigger) {
    case EscapeTrigger::kNone: return "none";
    case EscapeTrigger::kCommand: return "command";
    case EscapeTrigger::kFailedGrasp: return "failed grasp";
  }
  return "?";
}

const char* to_string(EscapeStep step) {
  switch (step) {
    case EscapeStep::kNone: return "none";
    case EscapeStep::kRetract: return "retract";
    case EscapeStep::kWithdraw: return "withdraw";
    case EscapeStep::kDesynchronise: return "desynchronise";
    case EscapeStep::kRetreat: return "retreat";
    case EscapeStep::kHold: return "hold";
  }
  return "?";
}

}  // namespace chaser::flight
