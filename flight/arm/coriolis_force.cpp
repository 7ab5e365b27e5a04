#include "flight/arm/coriolis_force.hpp"

namespace chaser::flight::arm {

ServicerVector coriolis_times(const ServicerArmParams& params, const ArmKinematics& kinematics,
                              const ServicerVector& velocity, const ServicerVector& w) {
  constexpr int n = model::kArmJoints;
  const BodyInertias inertias = body_inertias_about_hub(params, kinematics);
  const Vec3 v_hub_world_mps = velocity.head<3>();
  const Vec3 omega_world_radps = kinematics.world_from_hub * velocity.segment<3>(3);
  const Vec3 w_omega_world = kinematics.world_from_hub * w.segment<3>(3);

  // Forward pass: V_i = J_i v (the body's velocity), W_i = J_i w and Wd_i = (dJ_i/dt) w. The free
  // joint's derivative applied to w is (omega x a; v_hub x a), a = R w_omega (its linear part is in
  // world axes, so only the angular column turns); a hinge's is V_i x S_i w_i.
  std::array<Vec6, n> subspace;
  Vec6 body_velocity = spatial(omega_world_radps, v_hub_world_mps);
  Vec6 body_w = spatial(w_omega_world, w.head<3>());
  Vec6 body_w_rate = spatial(omega_world_radps.cross(w_omega_world), v_hub_world_mps.cross(w_omega_world));
  // F_i = I_i Wd_i + V_i x* I_i W_i.
  std::array<Vec6, 1 + n> body_force;
  body_force[0] = inertias[0] * body_w_rate + cross_force(body_velocity, inertias[0] * body_w);
  for (std::size_t i = 0; i < n; ++i) {
    subspace[i] = hinge_subspace(kinematics.axis_world[i], kinematics.r_link_world_m[i] - kinematics.r_hub_world_m);
    const auto dof = static_cast<Eigen::Index>(kBaseDofs + i);
    body_velocity += subspace[i] * velocity(dof);
    const Vec6 joint_w = subspace[i] * w(dof);
    body_w += joint_w;
    body_w_rate += cross_motion(body_velocity, joint_w);
    const SpatialInertia& inertia = inertias[i + 1];
    body_force[i + 1] = inertia * body_w_rate + cross_force(body_velocity, inertia * body_w);
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

ServicerVector coriolis_force(const ServicerArmParams& params, const ArmKinematics& kinematics,
                              const ServicerVector& velocity) {
  return coriolis_times(params, kinematics, velocity, velocity);
}

}  // namespace chaser::flight::arm
