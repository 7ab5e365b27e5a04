#include "flight/rigidise.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace chaser::flight {

double linear_saturation(double tau, double linear_limit, double limit) {
  const double span = limit - linear_limit;
  if (tau > linear_limit) return linear_limit + span * std::tanh((tau - linear_limit) / span);
  if (tau < -linear_limit) return -linear_limit + span * std::tanh((tau + linear_limit) / span);
  return tau;
}

double clip_saturation(double tau, double limit) { return std::clamp(tau, -limit, limit); }

model::ArmCommand step_rigidise(const RigidiseLawParams& params, RigidiseState& state,
                                const model::ArmMeasurements& joints, double t_s) {
  const model::RigidiseParams& r = params.rigidise;
  model::ArmCommand command;
  command.joints = model::kArmJoints;
  if (!state.started()) {
    for (int j = 0; j < model::kArmJoints; ++j) state.q_hold_rad(j) = joints.q_rad[static_cast<std::size_t>(j)];
    state.started_s = t_s;
  }
  if (state.brakes_s < 0.0) {
    const double threshold_radps = r.brake_rate_degps * std::numbers::pi / 180.0;
    bool quiet = true;
    for (int j = 0; j < model::kArmJoints; ++j)
      quiet = quiet && std::abs(joints.q_dot_radps[static_cast<std::size_t>(j)]) < threshold_radps;
    if (!quiet)
      state.quiet_since_s = -1.0;
    else if (state.quiet_since_s < 0.0)
      state.quiet_since_s = t_s;
    if (quiet && t_s - state.quiet_since_s >= r.brake_dwell_s) state.brakes_s = t_s;
  }
  if (state.brakes_s >= 0.0) {  // braked: the drives are off
    command.engage_brakes = true;
    return command;
  }
  for (int j = 0; j < model::kArmJoints; ++j) {
    const auto i = static_cast<std::size_t>(j);
    const double tau = r.damping_Nms_per_rad * joints.q_dot_radps[i] +
                       r.stiffness_Nm_per_rad * (joints.q_rad[i] - state.q_hold_rad(j));
    command.torque_Nm[i] = -(r.saturation == model::RigidiseSaturation::kClip
                                 ? clip_saturation(tau, params.torque_limit_Nm)
                                 : linear_saturation(tau, r.linear_limit_Nm, params.torque_limit_Nm));
  }
  return command;
}

}  // namespace chaser::flight
