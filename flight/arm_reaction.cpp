#include "flight/arm_reaction.hpp"

#include "flight/arm/servicer_momentum.hpp"

namespace chaser::flight {

ArmReaction arm_reaction(const arm::ServicerArmParams& servicer, ArmReactionState& state,
                         const model::ArmMeasurements& joints, const Vec3& omega_body_radps) {
  arm::JointVector q, q_dot;
  for (int j = 0; j < model::kArmJoints; ++j) {
    q(j) = joints.q_rad[static_cast<std::size_t>(j)];
    q_dot(j) = joints.q_dot_radps[static_cast<std::size_t>(j)];
  }
  const arm::ServicerMomentum m = arm::servicer_momentum(servicer, q, q_dot, omega_body_radps);
  if (!state.woken) {
    state.woken = true;
    // The locked inertia at the wake's angles, so that h starts at zero: the arm still, L = J_0 w.
    state.locked_inertia_wake_kgm2 = m.locked_inertia_kgm2;
    state.com_wake_hub_m = m.com_hub_m;
  }
  return {.momentum_Nms = m.angular_momentum_Nms - state.locked_inertia_wake_kgm2 * omega_body_radps,
          .com_shift_m = m.com_hub_m - state.com_wake_hub_m};
}

}  // namespace chaser::flight
