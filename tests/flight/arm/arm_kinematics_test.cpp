// The arm's kinematics against the stretched arm's closed form and against MuJoCo's kinematics of
// the same scene (plant/multibody): link poses, CoMs, the tool point and its Jacobian.
//
// Tolerances: positions 1e-12 m and rotations 1e-12, where both sides compose the same seven
// rotations (MuJoCo by quaternions, this model by matrices), so they differ by rounding, ~1e-15
// per factor over lever arms of ~10 m; the Jacobian 1e-10 (its entries are lever arms of up to
// ~15 m times unit axes, and MuJoCo forms them about the subtree's CoM, not the hub's origin:
// more terms, still rounding only).
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "flight/arm/arm_kinematics.hpp"
#include "plant/multibody/mjcf.hpp"
#include "plant/multibody/mujoco_model.hpp"
#include "tests/flight/arm/arm_test_support.hpp"

namespace chaser::flight::arm {
namespace {

using plant::multibody::MujocoModel;
using plant::multibody::mjcf_of;

constexpr int kConfigurations = 20;

TEST(ArmKinematics, TheStretchedArmsToolPointIsTheSumOfItsOffsets) {
  const ServicerArmParams params = servicer_arm_of(model::MultibodySceneParams{});
  const Vec3 r_hub_world_m(1.0, -2.0, 3.0);
  const ArmKinematics k = arm_kinematics(params, r_hub_world_m, Quat::Identity(), JointVector::Zero());
  // Mount 1.05 m, joint offsets 0.2 + 0.2 + 1.1 + 0.2 + 1.0 + 0.1 m, tool 0.3 m: 4.15 m along x.
  EXPECT_LT((k.r_tool_world_m - r_hub_world_m - Vec3(4.15, 0.0, 0.0)).norm(), 1e-14);
  // Turned by 90 deg about z, the arm points along the world's y.
  const Quat q_world_from_hub(Eigen::AngleAxisd(EIGEN_PI / 2.0, Vec3::UnitZ()));
  const ArmKinematics turned = arm_kinematics(params, Vec3::Zero(), q_world_from_hub, JointVector::Zero());
  EXPECT_LT((turned.r_tool_world_m - Vec3(0.0, 4.15, 0.0)).norm(), 1e-14);
}

TEST(ArmKinematics, LinkPosesComsAndToolPointMatchMujoco) {
  for (const model::MultibodySceneParams& scene : testing::scenes()) {
    const ServicerArmParams params = servicer_arm_of(scene);
    MujocoModel mujoco(mjcf_of(scene));
    const mjModel& m = mujoco.model();
    const mjData& d = mujoco.data();
    const int tool = mj_name2id(&m, mjOBJ_SITE, "tool");
    const int gripper = mujoco.body("gripper");
    RandomStream random(20180601, "flight/arm/kinematics");
    double worst_position_m = 0.0, worst_rotation = 0.0;
    for (int n = 0; n < kConfigurations; ++n) {
      const testing::Configuration c = testing::random_configuration(random, scene.arm);
      testing::set_state(mujoco, c);
      const ArmKinematics k = arm_kinematics(params, c.r_hub_world_m, c.q_world_from_hub, c.joint_angles_rad);
      for (int i = 0; i < model::kArmJoints; ++i) {
        const std::size_t u = static_cast<std::size_t>(i);
        const int b = mujoco.body(("link" + std::to_string(i + 1)).c_str());
        const Vec3 xpos(d.xpos + 3 * b);
        const Mat3 xmat = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(d.xmat + 9 * b);
        Vec3 xipos(d.xipos + 3 * b);
        if (i == model::kArmJoints - 1)  // link 7 with the gripper
          xipos = (m.body_mass[b] * xipos + m.body_mass[gripper] * Vec3(d.xipos + 3 * gripper)) /
                  (m.body_mass[b] + m.body_mass[gripper]);
        worst_position_m = std::max({worst_position_m, (k.r_link_world_m[u] - xpos).norm(),
                                     (k.r_com_world_m[u] - xipos).norm()});
        worst_rotation = std::max(worst_rotation, (k.world_from_link[u] - xmat).cwiseAbs().maxCoeff());
        EXPECT_LT((k.axis_world[u] - Vec3(d.xaxis + 3 * (i + 1))).norm(), 1e-12);  // joint i+1 after the free
      }
      worst_position_m = std::max(worst_position_m, (k.r_tool_world_m - Vec3(d.site_xpos + 3 * tool)).norm());
    }
    // Measured: 4.0e-15 m and 7.8e-16.
    EXPECT_LT(worst_position_m, 1e-12);
    EXPECT_LT(worst_rotation, 1e-12);
  }
}

// mj_jacSite's columns follow qvel, whose free-joint angular velocity MuJoCo 2.2.2 expresses in
// body axes (mj_comPos: a ball or free joint's rotational dofs are the columns of the body's
// xmat); the flight model's v has the same convention, so the columns compare one to one.
TEST(ArmKinematics, ToolJacobianMatchesMujocosJacSite) {
  for (const model::MultibodySceneParams& scene : testing::scenes()) {
    const ServicerArmParams params = servicer_arm_of(scene);
    MujocoModel mujoco(mjcf_of(scene));
    const mjModel& m = mujoco.model();
    const int nv = m.nv;
    const int tool = mj_name2id(&m, mjOBJ_SITE, "tool");
    RandomStream random(20180601, "flight/arm/jacobian");
    double worst = 0.0;
    for (int n = 0; n < kConfigurations; ++n) {
      const testing::Configuration c = testing::random_configuration(random, scene.arm);
      testing::set_state(mujoco, c);
      Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::RowMajor> jacp(3, nv), jacr(3, nv);
      double* p = jacp.data();
      double* r = jacr.data();
      const mjData* d = &mujoco.data();
      plant::multibody::guarded("the tool's Jacobian", [&m, d, p, r, tool] { mj_jacSite(&m, d, p, r, tool); });
      const ToolJacobian jacobian =
          tool_jacobian(arm_kinematics(params, c.r_hub_world_m, c.q_world_from_hub, c.joint_angles_rad));
      worst = std::max({worst, (jacobian.topRows<3>() - jacp.leftCols<kServicerDofs>()).cwiseAbs().maxCoeff(),
                        (jacobian.bottomRows<3>() - jacr.leftCols<kServicerDofs>()).cwiseAbs().maxCoeff()});
      EXPECT_EQ(jacp.rightCols(nv - kServicerDofs).cwiseAbs().maxCoeff(), 0.0);  // the target's dofs
    }
    EXPECT_LT(worst, 1e-10);  // measured: 5.3e-15
  }
}

}  // namespace
}  // namespace chaser::flight::arm
