#include "flight/reach.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>
#include <fmt/format.h>

#include "control/composite_design.hpp"
#include "control/six_axis_design.hpp"
#include "core/rotation.hpp"
#include "flight/arm/computed_torque.hpp"
#include "flight/carried_target.hpp"
#include "flight/pose_path.hpp"
#include "model/hub_mass_properties.hpp"

namespace chaser::flight {

namespace {

// The flight software's model of the servicer: the hub (the chaser less its stowed arm) and the arm.
model::MultibodySceneParams servicer_scene(const model::Scenario& s) {
  const model::BodyMassProperties hub = model::hub_mass_properties(s.chaser, *s.chaser.arm);
  model::MultibodySceneParams scene;
  scene.hub_mass_kg = hub.mass_kg;
  scene.hub_inertia_kgm2 = hub.inertia_kgm2;
  scene.hub_com_body_m = hub.com_body_m;
  scene.arm = *s.chaser.arm;
  return scene;
}

// The H-infinity law's specs: the hub's authority and loop delay from the platform's own design
// (control.hinf: what the thrusters give along each axis, half a period's hold, the valves), the
// tool's and the joint's from the arm, delays of one joint step.
ArmHinfSpec hinf_spec(const model::Scenario& s, const model::CaptureParams& c) {
  const std::array<control::AxisDesignSpec, 6> platform = control::six_axis_specs(s);
  const auto group = [](double authority, double delay_s, double bandwidth_radps, double error_scale) {
    return ArmHinfGroupSpec{.authority = authority, .delay_s = delay_s, .bandwidth_radps = bandwidth_radps,
                            .peak_sensitivity = 2.0, .low_frequency_gain = 1e-3, .error_scale = error_scale,
                            .input_disturbance = 0.01};
  };
  const double joint_period_s = 1.0 / c.joint_rate_hz;
  const double hub_force = std::min({platform[0].authority, platform[1].authority, platform[2].authority});
  const double hub_torque = std::min({platform[3].authority, platform[4].authority, platform[5].authority});
  ArmHinfSpec spec;
  spec.hub_position = group(hub_force, platform[0].delay_s, c.hub_bandwidth_radps, 0.05);
  spec.hub_attitude = group(hub_torque, platform[3].delay_s, c.hub_bandwidth_radps, 0.035);
  // The arm's: 1 m/s^2 and 2 rad/s^2 at the tool, 2 rad/s^2 at the joint, a fraction of what the
  // 176 N m drives give the 80 kg arm; errors scaled to COMRADE Table 2's envelope (10 mm, 2.74 deg).
  spec.tool_position = group(1.0, joint_period_s, c.tool_bandwidth_radps, 0.01);
  spec.tool_attitude = group(2.0, joint_period_s, c.tool_bandwidth_radps, 0.048);
  spec.joint = group(2.0, joint_period_s, c.joint_bandwidth_radps, 0.05);
  spec.period_s = joint_period_s;
  return spec;
}

// The estimates carried from the last period to t_s: the hub (its CoM) in the law's world, its
// velocity, attitude and rate; the target's frame.
struct Carried {
  Vec3 r_hub_m = Vec3::Zero(), v_hub_mps = Vec3::Zero();
  Quat q_inertial_from_body = Quat::Identity();
  Vec3 omega_body_radps = Vec3::Zero();
  arm::FrameMotion target;
};

Carried carry(const ReachParams& p, const ReachState& s, double t_s) {
  const double dt = t_s - s.nav_t_s;
  Carried c;
  c.q_inertial_from_body = (s.nav.q_inertial_from_body * quat_from_rotation_vector(s.nav.omega_body_radps * dt)).normalized();
  c.omega_body_radps = s.nav.omega_body_radps;
  // The chaser's CoM point (arm stowed) in inertial axes from the target: r_I = R_IL r, v_I = R_IL (v + w_L x r).
  const Mat3 inertial_from_lvlh = s.lvlh.q_inertial_from_lvlh.toRotationMatrix();
  const Vec3 r_lvlh = s.nav.r_lvlh_m + s.nav.v_lvlh_mps * dt;
  const Vec3 r_point = inertial_from_lvlh * r_lvlh;
  const Vec3 v_point = inertial_from_lvlh * (s.nav.v_lvlh_mps + s.lvlh.omega_lvlh_radps.cross(r_lvlh));
  const Vec3 offset = c.q_inertial_from_body * p.hub_from_chaser_com_body_m;
  c.r_hub_m = r_point + offset;
  c.v_hub_mps = v_point + (c.q_inertial_from_body * c.omega_body_radps).cross(offset);
  c.target = corrected_target_frame(*s.target, s.frame_offset_m, s.frame_rotation_rad, t_s);
  return c;
}

}  // namespace

std::optional<ReachParams> make_reach(const model::Scenario& s) {
  if (!s.capture || !s.chaser.arm || !s.target.body || !s.guidance.synchronised) return std::nullopt;
  const model::CaptureParams& c = *s.capture;
  const model::MultibodySceneParams scene = servicer_scene(s);
  ReachParams p;
  p.start_s = c.start_s;
  p.law = c.law;
  p.path_duration_s = c.path_duration_s;
  p.joint_period_ns = static_cast<TimeNs>(std::llround(1e9 / c.joint_rate_hz));
  if (c.escape) p.braked_step_s = c.escape->braked_step_s;
  p.platform_period_s = 1.0 / c.platform_rate_hz;
  p.servicer = arm::servicer_arm_of(scene);
  p.hub_from_chaser_com_body_m = scene.hub_com_body_m - s.chaser.com_body_m;
  p.capture_point_target_m = s.target.body->capture_point_target_m;
  p.q_target_from_body = s.guidance.synchronised->q_target_from_body.normalized();
  // The grasp attitude: the tool's x (its approach axis) along the chaser's +x, as the hold faces
  // the fixture; the pre-grasp point standoff short of the fixture along it.
  p.q_target_from_tool = p.q_target_from_body;
  p.grasp_point_target_m = s.target.body->grasp_point_target_m;
  p.pre_grasp_target_m = p.grasp_point_target_m - c.standoff_m * (p.q_target_from_tool * Vec3::UnitX());
  p.approach_end_target_m = p.grasp_point_target_m;
  if (c.berthing) p.approach_end_target_m += c.berthing->insertion_overtravel_m * (p.q_target_from_tool * Vec3::UnitX());
  p.approach_duration_s = c.approach_duration_s;
  p.grasp = make_grasp(c);
  p.torque_limit_Nm = s.chaser.arm->torque_repeated_peak_Nm;
  if (c.rigidise) {
    // The H-infinity law's chain: the servicer holding the catalogue target where the grasp holds it;
    // its loops' delay half the joints' period and the drives' torque loop.
    const double joint_period_s = 1.0 / c.joint_rate_hz;
    p.rigidise = RigidiseLawParams{
        .rigidise = *c.rigidise,
        .torque_limit_Nm = p.torque_limit_Nm,
        .held = arm::with_payload(p.servicer, arm::grasped_payload(p.servicer, s.target.body->mass_kg, s.target.body->inertia_kgm2,
                                                                   p.grasp_point_target_m, p.q_target_from_tool)),
        .joint_period_s = joint_period_s,
        .delay_s = 0.5 * joint_period_s + 1.0 / s.chaser.arm->torque_loop_bandwidth_radps};
  }
  if (c.escape) {  // the plan's ends: the capture point's hold, the tool stowed in the hub's frame
    arm::JointVector stowed_q;
    for (int j = 0; j < model::kArmJoints; ++j) stowed_q(j) = s.chaser.arm->stowed_rad[static_cast<std::size_t>(j)];
    const arm::ArmKinematics stowed = arm::arm_kinematics(p.servicer, Vec3::Zero(), Quat::Identity(), stowed_q);
    p.escape = EscapeLawParams{.escape = *c.escape,
                               .capture_point_target_m = p.capture_point_target_m,
                               .q_target_from_body = p.q_target_from_body,
                               .withdraw_point_target_m = s.guidance.synchronised->start_target_m,
                               .target_inertia_kgm2 = s.target.body->inertia_kgm2,
                               .hub_from_chaser_com_body_m = p.hub_from_chaser_com_body_m,
                               .tool_stowed_hub_m = stowed.r_tool_world_m,
                               .q_hub_from_tool_stowed = arm::tool_attitude(stowed),
                               .joint3_stowed_rad = stowed_q(arm::kRedundancyJoint)};
  }
  if (c.rigidise && c.stabilise)  // the target as the catalogue has it, where the grasp holds it
    p.stabilise = StabiliseLawParams{.stabilise = *c.stabilise,
                                     .target = {.mass_kg = s.target.body->mass_kg,
                                                .inertia_kgm2 = s.target.body->inertia_kgm2,
                                                .grasp_point_target_m = p.grasp_point_target_m,
                                                .q_target_from_tool = p.q_target_from_tool},
                                     .period_s = s.control_period_s};
  if (p.stabilise && c.stabilise->law == model::StabiliseLaw::kHinf) {  // COMRADE 2018, sec. 6.1.4
    const auto specs = control::composite_specs(s);
    for (std::size_t i = 0; i < specs.size(); ++i) {
      const control::AxisDesign design = control::design_axis(specs[i]);
      if (!design.ok())
        throw std::runtime_error(fmt::format("capture.stabilise.hinf: the {} loop's H-infinity design failed ({})",
                                             specs[i].name, design.synthesis.message));
      p.stabilise->hinf_loops[i] = discrete_loop(design, s.control_period_s);
    }
  }
  // The compliance gains at the stowed arm on a hub at rest (the tasks' inertias barely change over the reach).
  arm::JointVector stowed;
  for (int j = 0; j < model::kArmJoints; ++j) stowed(j) = s.chaser.arm->stowed_rad[static_cast<std::size_t>(j)];
  const arm::ArmKinematics at_stowed = arm::arm_kinematics(p.servicer, Vec3::Zero(), Quat::Identity(), stowed);
  p.gains = arm::compliance_gains(
      p.servicer, at_stowed,
      {.hub_radps = c.hub_bandwidth_radps, .tool_radps = c.tool_bandwidth_radps, .joint_radps = c.joint_bandwidth_radps,
       .damping_ratio = c.damping_ratio});
  if (c.law == model::CaptureLaw::kHinf) p.hinf = make_arm_hinf_control(hinf_spec(s, c));
  return p;
}

void hold_estimates(ReachState& state, const NavEstimate& nav, const std::optional<TargetEstimate>& target, double t_s,
                    const model::LvlhFrame& lvlh) {
  state.nav = nav;
  state.target = target;
  state.nav_t_s = t_s;
  state.lvlh = lvlh;
}

arm::FrameMotion tool_path(const ReachParams& params, const ReachState& state, double t_s) {
  if (params.approach_duration_s > 0.0 && t_s >= params.grasp.approach_start_s) {  // onto the fixture
    const Blend b = quintic(t_s - params.grasp.approach_start_s, params.approach_duration_s);
    const Vec3 travel = params.approach_end_target_m - params.pre_grasp_target_m;
    arm::FrameMotion f;
    f.r_m = params.pre_grasp_target_m + b.s * travel;
    f.v_mps = b.rate * travel;
    f.a_mps2 = b.acceleration * travel;
    f.q_world_from_frame = params.q_target_from_tool;
    if (params.grasp.berthing && state.grasp.lock_s >= 0.0) {  // latched: on, as the probe retracts
      const Blend r = quintic(t_s - state.grasp.lock_s, params.grasp.retraction_duration_s);
      const Vec3 retraction = params.grasp.retraction_m * (params.q_target_from_tool * Vec3::UnitX());
      f.r_m += r.s * retraction;
      f.v_mps += r.rate * retraction;
      f.a_mps2 += r.acceleration * retraction;
    }
    return f;
  }
  return pose_path(state.tool_start_target_m, state.q_target_from_tool_start, params.pre_grasp_target_m,
                   params.q_target_from_tool, t_s - params.start_s, params.path_duration_s);
}

bool platform_command(const ReachParams& params, ReachState& state, double t_s, Vec3& force_inertial_N,
                      Vec3& torque_body_Nm) {
  if (!state.has_output) return false;
  constexpr double kTimeTolS = 1e-9;  // ticks are sums of the period (as the sensors' samples)
  if (t_s + kTimeTolS >= state.next_platform_s) {
    state.held_force_inertial_N = state.platform_force_inertial_N;
    state.held_torque_body_Nm = state.platform_torque_body_Nm;
    if (state.next_platform_s == 0.0) state.next_platform_s = t_s;
    while (state.next_platform_s <= t_s + kTimeTolS) state.next_platform_s += params.platform_period_s;
  }
  force_inertial_N = state.held_force_inertial_N;
  torque_body_Nm = state.held_torque_body_Nm;
  return true;
}

void update_from_camera(const ReachParams& params, ReachState& state, const model::RelativePoseMeasurement& sample) {
  if (!sample.valid || !state.target) return;
  // The tool's pose nearest the sample's time (within two joint steps; the escape's braked arm is
  // stepped at its braked step).
  const ToolPoseSample* nearest = nullptr;
  for (const ToolPoseSample& p : state.tool_history)
    if (p.t_s >= 0.0 && (nearest == nullptr || std::abs(p.t_s - sample.taken_s) < std::abs(nearest->t_s - sample.taken_s)))
      nearest = &p;
  double step_s = to_seconds(params.joint_period_ns);
  if (state.escape.braked()) step_s = std::max(step_s, params.braked_step_s);
  if (nearest == nullptr || std::abs(nearest->t_s - sample.taken_s) > 2.0 * step_s) return;
  // The fixture in the law's world, and the target frame that puts it there.
  const Quat q_world_from_fixture = (nearest->q * sample.q_camera_from_fixture).normalized();
  const Vec3 r_fixture_m = nearest->r_m + nearest->q * sample.r_camera_m;
  const Quat q_world_from_target = (q_world_from_fixture * params.q_target_from_tool.conjugate()).normalized();
  const Vec3 offset_m = r_fixture_m - q_world_from_target * params.grasp_point_target_m;
  const Quat q_estimate = estimated_target_frame(*state.target, sample.taken_s).q_world_from_frame;
  const Vec3 rotation_rad = rotation_vector_from_quat(q_estimate.conjugate() * q_world_from_target);
  state.frame_offset_m += kCameraGain * (offset_m - state.frame_offset_m);
  state.frame_rotation_rad += kCameraGain * (rotation_rad - state.frame_rotation_rad);
  ++state.camera_samples;
  if (params.approach_duration_s > 0.0 && !state.escape.started())
    grasp_camera_sample(params.grasp, state.grasp, sample, state.nav_t_s);
}

model::ArmCommand step_reach(const ReachParams& params, ReachState& state, const model::ArmMeasurements& joints,
                             double t_s) {
  model::ArmCommand command;
  command.joints = model::kArmJoints;
  if (!state.target || joints.joints != model::kArmJoints) return command;
  arm::JointVector q, q_dot;
  for (int j = 0; j < model::kArmJoints; ++j) {
    q(j) = joints.q_rad[static_cast<std::size_t>(j)];
    q_dot(j) = joints.q_dot_radps[static_cast<std::size_t>(j)];
  }
  // Escaping, the grasp is over: the jaws stay open (the command's default).
  if (params.approach_duration_s > 0.0 && !state.escape.started())
    grasp_joint_step(params.grasp, state.grasp, joints, t_s, command);
  // A berthing soft docked is rigidised at once: the probe's mechanism draws the target in while the
  // arm holds its shape (the thrusters inhibited), the combined law no longer pressing the tip onto
  // a socket its camera may misplace (an H-infinity law's integral winds up against the latches).
  const bool soft_docked = params.grasp.berthing && state.grasp.step == GraspStep::kLocking;
  if (params.rigidise && (state.grasp.step == GraspStep::kCaptured || soft_docked)) {  // COMRADE 2018, sec. 4: the arm alone
    model::ArmCommand rigidise = step_rigidise(*params.rigidise, state.rigidise, joints, t_s, !soft_docked);
    rigidise.close_gripper = command.close_gripper;
    rigidise.lock_gripper = command.lock_gripper;
    rigidise.retract_probe = command.retract_probe;
    for (int j = 0; j < model::kArmJoints; ++j) state.joint_torque_Nm(j) = rigidise.torque_Nm[static_cast<std::size_t>(j)];
    return rigidise;
  }
  const Carried c = carry(params, state, t_s);
  const arm::ArmKinematics kinematics = arm::arm_kinematics(params.servicer, c.r_hub_m, c.q_inertial_from_body, q);
  ToolPoseSample& record = state.tool_history[static_cast<std::size_t>(state.tool_history_next)];
  record = {.t_s = t_s, .r_m = kinematics.r_tool_world_m, .q = arm::tool_attitude(kinematics)};
  state.tool_history_next = (state.tool_history_next + 1) % kToolPoseHistory;
  if (!state.started) {  // the path starts where the tool is, in the target's frame
    const Quat q_target_from_world = c.target.q_world_from_frame.conjugate();
    state.tool_start_target_m = q_target_from_world * kinematics.r_tool_world_m;
    state.q_target_from_tool_start = (q_target_from_world * arm::tool_attitude(kinematics)).normalized();
    state.joint3_start_rad = q(arm::kRedundancyJoint);
    state.started = true;
  }
  if (params.escape && !state.escape.started()) {  // the tool's pose in the target's frame, if it starts now
    const Quat q_target_from_world = c.target.q_world_from_frame.conjugate();
    escape_trigger(*params.escape, state.escape, state.grasp.step, t_s,
                   {.target = *state.target,
                    .target_frame = c.target,
                    .tool_target_m = q_target_from_world * (kinematics.r_tool_world_m - c.target.r_m),
                    .q_target_from_tool = (q_target_from_world * arm::tool_attitude(kinematics)).normalized(),
                    .joint3_rad = q(arm::kRedundancyJoint)});
  }
  // The escape's arm stowed and braked: the drives off, the combined law idle (the platform's own
  // loops fly the plan: flight/flight_software.cpp). The tool's pose is still recorded above, for
  // the camera's samples.
  if (state.escape.started() && escape_brakes(*params.escape, state.escape, joints, t_s)) {
    command.engage_brakes = true;
    state.joint_torque_Nm.setZero();
    return command;
  }
  arm::TaskReference reference;
  if (state.escape.started()) {
    reference = escape_reference(*params.escape, state.escape, *state.target, state.frame_offset_m,
                                 state.frame_rotation_rad, t_s);
  } else {
    arm::FrameMotion hub_in_target;
    hub_in_target.r_m = params.capture_point_target_m + params.q_target_from_body * params.hub_from_chaser_com_body_m;
    hub_in_target.q_world_from_frame = params.q_target_from_body;
    reference.hub = arm::compose(c.target, hub_in_target);
    reference.tool = arm::compose(c.target, tool_path(params, state, t_s));
    reference.joint_rad = state.joint3_start_rad;
  }

  arm::ServicerVector velocity;
  velocity << c.v_hub_mps, c.omega_body_radps, q_dot;
  arm::ServicerVector tau;
  if (params.law == model::CaptureLaw::kHinf) {
    const arm::ComputedTorque out = arm_hinf_control(params.hinf, state.hinf, params.servicer, kinematics, q, velocity, reference);
    tau = out.generalized_force;
    state.errors = out.errors;
  } else {
    const arm::ComplianceOutput out = arm::compliance_control(params.servicer, kinematics, q, velocity, reference, params.gains);
    tau = out.generalized_force;
    state.errors = out.errors;
  }
  // The platform's share for the thrusters: the force (inertial axes) and the torque moved from the
  // hub's CoM to the chaser's (arm stowed), about which the thrusters are allocated.
  state.platform_force_inertial_N = tau.head<3>();
  const Vec3 force_body = c.q_inertial_from_body.conjugate() * state.platform_force_inertial_N;
  state.platform_torque_body_Nm = tau.segment<3>(3) + params.hub_from_chaser_com_body_m.cross(force_body);
  for (int j = 0; j < model::kArmJoints; ++j) {
    state.joint_torque_Nm(j) = std::clamp(tau(arm::kBaseDofs + j), -params.torque_limit_Nm, params.torque_limit_Nm);
    command.torque_Nm[static_cast<std::size_t>(j)] = state.joint_torque_Nm(j);
  }
  state.has_output = true;
  return command;
}

}  // namespace chaser::flight
