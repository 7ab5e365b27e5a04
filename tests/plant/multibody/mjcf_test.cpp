// The generated MJCF against the parameters it comes from, read back from the model MuJoCo
// compiled: the same masses, inertias, joints, limits and drives, and the same text every time.
#include <cmath>
#include <numeric>

#include <gtest/gtest.h>

#include "model/arm.hpp"
#include "plant/multibody/mjcf.hpp"
#include "plant/multibody/mujoco_model.hpp"

namespace chaser::plant::multibody {
namespace {

TEST(Mjcf, TheCompiledSceneHoldsTheParametersExactly) {
  model::MultibodySceneParams scene;
  scene.hub_inertia_kgm2 = Vec3(1850.0, 1900.0, 1300.0).asDiagonal();
  scene.target_inertia_kgm2 = Vec3(17023.0, 124826.0, 129112.0).asDiagonal();
  MujocoModel model(mjcf_of(scene));
  const mjModel& m = model.model();
  EXPECT_EQ(m.nv, 6 + model::kArmJoints + 6);
  EXPECT_EQ(m.nu, model::kArmJoints);
  EXPECT_EQ(m.opt.timestep, scene.timestep_s);
  EXPECT_EQ(m.opt.integrator, mjINT_RK4);
  EXPECT_EQ(m.body_mass[model.body("hub")], scene.hub_mass_kg);
  EXPECT_EQ(m.body_mass[model.body("target")], scene.target_mass_kg);
  double arm_mass_kg = scene.arm.gripper.mass_kg;
  for (int i = 0; i < model::kArmJoints; ++i) {
    const model::ArmLinkParams& link = scene.arm.links[static_cast<std::size_t>(i)];
    const std::string name = "joint" + std::to_string(i + 1);
    const int joint = model.joint(name.c_str());
    const int dof = m.jnt_dofadr[joint];
    EXPECT_EQ(m.body_mass[m.jnt_bodyid[joint]], link.mass_kg) << name;
    EXPECT_EQ(m.jnt_range[2 * joint], link.lower_rad) << name;
    EXPECT_EQ(m.jnt_range[2 * joint + 1], link.upper_rad) << name;
    EXPECT_EQ(m.dof_frictionloss[dof], link.friction_Nm) << name;
    EXPECT_EQ(m.dof_armature[dof], link.armature_kgm2) << name;
    const int motor = model.actuator(("motor" + std::to_string(i + 1)).c_str());
    EXPECT_EQ(m.actuator_ctrlrange[2 * motor + 1], scene.arm.torque_momentary_Nm) << name;
    arm_mass_kg += link.mass_kg;
  }
  const double total_kg = std::accumulate(m.body_mass, m.body_mass + m.nbody, 0.0);
  EXPECT_NEAR(total_kg, scene.hub_mass_kg + arm_mass_kg + scene.target_mass_kg, 1e-9);
  EXPECT_NEAR(arm_mass_kg, 80.0, 1e-12);  // default_arm()'s total, gripper included
}

TEST(Mjcf, TheTargetsShapeIsGeometryWithoutMassOrContact) {
  model::MultibodySceneParams scene;
  scene.target_inertia_kgm2 = Vec3(17023.0, 124826.0, 129112.0).asDiagonal();
  MujocoModel bare(mjcf_of(scene));
  scene.target_shape = {{Vec3(-1.1, 0.0, 0.0), Vec3(5.0, 2.0, 2.0)}, {Vec3(-15.1, 0.0, 0.0), Vec3(7.0, 2.5, 0.1)}};  // ENVISAT's
  MujocoModel shaped(mjcf_of(scene));
  const mjModel& m = shaped.model();
  const int target = shaped.body("target");
  for (std::size_t i = 0; i < scene.target_shape.size(); ++i) {
    const int geom = mj_name2id(&m, mjOBJ_GEOM, ("shape" + std::to_string(i)).c_str());
    ASSERT_GE(geom, 0);
    EXPECT_EQ(m.geom_bodyid[geom], target);
    EXPECT_EQ(m.geom_type[geom], mjGEOM_BOX);
    EXPECT_EQ(m.geom_contype[geom], 0);
    EXPECT_EQ(m.geom_conaffinity[geom], 0);
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(m.geom_size[3 * geom + k], scene.target_shape[i].half_extents_m[k]);
      EXPECT_EQ(m.geom_pos[3 * geom + k], scene.target_shape[i].centre_target_m[k]);
    }
  }
  // The boxes add no mass and move neither the CoM nor the inertia: the <inertial>'s are the target's.
  EXPECT_EQ(m.body_mass[target], bare.model().body_mass[bare.body("target")]);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(m.body_inertia[3 * target + k], bare.model().body_inertia[3 * bare.body("target") + k]);
    EXPECT_EQ(m.body_ipos[3 * target + k], bare.model().body_ipos[3 * bare.body("target") + k]);
  }
}

TEST(Mjcf, TheStretchedArmPutsTheToolPointWhereTheLinksSayAndTheTextIsStable) {
  model::MultibodySceneParams scene;
  scene.hub_com_body_m = Vec3(0.02, -0.01, 0.03);  // the hub's frame is at its CoM
  MujocoModel model(mjcf_of(scene));
  model.forward();
  const int tool = mj_name2id(&model.model(), mjOBJ_SITE, "tool");
  ASSERT_GE(tool, 0);
  Vec3 expected = scene.arm.mount_body_m - scene.hub_com_body_m + scene.arm.gripper.position_link7_m;
  for (const auto& link : scene.arm.links) expected += link.joint_position_parent_m;
  const Vec3 tool_m(model.data().site_xpos[3 * tool], model.data().site_xpos[3 * tool + 1],
                    model.data().site_xpos[3 * tool + 2]);
  EXPECT_LT((tool_m - expected).norm(), 1e-12);
  EXPECT_NEAR(expected.x() + scene.hub_com_body_m.x() - scene.arm.mount_body_m.x(), 3.1, 1e-12);  // the arm's reach
  EXPECT_EQ(mjcf_of(scene), mjcf_of(scene));
}

}  // namespace
}  // namespace chaser::plant::multibody
