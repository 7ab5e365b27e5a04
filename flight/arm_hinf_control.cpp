#include "flight/arm_hinf_control.hpp"

#include <stdexcept>

#include <fmt/format.h>

namespace chaser::flight {

namespace {

constexpr std::array<const char*, arm::kTaskDofs> kTaskNames = {
    "hub x", "hub y", "hub z", "hub rx", "hub ry", "hub rz", "tool x", "tool y", "tool z",
    "tool rx", "tool ry", "tool rz", "joint 3"};

const ArmHinfGroupSpec& group_of(const ArmHinfSpec& spec, int task) {
  if (task < 3) return spec.hub_position;
  if (task < 6) return spec.hub_attitude;
  if (task < 9) return spec.tool_position;
  if (task < 12) return spec.tool_attitude;
  return spec.joint;
}

}  // namespace

ArmHinfParams make_arm_hinf_control(const ArmHinfSpec& spec) {
  ArmHinfParams params;
  for (int k = 0; k < arm::kTaskDofs; ++k) {
    const ArmHinfGroupSpec& group = group_of(spec, k);
    control::AxisDesignSpec axis;
    axis.name = kTaskNames[static_cast<std::size_t>(k)];
    axis.authority = group.authority;
    axis.delay_s = group.delay_s;
    axis.bandwidth_radps = group.bandwidth_radps;
    axis.peak_sensitivity = group.peak_sensitivity;
    axis.low_frequency_gain = group.low_frequency_gain;
    axis.error_scale = group.error_scale;
    axis.input_disturbance = group.input_disturbance;
    const control::AxisDesign design = control::design_axis(axis);
    if (!design.ok())
      throw std::runtime_error(
          fmt::format("the arm's H-infinity loop of {} failed ({})", axis.name, design.synthesis.message));
    params.loops[static_cast<std::size_t>(k)] = discrete_loop(design, spec.period_s);
  }
  return params;
}

arm::ComputedTorque arm_hinf_control(const ArmHinfParams& params, ArmHinfState& state,
                                     const arm::ServicerArmParams& servicer, const arm::ArmKinematics& kinematics,
                                     const arm::JointVector& joint_angles_rad, const arm::ServicerVector& velocity,
                                     const arm::TaskReference& reference) {
  const arm::TaskJacobian J = arm::extended_jacobian(kinematics);
  const arm::TaskVector e =
      arm::loop_errors(arm::task_errors(kinematics, J, joint_angles_rad, velocity, reference));
  arm::TaskVector u;
  for (std::size_t k = 0; k < params.loops.size(); ++k)
    u(static_cast<Eigen::Index>(k)) = step_loop(params.loops[k], state.x[k], -e(static_cast<Eigen::Index>(k)));
  return arm::computed_torque(servicer, kinematics, joint_angles_rad, velocity, reference, u);
}

}  // namespace chaser::flight
