// The multibody hub is the rigid chaser less its stowed arm: put back together they are the
// chaser, by the parallel-axis sums and by MuJoCo's own composite; an arm the chaser cannot carry
// is refused naming the key.
#include "model/hub_mass_properties.hpp"

#include <gtest/gtest.h>

#include "plant/multibody/mjcf.hpp"
#include "plant/multibody/mujoco_model.hpp"

namespace chaser::plant {

using model::BodyMassProperties;
namespace {

model::SpacecraftParams chaser_with_arm() {
  model::SpacecraftParams c;
  c.mass_kg = 1700.0;
  c.com_body_m = Vec3(0.12, 0.05, -0.03);
  c.inertia_kgm2 << 2100.0, 35.0, -20.0, 35.0, 1950.0, 30.0, -20.0, 30.0, 2400.0;
  c.arm = model::default_arm();
  return c;
}

Mat3 skew(const Vec3& v) {
  Mat3 s;
  s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return s;
}

TEST(HubMassProperties, HubAndStowedArmPutBackTogetherAreTheChaser) {
  const model::SpacecraftParams c = chaser_with_arm();
  const BodyMassProperties hub = hub_mass_properties(c, *c.arm);
  EXPECT_FALSE(hub_problem(c, hub));
  std::array<BodyMassProperties, model::kArmJoints + 2> bodies;
  const auto arm = arm_bodies(*c.arm, c.arm->stowed_rad);
  std::copy(arm.begin(), arm.end(), bodies.begin());
  bodies.back() = hub;
  const BodyMassProperties whole = composite(bodies);
  EXPECT_NEAR(hub.mass_kg, c.mass_kg - 80.0, 1e-12 * c.mass_kg);
  EXPECT_NEAR(whole.mass_kg, c.mass_kg, 1e-12 * c.mass_kg);
  EXPECT_LT((whole.com_body_m - c.com_body_m).norm(), 1e-12 * c.com_body_m.norm());
  EXPECT_LT((whole.inertia_kgm2 - c.inertia_kgm2).norm(), 1e-12 * c.inertia_kgm2.norm());
}

// MuJoCo's joint-space mass matrix at the stowed angles: the hub's free-joint block is the
// composite's spatial inertia about the hub's CoM (hub frame = world at rest, qvel linear in world
// axes, angular in body axes): [M 1, -M [d]x; M [d]x, I_c + M (|d|^2 1 - d d^T)], d = c - c_hub.
// To the compiler's diagonalisation of the hub's full inertia (4e-8 of it, docs/dynamics.md).
TEST(HubMassProperties, MujocosCompositeAtTheStowedAnglesIsTheChaser) {
  const model::SpacecraftParams c = chaser_with_arm();
  const BodyMassProperties hub = hub_mass_properties(c, *c.arm);
  model::MultibodySceneParams scene;
  scene.hub_mass_kg = hub.mass_kg;
  scene.hub_inertia_kgm2 = hub.inertia_kgm2;
  scene.hub_com_body_m = hub.com_body_m;
  scene.arm = *c.arm;
  multibody::MujocoModel world(multibody::mjcf_of(scene));
  const int q1 = world.model().jnt_qposadr[world.joint("joint1")];
  for (int j = 0; j < model::kArmJoints; ++j) world.data().qpos[q1 + j] = c.arm->stowed_rad[static_cast<std::size_t>(j)];
  world.forward();
  const Eigen::MatrixXd M = world.mass_matrix();
  const Vec3 d = c.com_body_m - hub.com_body_m;
  Mat6 expected;
  expected << c.mass_kg * Mat3::Identity(), -c.mass_kg * skew(d), c.mass_kg * skew(d),
      c.inertia_kgm2 + c.mass_kg * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
  Mat6 block = M.topLeftCorner<6, 6>();
  // (The joints' armature adds to their own diagonal entries only, not to this block.)
  EXPECT_LT((block - expected).norm(), 1e-7 * expected.norm()) << block << "\n\n" << expected;
}

TEST(HubMassProperties, AnArmTheChaserCannotCarryIsRefusedNamingTheKey) {
  model::SpacecraftParams c = chaser_with_arm();
  c.mass_kg = 60.0;  // the arm alone is 80 kg
  const auto heavy = hub_problem(c, hub_mass_properties(c, *c.arm));
  ASSERT_TRUE(heavy);
  EXPECT_NE(heavy->find("chaser.mass_kg"), std::string::npos) << *heavy;
  c = chaser_with_arm();
  c.inertia_kgm2 = Vec3(60.0, 60.0, 60.0).asDiagonal();  // less than the stowed arm's own
  const auto light = hub_problem(c, hub_mass_properties(c, *c.arm));
  ASSERT_TRUE(light);
  EXPECT_NE(light->find("chaser.inertia_kgm2"), std::string::npos) << *light;
}

}  // namespace
}  // namespace chaser::plant
