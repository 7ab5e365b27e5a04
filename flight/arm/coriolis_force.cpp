#include "flight/arm/coriolis_force.hpp"

namespace chaser::flight::arm {

ServicerVector coriolis_times(const ServicerArmParams& params, const ArmKinematics& kinematics,
                              const ServicerVector& velocity, const ServicerVector& w) {
  constexpr int n = model::kArmJoints;
  const BodyInertias inertias = body_inertias_about_hub(params, kinematics);
  const ChainMotion c = chain_motion(kinematics, velocity, w);

  // Backward pass: each joint carries the forces F_i = I_i W'_i + V_i x* I_i W_i of the bodies
  // beyond it.
  ServicerVector tau;
  Vec6 carried = Vec6::Zero();
  for (int i = n; i >= 0; --i) {
    const std::size_t u = static_cast<std::size_t>(i);
    carried += inertias[u] * c.w_rate[u] + cross_force(c.velocity[u], inertias[u] * c.w[u]);
    if (i > 0) tau(kBaseDofs + i - 1) = c.subspace[u - 1].dot(carried);
  }
  tau.head<3>() = linear(carried);
  tau.segment<3>(3) = kinematics.world_from_hub.transpose() * angular(carried);
  return tau;
}

ServicerVector coriolis_force(const ServicerArmParams& params, const ArmKinematics& kinematics,
                              const ServicerVector& velocity) {
  return coriolis_times(params, kinematics, velocity, velocity);
}

}  // namespace chaser::flight::arm
