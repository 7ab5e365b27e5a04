// The flight model's parameters from the scene: the gripper lumped into link 7 keeps the mass,
// first moment and inertia of the two bodies; a broken model is refused with every problem named.
#include <gtest/gtest.h>

#include "flight/arm/servicer_arm.hpp"
#include "model/arm.hpp"

namespace chaser::flight::arm {
namespace {

TEST(ServicerArm, TheGripperLumpedIntoLink7KeepsTheTwoBodiesMassMomentAndInertia) {
  const model::MultibodySceneParams scene;
  const ServicerArmParams params = servicer_arm_of(scene);
  const model::ArmLinkParams& link7 = scene.arm.links.back();
  const model::GripperParams& gripper = scene.arm.gripper;
  const ServicerLinkParams& lumped = params.links.back();
  EXPECT_DOUBLE_EQ(lumped.mass_kg, link7.mass_kg + gripper.mass_kg);
  EXPECT_LT((lumped.mass_kg * lumped.com_link_m - link7.mass_kg * link7.com_link_m -
             gripper.mass_kg * gripper.com_link7_m).norm(), 1e-14);
  // About link 7's origin the inertias add: I_o = I_c + m (|c|^2 1 - c c') for each body.
  const auto about_origin = [](double m, const Mat3& I, const Vec3& c) -> Mat3 {
    return I + m * (c.squaredNorm() * Mat3::Identity() - c * c.transpose());
  };
  const Mat3 expected = about_origin(link7.mass_kg, link7.inertia_kgm2.asDiagonal(), link7.com_link_m) +
                        about_origin(gripper.mass_kg, gripper.inertia_kgm2.asDiagonal(), gripper.com_link7_m);
  const Mat3 lumped_about_origin = about_origin(lumped.mass_kg, lumped.inertia_com_link_kgm2, lumped.com_link_m);
  EXPECT_LT((lumped_about_origin - expected).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_EQ(params.links[0].joint_position_parent_m, scene.arm.mount_body_m);  // the mount folded in
  EXPECT_TRUE(validate(params).empty());
}

TEST(ServicerArm, TheMountIsTakenFromTheHubsCentreOfMass) {
  model::MultibodySceneParams scene;
  scene.hub_com_body_m = Vec3(0.1, -0.2, 0.3);
  EXPECT_EQ(servicer_arm_of(scene).links[0].joint_position_parent_m, scene.arm.mount_body_m - scene.hub_com_body_m);
}

TEST(ServicerArm, ABrokenModelIsRefusedWithEveryProblem) {
  ServicerArmParams params = servicer_arm_of(model::MultibodySceneParams{});
  params.hub_mass_kg = 0.0;
  params.hub_inertia_kgm2(0, 1) = 0.5;  // not symmetric
  params.links[2].joint_axis = Vec3(1.0, 1.0, 0.0);
  params.links[4].mass_kg = -1.0;
  params.links[5].armature_kgm2 = -0.1;
  EXPECT_EQ(validate(params).size(), 5u);
}

}  // namespace
}  // namespace chaser::flight::arm
