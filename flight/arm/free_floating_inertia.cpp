#include "flight/arm/free_floating_inertia.hpp"

#include <Eigen/Cholesky>

namespace chaser::flight::arm {

Link7Payload grasped_payload(const ServicerArmParams& servicer, double mass_kg, const Mat3& inertia_kgm2,
                             const Vec3& grasp_point_target_m, const Quat& q_target_from_tool) {
  const Mat3 tool_from_target = q_target_from_tool.normalized().toRotationMatrix().transpose();
  return {.mass_kg = mass_kg,
          .com_link7_m = servicer.tool_link7_m - tool_from_target * grasp_point_target_m,
          .inertia_link7_kgm2 = tool_from_target * inertia_kgm2 * tool_from_target.transpose()};
}

ServicerArmParams with_payload(ServicerArmParams servicer, const Link7Payload& payload) {
  servicer.links.back() =
      with_rigid_body(servicer.links.back(), payload.mass_kg, payload.com_link7_m, payload.inertia_link7_kgm2);
  return servicer;
}

JointMatrix free_floating_joint_inertia(const ServicerMatrix& mass_matrix) {
  constexpr int n = model::kArmJoints;
  using BaseMatrix = Eigen::Matrix<double, kBaseDofs, kBaseDofs>;
  const BaseMatrix base = mass_matrix.topLeftCorner<kBaseDofs, kBaseDofs>();
  const Eigen::Matrix<double, kBaseDofs, n> coupling = mass_matrix.topRightCorner<kBaseDofs, n>();
  const JointMatrix schur =
      mass_matrix.bottomRightCorner<n, n>() - coupling.transpose() * Eigen::LLT<BaseMatrix>(base).solve(coupling);
  return 0.5 * (schur + schur.transpose());  // symmetric to rounding: made exactly so
}

}  // namespace chaser::flight::arm
