#include "flight/arm/arm_kinematics.hpp"

#include <Eigen/Geometry>

namespace chaser::flight::arm {

ArmKinematics arm_kinematics(const ServicerArmParams& params, const Vec3& r_hub_world_m, const Quat& q_world_from_hub,
                             const JointVector& joint_angles_rad) {
  ArmKinematics k;
  k.r_hub_world_m = r_hub_world_m;
  k.world_from_hub = q_world_from_hub.normalized().toRotationMatrix();
  Mat3 world_from_parent = k.world_from_hub;
  Vec3 r_parent_world_m = r_hub_world_m;
  for (std::size_t i = 0; i < params.links.size(); ++i) {
    const ServicerLinkParams& link = params.links[i];
    k.r_link_world_m[i] = r_parent_world_m + world_from_parent * link.joint_position_parent_m;
    k.axis_world[i] = world_from_parent * link.joint_axis;  // the axis is fixed in both frames
    const double q_rad = joint_angles_rad(static_cast<Eigen::Index>(i));
    k.world_from_link[i] = world_from_parent * Eigen::AngleAxisd(q_rad, link.joint_axis).toRotationMatrix();
    k.r_com_world_m[i] = k.r_link_world_m[i] + k.world_from_link[i] * link.com_link_m;
    world_from_parent = k.world_from_link[i];
    r_parent_world_m = k.r_link_world_m[i];
  }
  k.r_tool_world_m = r_parent_world_m + world_from_parent * params.tool_link7_m;
  return k;
}

ToolJacobian tool_jacobian(const ArmKinematics& kinematics) {
  ToolJacobian jacobian = ToolJacobian::Zero();
  jacobian.topLeftCorner<3, 3>().setIdentity();
  const Vec3 r_tool_from_hub_m = kinematics.r_tool_world_m - kinematics.r_hub_world_m;
  for (int k = 0; k < 3; ++k) {
    const Vec3 axis = kinematics.world_from_hub.col(k);  // the hub's angular velocity is in hub axes
    jacobian.block<3, 1>(0, 3 + k) = axis.cross(r_tool_from_hub_m);
    jacobian.block<3, 1>(3, 3 + k) = axis;
  }
  for (int i = 0; i < model::kArmJoints; ++i) {
    const std::size_t n = static_cast<std::size_t>(i);
    const Vec3& axis = kinematics.axis_world[n];
    jacobian.block<3, 1>(0, kBaseDofs + i) = axis.cross(kinematics.r_tool_world_m - kinematics.r_link_world_m[n]);
    jacobian.block<3, 1>(3, kBaseDofs + i) = axis;
  }
  return jacobian;
}

ChainMotion chain_motion(const ArmKinematics& kinematics, const Eigen::Matrix<double, kServicerDofs, 1>& velocity,
                         const Eigen::Matrix<double, kServicerDofs, 1>& w) {
  ChainMotion c;
  const Vec3 v_hub_world_mps = velocity.head<3>();
  const Vec3 omega_world_radps = kinematics.world_from_hub * velocity.segment<3>(3);
  const Vec3 w_omega_world = kinematics.world_from_hub * w.segment<3>(3);
  c.velocity[0] = spatial(omega_world_radps, v_hub_world_mps);
  c.w[0] = spatial(w_omega_world, w.head<3>());
  c.w_rate[0] = spatial(omega_world_radps.cross(w_omega_world), v_hub_world_mps.cross(w_omega_world));
  for (std::size_t i = 0; i < static_cast<std::size_t>(model::kArmJoints); ++i) {
    c.subspace[i] = hinge_subspace(kinematics.axis_world[i], kinematics.r_link_world_m[i] - kinematics.r_hub_world_m);
    const auto dof = static_cast<Eigen::Index>(kBaseDofs + i);
    const Vec6 joint_w = c.subspace[i] * w(dof);
    c.velocity[i + 1] = c.velocity[i] + c.subspace[i] * velocity(dof);
    c.w[i + 1] = c.w[i] + joint_w;
    c.w_rate[i + 1] = c.w_rate[i] + cross_motion(c.velocity[i + 1], joint_w);
  }
  return c;
}

BodyInertias body_inertias_about_hub(const ServicerArmParams& params, const ArmKinematics& kinematics) {
  BodyInertias inertias;
  const Mat3& world_from_hub = kinematics.world_from_hub;
  inertias[0] = spatial_inertia(params.hub_mass_kg, Vec3::Zero(),
                                world_from_hub * params.hub_inertia_kgm2 * world_from_hub.transpose());
  for (std::size_t i = 0; i < params.links.size(); ++i) {
    const ServicerLinkParams& link = params.links[i];
    const Mat3& world_from_link = kinematics.world_from_link[i];
    inertias[i + 1] = spatial_inertia(link.mass_kg, kinematics.r_com_world_m[i] - kinematics.r_hub_world_m,
                                      world_from_link * link.inertia_com_link_kgm2 * world_from_link.transpose());
  }
  return inertias;
}

}  // namespace chaser::flight::arm
