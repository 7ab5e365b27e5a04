// The servicer's angular momentum about its centre of mass (flight/arm/servicer_momentum.hpp)
// against MuJoCo's own (mj_subtreeVel: the hub's subtree, the servicer, about its CoM), and its
// locked inertia against the momentum with the joints still.
#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "flight/arm/servicer_momentum.hpp"
#include "flight/stabilise.hpp"
#include "plant/multibody/mjcf.hpp"
#include "plant/multibody/mujoco_model.hpp"
#include "tests/flight/arm/arm_test_support.hpp"

namespace chaser::flight::arm {
namespace {

using plant::multibody::mjcf_of;
using plant::multibody::MujocoModel;

// Random configurations of both scenes, hub and joints moving (arm_test_support's sizes): the
// momentum and the CoM as MuJoCo computes them, turned into hub axes. MuJoCo sums each body's
// I w + m (r - c) x v from the same compiled masses: a second method. The hub's translation is in
// MuJoCo's velocities and left out of ours, which must not matter. Tolerance: round-off on
// momenta of 350-540 N m s (measured at most 1.6e-15 relative, the CoM to 2.1e-15 m).
TEST(ServicerMomentum, MatchesMujocosSubtreeMomentumAboutTheServicersCentreOfMass) {
  for (const model::MultibodySceneParams& scene : testing::scenes()) {
    MujocoModel mujoco(mjcf_of(scene));
    const ServicerArmParams params = testing::servicer_arm_as_compiled(scene, mujoco);
    const int hub = mj_name2id(&mujoco.model(), mjOBJ_BODY, "hub");
    ASSERT_GE(hub, 0);
    RandomStream random(20181130, "flight/arm/servicer_momentum");
    for (int n = 0; n < 20; ++n) {
      const testing::Configuration c = testing::random_configuration(random, scene.arm);
      testing::set_state(mujoco, c);
      mj_subtreeVel(&mujoco.model(), &mujoco.data());
      const mjData& d = mujoco.data();
      const Mat3 hub_from_world = c.q_world_from_hub.toRotationMatrix().transpose();
      const auto u = static_cast<std::size_t>(3 * hub);
      const Vec3 angmom_hub = hub_from_world * Vec3(d.subtree_angmom[u], d.subtree_angmom[u + 1], d.subtree_angmom[u + 2]);
      const Vec3 com_hub =
          hub_from_world * (Vec3(d.subtree_com[u], d.subtree_com[u + 1], d.subtree_com[u + 2]) - c.r_hub_world_m);
      const ServicerMomentum m = servicer_momentum(params, c.joint_angles_rad, c.velocity.tail<model::kArmJoints>(),
                                                   c.velocity.segment<3>(3));
      EXPECT_LT((m.angular_momentum_Nms - angmom_hub).norm(), 1e-12 * (1.0 + angmom_hub.norm())) << n;
      EXPECT_LT((m.com_hub_m - com_hub).norm(), 1e-12 * (1.0 + com_hub.norm())) << n;
    }
  }
}

// Joints still, the servicer turns as one rigid body: its momentum is the locked inertia times the
// hub's rate, and that inertia is symmetric positive definite.
TEST(ServicerMomentum, WithTheJointsStillTheMomentumIsTheLockedInertiaTimesTheRate) {
  const model::MultibodySceneParams scene = testing::default_scene();
  const ServicerArmParams params = servicer_arm_of(scene);
  RandomStream random(20181201, "flight/arm/servicer_momentum/locked");
  for (int n = 0; n < 10; ++n) {
    const testing::Configuration c = testing::random_configuration(random, scene.arm);
    const Vec3 omega = c.velocity.segment<3>(3);
    const ServicerMomentum m = servicer_momentum(params, c.joint_angles_rad, JointVector::Zero(), omega);
    EXPECT_LT((m.angular_momentum_Nms - m.locked_inertia_kgm2 * omega).norm(), 1e-12 * m.angular_momentum_Nms.norm());
    EXPECT_EQ((m.locked_inertia_kgm2 - m.locked_inertia_kgm2.transpose()).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<Mat3>(m.locked_inertia_kgm2).eigenvalues().minCoeff(), 0.0);
  }
}

// The locked inertia and the CoM by a second method: the stabilisation's composite inertia
// (flight/stabilise.hpp), which sums hub and links by the parallel-axis theorem, with a massless
// target. Ours moves the mass matrix's hub block from the hub's origin instead. Tolerance: round-off
// on inertias of ~2e3 kg m^2.
TEST(ServicerMomentum, LockedInertiaAndCentreAreTheParallelAxisSumsOfHubAndLinks) {
  const model::MultibodySceneParams scene = testing::default_scene();
  const ServicerArmParams params = servicer_arm_of(scene);
  RandomStream random(20181202, "flight/arm/servicer_momentum/parallel_axis");
  for (int n = 0; n < 10; ++n) {
    const testing::Configuration c = testing::random_configuration(random, scene.arm);
    const ServicerMomentum m = servicer_momentum(params, c.joint_angles_rad, JointVector::Zero(), Vec3::Zero());
    const CompositeInertia summed = composite_inertia(params, c.joint_angles_rad, GraspedTarget{});
    EXPECT_LT((m.locked_inertia_kgm2 - summed.inertia_kgm2).norm(), 1e-12 * summed.inertia_kgm2.norm()) << n;
    EXPECT_LT((m.com_hub_m - summed.com_hub_m).norm(), 1e-12) << n;
  }
}

}  // namespace
}  // namespace chaser::flight::arm
