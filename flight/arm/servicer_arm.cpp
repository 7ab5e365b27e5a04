#include "flight/arm/servicer_arm.hpp"

#include <cmath>

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

namespace chaser::flight::arm {

namespace {

// The inertia about a point displaced by d from the CoM: I + m (|d|^2 1 - d d') (parallel axes).
Mat3 shifted_inertia(double mass_kg, const Mat3& inertia_com_kgm2, const Vec3& d_m) {
  return inertia_com_kgm2 + mass_kg * (d_m.squaredNorm() * Mat3::Identity() - d_m * d_m.transpose());
}

bool symmetric_psd(const Mat3& inertia_kgm2, bool definite) {
  if (!inertia_kgm2.allFinite()) return false;
  const double scale = inertia_kgm2.cwiseAbs().maxCoeff();
  if ((inertia_kgm2 - inertia_kgm2.transpose()).cwiseAbs().maxCoeff() > 1e-12 * scale) return false;
  const double smallest = Eigen::SelfAdjointEigenSolver<Mat3>(inertia_kgm2).eigenvalues().minCoeff();
  return definite ? smallest > 0.0 : smallest >= -1e-12 * scale;
}

}  // namespace

ServicerLinkParams with_rigid_body(ServicerLinkParams link, double mass_kg, const Vec3& com_link_m,
                                   const Mat3& inertia_com_link_kgm2) {
  const double total_kg = link.mass_kg + mass_kg;
  const Vec3 com_m = (link.mass_kg * link.com_link_m + mass_kg * com_link_m) / total_kg;
  link.inertia_com_link_kgm2 = shifted_inertia(link.mass_kg, link.inertia_com_link_kgm2, link.com_link_m - com_m) +
                               shifted_inertia(mass_kg, inertia_com_link_kgm2, com_link_m - com_m);
  link.mass_kg = total_kg;
  link.com_link_m = com_m;
  return link;
}

ServicerArmParams servicer_arm_of(const model::MultibodySceneParams& scene) {
  ServicerArmParams params;
  params.hub_mass_kg = scene.hub_mass_kg;
  params.hub_inertia_kgm2 = scene.hub_inertia_kgm2;
  for (int i = 0; i < model::kArmJoints; ++i) {
    const model::ArmLinkParams& from = scene.arm.links[static_cast<std::size_t>(i)];
    ServicerLinkParams& link = params.links[static_cast<std::size_t>(i)];
    // The hub's frame is at its CoM: the mount, given from the body's reference point, moves by
    // the CoM's offset (as plant/multibody/mjcf places it).
    link.joint_position_parent_m =
        i == 0 ? Vec3(scene.arm.mount_body_m - scene.hub_com_body_m + from.joint_position_parent_m)
               : from.joint_position_parent_m;
    link.joint_axis = from.joint_axis;
    link.mass_kg = from.mass_kg;
    link.com_link_m = from.com_link_m;
    link.inertia_com_link_kgm2 = from.inertia_kgm2.asDiagonal();
    link.armature_kgm2 = from.armature_kgm2;
  }
  const model::GripperParams& gripper = scene.arm.gripper;  // rigid on link 7, in its frame
  params.links.back() =
      with_rigid_body(params.links.back(), gripper.mass_kg, gripper.com_link7_m, gripper.inertia_kgm2.asDiagonal());
  params.tool_link7_m = scene.arm.gripper.position_link7_m;
  return params;
}

std::vector<std::string> validate(const ServicerArmParams& params) {
  std::vector<std::string> problems;
  if (!(params.hub_mass_kg > 0.0 && std::isfinite(params.hub_mass_kg)))
    problems.push_back("arm.hub_mass_kg: must be finite and > 0");
  if (!symmetric_psd(params.hub_inertia_kgm2, true))
    problems.push_back("arm.hub_inertia_kgm2: must be symmetric positive definite");
  for (int i = 0; i < model::kArmJoints; ++i) {
    const ServicerLinkParams& link = params.links[static_cast<std::size_t>(i)];
    const std::string key = fmt::format("arm.links[{}]", i);
    if (!link.joint_position_parent_m.allFinite() || !link.com_link_m.allFinite())
      problems.push_back(key + ".joint_position_parent_m, com_link_m: must be finite");
    if (!(std::abs(link.joint_axis.norm() - 1.0) <= 1e-12))
      problems.push_back(key + ".joint_axis: must be a unit vector (to 1e-12)");
    if (!(link.mass_kg >= 0.0 && std::isfinite(link.mass_kg)))
      problems.push_back(key + ".mass_kg: must be finite and >= 0");
    if (!symmetric_psd(link.inertia_com_link_kgm2, false))
      problems.push_back(key + ".inertia_com_link_kgm2: must be symmetric positive semidefinite");
    if (!(link.armature_kgm2 >= 0.0 && std::isfinite(link.armature_kgm2)))
      problems.push_back(key + ".armature_kgm2: must be finite and >= 0");
  }
  if (!params.tool_link7_m.allFinite()) problems.push_back("arm.tool_link7_m: must be finite");
  return problems;
}

}  // namespace chaser::flight::arm
