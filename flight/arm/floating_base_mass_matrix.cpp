#include "flight/arm/floating_base_mass_matrix.hpp"

namespace chaser::flight::arm {

ServicerMatrix floating_base_mass_matrix(const ServicerArmParams& params, const ArmKinematics& kinematics) {
  constexpr int n = model::kArmJoints;
  const BodyInertias inertias = body_inertias_about_hub(params, kinematics);
  BodyInertias composite;  // RBDA Table 6.2: I^c_i = I_i + the composite of its child
  composite[n] = inertias[n];
  for (int b = n - 1; b >= 0; --b) composite[b] = inertias[b] + composite[b + 1];

  std::array<Vec6, n> subspace;
  for (std::size_t i = 0; i < n; ++i)
    subspace[i] = hinge_subspace(kinematics.axis_world[i], kinematics.r_link_world_m[i] - kinematics.r_hub_world_m);

  const Mat3& world_from_hub = kinematics.world_from_hub;
  ServicerMatrix H;
  for (int i = n - 1; i >= 0; --i) {
    const std::size_t u = static_cast<std::size_t>(i);
    const Vec6 force = composite[u + 1] * subspace[u];  // F = I^c_i S_i
    const int col = kBaseDofs + i;
    H(col, col) = subspace[u].dot(force) + params.links[u].armature_kgm2;
    for (int j = 0; j < i; ++j)  // the joints between the hub and joint i: H_ji = S_j' F
      H(kBaseDofs + j, col) = H(col, kBaseDofs + j) = subspace[static_cast<std::size_t>(j)].dot(force);
    H.block<3, 1>(0, col) = linear(force);
    H.block<3, 1>(3, col) = world_from_hub.transpose() * angular(force);
    H.block<1, 6>(col, 0) = H.block<6, 1>(0, col).transpose();
  }

  const SpatialInertia& servicer = composite[0];
  const Mat3 coupling = -cross_matrix(servicer.h_kgm) * world_from_hub;  // linear momentum per omega_hub
  H.topLeftCorner<3, 3>() = servicer.mass_kg * Mat3::Identity();
  H.block<3, 3>(0, 3) = coupling;
  H.block<3, 3>(3, 0) = coupling.transpose();
  const Mat3 rotational = world_from_hub.transpose() * servicer.inertia_o_kgm2 * world_from_hub;
  H.block<3, 3>(3, 3) = 0.5 * (rotational + rotational.transpose());  // symmetric to the last bit
  return H;
}

}  // namespace chaser::flight::arm
