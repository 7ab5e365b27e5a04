#include "flight/rigidise.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "control/joint_design.hpp"
#include "flight/arm/arm_kinematics.hpp"
#include "flight/arm/floating_base_mass_matrix.hpp"
#include "flight/joints_quiet.hpp"

namespace chaser::flight {

double linear_saturation(double tau, double linear_limit, double limit) {
  const double span = limit - linear_limit;
  if (tau > linear_limit) return linear_limit + span * std::tanh((tau - linear_limit) / span);
  if (tau < -linear_limit) return -linear_limit + span * std::tanh((tau + linear_limit) / span);
  return tau;
}

double clip_saturation(double tau, double limit) { return std::clamp(tau, -limit, limit); }

arm::JointMatrix rigidise_joint_inertia(const RigidiseLawParams& params, const arm::JointVector& joint_angles_rad) {
  const arm::ArmKinematics k = arm::arm_kinematics(params.held, Vec3::Zero(), Quat::Identity(), joint_angles_rad);
  return arm::free_floating_joint_inertia(arm::floating_base_mass_matrix(params.held, k));
}

std::array<DiscreteLoop, model::kArmJoints> rigidise_loops(const RigidiseLawParams& params,
                                                           const arm::JointMatrix& inertia_kgm2) {
  std::array<double, model::kArmJoints> diagonal{};
  for (int j = 0; j < model::kArmJoints; ++j) diagonal[static_cast<std::size_t>(j)] = inertia_kgm2(j, j);
  const auto specs = control::joint_specs(params.rigidise.hinf, params.torque_limit_Nm, diagonal, params.delay_s);
  std::array<DiscreteLoop, model::kArmJoints> loops;
  for (std::size_t j = 0; j < specs.size(); ++j) {
    const control::AxisDesign design = control::design_axis(specs[j]);
    if (!design.ok())
      throw std::runtime_error(fmt::format("capture.rigidise.hinf: the {} loop's H-infinity design failed ({})",
                                           specs[j].name, design.synthesis.message));
    loops[j] = discrete_loop(design, params.joint_period_s);
    // The drives' saturation of tau = H* u limits the law, not a clamp on each u_j: a load on the
    // chain's self-motion (a small eigenvalue of H*) asks for a u far beyond M / H*_jj and a
    // modest torque.
    loops[j].authority = std::numeric_limits<double>::infinity();
  }
  return loops;
}

model::ArmCommand step_rigidise(const RigidiseLawParams& params, RigidiseState& state,
                                const model::ArmMeasurements& joints, double t_s, bool may_brake) {
  const model::RigidiseParams& r = params.rigidise;
  model::ArmCommand command;
  command.joints = model::kArmJoints;
  if (!state.started()) {
    for (int j = 0; j < model::kArmJoints; ++j) state.q_hold_rad(j) = joints.q_rad[static_cast<std::size_t>(j)];
    state.started_s = t_s;
    if (r.law == model::RigidiseLaw::kHinf) {
      state.inertia_kgm2 = rigidise_joint_inertia(params, state.q_hold_rad);
      state.loops = rigidise_loops(params, state.inertia_kgm2);
    }
  }
  if (state.brakes_s < 0.0) {
    const bool quiet = joints_slower_than(joints, r.brake_rate_degps);
    if (!quiet || !may_brake)
      state.quiet_since_s = -1.0;
    else if (state.quiet_since_s < 0.0)
      state.quiet_since_s = t_s;
    if (quiet && may_brake && t_s - state.quiet_since_s >= r.brake_dwell_s) state.brakes_s = t_s;
  }
  if (state.brakes_s >= 0.0) {  // braked: the drives are off
    command.engage_brakes = true;
    return command;
  }
  const auto saturate = [&](double tau) {
    return r.saturation == model::RigidiseSaturation::kClip ? clip_saturation(tau, params.torque_limit_Nm)
                                                            : linear_saturation(tau, r.linear_limit_Nm, params.torque_limit_Nm);
  };
  if (r.law == model::RigidiseLaw::kHinf) {
    arm::JointVector u;  // [rad/s^2]
    for (int j = 0; j < model::kArmJoints; ++j) {
      const auto i = static_cast<std::size_t>(j);
      u(j) = step_loop(state.loops[i], state.x[i], state.q_hold_rad(j) - joints.q_rad[i]);
    }
    const arm::JointVector tau = state.inertia_kgm2 * u;
    for (int j = 0; j < model::kArmJoints; ++j) command.torque_Nm[static_cast<std::size_t>(j)] = saturate(tau(j));
    return command;
  }
  for (int j = 0; j < model::kArmJoints; ++j) {
    const auto i = static_cast<std::size_t>(j);
    const double tau = r.damping_Nms_per_rad * joints.q_dot_radps[i] +
                       r.stiffness_Nm_per_rad * (joints.q_rad[i] - state.q_hold_rad(j));
    command.torque_Nm[i] = -saturate(tau);
  }
  return command;
}

}  // namespace chaser::flight
