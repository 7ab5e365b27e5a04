#include "flight/arm/coriolis_force.hpp"

namespace chaser::flight::arm {

ServicerVector coriolis_force(const ServicerArmParams& params, const ArmKinematics& kinematics,
                              const ServicerVector& velocity) {
  constexpr int n = model::kArmJoints;
  const BodyInertias inertias = body_inertias_about_hub(params, kinematics);
  const Vec3 v_hub_world_mps = velocity.head<3>();
  const Vec3 omega_world_radps = kinematics.world_from_hub * velocity.segment<3>(3);

  // Forward pass (RBDA Table 5.1): velocities, velocity-product accelerations and body forces.
  std::array<Vec6, n> subspace;
  Vec6 body_velocity = spatial(omega_world_radps, v_hub_world_mps);
  Vec6 body_acceleration = spatial(Vec3::Zero(), -omega_world_radps.cross(v_hub_world_mps));
  std::array<Vec6, 1 + n> body_force;
  body_force[0] = inertias[0] * body_acceleration + cross_force(body_velocity, inertias[0] * body_velocity);
  for (std::size_t i = 0; i < n; ++i) {
    subspace[i] = hinge_subspace(kinematics.axis_world[i], kinematics.r_link_world_m[i] - kinematics.r_hub_world_m);
    const Vec6 joint_velocity = subspace[i] * velocity(kBaseDofs + static_cast<Eigen::Index>(i));
    body_velocity += joint_velocity;
    body_acceleration += cross_motion(body_velocity, joint_velocity);
    const SpatialInertia& inertia = inertias[i + 1];
    body_force[i + 1] = inertia * body_acceleration + cross_force(body_velocity, inertia * body_velocity);
  }

  // Backward pass: each joint carries the forces of the bodies beyond it.
  ServicerVector tau;
  Vec6 carried = Vec6::Zero();
  for (int i = n - 1; i >= 0; --i) {
    const std::size_t u = static_cast<std::size_t>(i);
    carried += body_force[u + 1];
    tau(kBaseDofs + i) = subspace[u].dot(carried);
  }
  carried += body_force[0];
  tau.head<3>() = linear(carried);
  tau.segment<3>(3) = kinematics.world_from_hub.transpose() * angular(carried);
  return tau;
}

}  // namespace chaser::flight::arm
