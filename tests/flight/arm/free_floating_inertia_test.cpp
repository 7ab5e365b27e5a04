// The free-floating joint inertia H* of the servicer with a grasped target (flight/arm/free_floating_inertia.hpp)
// against MuJoCo's model of the same scene, where the target is a body of its own on a free joint
// and the grasp a kinematic constraint, and against the momentum it must conserve.
#include <cmath>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "flight/arm/free_floating_inertia.hpp"
#include "flight/arm/floating_base_mass_matrix.hpp"
#include "plant/multibody/mjcf.hpp"
#include "tests/flight/arm/arm_test_support.hpp"

namespace chaser::flight::arm {
namespace {

using plant::multibody::mjcf_of;
using plant::multibody::MujocoModel;

// ENVISAT's size of target: 7,828 kg, a full tensor.
model::MultibodySceneParams scene_with_target(model::MultibodySceneParams scene) {
  scene.target_mass_kg = 7828.0;
  scene.target_inertia_kgm2 << 17023.0, 397.0, -2171.0, 397.0, 124826.0, 344.0, -2171.0, 344.0, 129112.0;
  return scene;
}

struct Grasp {
  Vec3 grasp_point_target_m;
  Quat q_target_from_tool;
};

// Puts MuJoCo's target where the tool holds it: its frame at q_world_from_tool q_target_from_tool^-1,
// its CoM the tool point less the grasp point turned into world axes.
void place_target(MujocoModel& mujoco, const ArmKinematics& k, const Grasp& g) {
  const mjModel& m = mujoco.model();
  mjData& d = mujoco.data();
  const int target = mujoco.body("target");
  const int qpos = m.jnt_qposadr[m.body_jntadr[target]];
  const Quat q_world_from_tool(k.world_from_link[model::kArmJoints - 1]);
  const Quat q_world_from_target = (q_world_from_tool * g.q_target_from_tool.conjugate()).normalized();
  const Vec3 r_target_m = k.r_tool_world_m - q_world_from_target * g.grasp_point_target_m;
  for (int i = 0; i < 3; ++i) d.qpos[qpos + i] = r_target_m(i);
  d.qpos[qpos + 3] = q_world_from_target.w();
  d.qpos[qpos + 4] = q_world_from_target.x();
  d.qpos[qpos + 5] = q_world_from_target.y();
  d.qpos[qpos + 6] = q_world_from_target.z();
  mujoco.forward();
}

// MuJoCo's H*: the 19 x 19 mass matrix restricted to the velocities that keep the target welded to
// link 7 (v = N z, z the hub's and the joints' 13: the target's twist from J_t v_t = -J_s z, the
// rows the relative motion of link 7 and the target at the target's CoM), then the hub's 6 eliminated.
JointMatrix mujoco_free_floating_inertia(const MujocoModel& mujoco) {
  const mjModel& m = mujoco.model();
  const mjData& d = mujoco.data();
  const int nv = m.nv, target = mujoco.body("target"), link7 = mujoco.body("link7");
  Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::RowMajor> p7(3, nv), r7(3, nv), pt(3, nv), rt(3, nv);
  const double* point = d.xipos + 3 * target;
  mj_jac(&m, &d, p7.data(), r7.data(), point, link7);
  mj_jac(&m, &d, pt.data(), rt.data(), point, target);
  Eigen::MatrixXd relative(6, nv);
  relative << p7 - pt, r7 - rt;
  const int target_dof = m.jnt_dofadr[m.body_jntadr[target]];
  Eigen::MatrixXd N = Eigen::MatrixXd::Zero(nv, kServicerDofs);
  N.topRows(kServicerDofs).setIdentity();
  N.middleRows(target_dof, 6) =
      -relative.middleCols(target_dof, 6).fullPivLu().solve(relative.leftCols(kServicerDofs));
  const Eigen::MatrixXd full = mujoco.mass_matrix();
  const ServicerMatrix constrained = N.transpose() * full * N;
  return free_floating_joint_inertia(constrained);
}

TEST(FreeFloatingInertia, MatchesMujocosWeldedSceneAtRandomConfigurationsAndGrasps) {
  for (const model::MultibodySceneParams& base_scene : testing::scenes()) {
    const model::MultibodySceneParams scene = scene_with_target(base_scene);
    MujocoModel mujoco(mjcf_of(scene));
    const ServicerArmParams servicer = testing::servicer_arm_as_compiled(scene, mujoco);
    RandomStream random(20180602, "flight/arm/free_floating");
    double worst_relative = 0.0;
    for (int n = 0; n < 10; ++n) {
      const testing::Configuration c = testing::random_configuration(random, scene.arm);
      testing::set_state(mujoco, c);
      const Grasp g{.grasp_point_target_m = Vec3(random.uniform(-2.0, 2.0), random.uniform(-2.0, 2.0), random.uniform(-2.0, 2.0)),
                    .q_target_from_tool = Quat(random.normal(), random.normal(), random.normal(), random.normal()).normalized()};
      const ArmKinematics k = arm_kinematics(servicer, c.r_hub_world_m, c.q_world_from_hub, c.joint_angles_rad);
      place_target(mujoco, k, g);
      // MuJoCo's compiler diagonalises the target's tensor: the flight model takes what it flies.
      const mjModel& m = mujoco.model();
      const int t = mujoco.body("target");
      const Mat3 principal = Quat(m.body_iquat[4 * t], m.body_iquat[4 * t + 1], m.body_iquat[4 * t + 2], m.body_iquat[4 * t + 3])
                                 .toRotationMatrix();
      const Mat3 inertia = principal * Vec3(m.body_inertia + 3 * t).asDiagonal() * principal.transpose();
      const ServicerArmParams held =
          with_payload(servicer, grasped_payload(servicer, m.body_mass[t], inertia, g.grasp_point_target_m, g.q_target_from_tool));
      // The kinematics of the chain that holds the payload (link 7's CoM moves with it).
      const JointMatrix flight = free_floating_joint_inertia(
          floating_base_mass_matrix(held, arm_kinematics(held, c.r_hub_world_m, c.q_world_from_hub, c.joint_angles_rad)));
      const JointMatrix reference = mujoco_free_floating_inertia(mujoco);
      worst_relative = std::max(worst_relative, (flight - reference).cwiseAbs().maxCoeff() / reference.cwiseAbs().maxCoeff());
      EXPECT_EQ(Eigen::LLT<JointMatrix>(flight).info(), Eigen::Success);
    }
    EXPECT_LT(worst_relative, 1e-10);  // measured: 2.1e-14 (rounding through the 6 x 6 solves)
  }
}

// From rest, with no force on the hub, joint rates q' carry the hub along so that the chain's
// momentum stays zero: v_b = -H_bb^-1 H_bq q', and the kinetic energy of the whole motion is
// q'^T H* q' / 2 (the definition's two halves, checked on the full 13-vector).
TEST(FreeFloatingInertia, IsTheKineticEnergyOfTheJointsWithTheHubFloatingAtZeroMomentum) {
  const model::MultibodySceneParams scene = scene_with_target(testing::default_scene());
  const ServicerArmParams servicer = servicer_arm_of(scene);
  const ServicerArmParams held = with_payload(
      servicer, grasped_payload(servicer, scene.target_mass_kg, scene.target_inertia_kgm2, Vec3(0.3, 1.2, -0.8),
                                Quat(0.9, 0.1, -0.3, 0.2).normalized()));
  RandomStream random(20180603, "flight/arm/free_floating_energy");
  const testing::Configuration c = testing::random_configuration(random, scene.arm);
  const ServicerMatrix H = floating_base_mass_matrix(held, arm_kinematics(held, c.r_hub_world_m, c.q_world_from_hub, c.joint_angles_rad));
  const JointMatrix h_star = free_floating_joint_inertia(H);
  const JointVector rates = c.velocity.tail<model::kArmJoints>();
  ServicerVector v;
  v.head<kBaseDofs>() = -H.topLeftCorner<kBaseDofs, kBaseDofs>().ldlt().solve(H.topRightCorner<kBaseDofs, model::kArmJoints>() * rates);
  v.tail<model::kArmJoints>() = rates;
  EXPECT_LT((H * v).head<kBaseDofs>().norm(), 1e-9 * (H * v).norm());  // the hub's momentum row: zero
  EXPECT_NEAR(v.dot(H * v), rates.dot(h_star * rates), 1e-10 * v.dot(H * v));
  // And the payload adds its mass: the chain's total is the servicer's plus the target's.
  EXPECT_NEAR(H(0, 0), floating_base_mass_matrix(servicer, arm_kinematics(servicer, c.r_hub_world_m, c.q_world_from_hub,
                                                                              c.joint_angles_rad))(0, 0) + scene.target_mass_kg, 1e-9);
}

}  // namespace
}  // namespace chaser::flight::arm
