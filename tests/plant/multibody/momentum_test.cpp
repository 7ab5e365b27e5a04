// With the joints driven and no external force, the scene's linear and angular momentum are
// conserved (Newton's third law: joint torques and joint friction are internal). MuJoCo's RK4
// conserves them only to its truncation error: the test bounds the drift and checks that it falls
// with the step as a high-order method's does, which a wrong mass matrix, a torque applied to one
// body only or a lost term would break (the drift would then not fall with the step).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "model/arm.hpp"
#include "plant/multibody/mjcf.hpp"
#include "plant/multibody/mujoco_model.hpp"
#include "tests/plant/multibody/moving_scene.hpp"

namespace chaser::plant::multibody {
namespace {

struct Drift {
  double linear_kgmps = 0;
  double angular_kgm2ps = 0;
  double largest_joint_angle_rad = 0;
};

// The moving scene (moving_scene.hpp) for 1 s, its joints driven (no joint reaches its limit: a
// limit is a stiff constraint whose contact spoils any integrator's order).
Drift momentum_drift_over_one_second(double timestep_s, double friction_Nm) {
  model::MultibodySceneParams scene;
  scene.timestep_s = timestep_s;
  for (auto& link : scene.arm.links) link.friction_Nm = friction_Nm;
  MujocoModel model = moving_scene(scene);
  mjData& d = model.data();
  const int joint1 = model.model().jnt_qposadr[model.joint("joint1")];
  const Momentum p0 = model.momentum();
  Drift drift;
  const int steps = static_cast<int>(std::lround(1.0 / timestep_s));
  for (int k = 0; k < steps; ++k) {
    drive_joints(model);
    model.step();
    for (int j = 0; j < model::kArmJoints; ++j)
      drift.largest_joint_angle_rad = std::max(drift.largest_joint_angle_rad, std::abs(d.qpos[joint1 + j]));
  }
  const Momentum p1 = model.momentum();
  drift.linear_kgmps = (p1.linear_kgmps - p0.linear_kgmps).norm();
  drift.angular_kgm2ps = (p1.angular_kgm2ps - p0.angular_kgm2ps).norm();
  return drift;
}

TEST(Momentum, ConservedWhileTheArmMovesWithItsFriction) {
  // Measured: 2.6e-11 kg m/s and 4.5e-9 kg m^2/s at 1 ms (relative 3e-13 and 8e-13); the bounds
  // leave a factor of 4 or more for another libm.
  const Drift drift = momentum_drift_over_one_second(1e-3, model::default_arm().links[0].friction_Nm);
  EXPECT_LT(drift.largest_joint_angle_rad, 1.0);  // inside every limit (+/-120 deg and more)
  EXPECT_LT(drift.linear_kgmps, 2e-10);
  EXPECT_LT(drift.angular_kgm2ps, 2e-8);
}

TEST(Momentum, DriftFallsWithTheStepAsAHighOrderMethods) {
  // Without friction (dry friction sticks and slips: not smooth) the drift halving the step falls
  // 7.9x for both momenta (1 ms: 2.6e-9, 7.6e-9; 0.5 ms: 3.2e-10, 9.7e-10): third order in this
  // quantity for MuJoCo 2.2.2's RK4 with its step-held controls. A first-order error (a force not
  // balanced by its reaction) would fall 2x at best.
  const Drift coarse = momentum_drift_over_one_second(1e-3, 0.0);
  const Drift fine = momentum_drift_over_one_second(5e-4, 0.0);
  EXPECT_GT(coarse.linear_kgmps / fine.linear_kgmps, 6.0);
  EXPECT_GT(coarse.angular_kgm2ps / fine.angular_kgm2ps, 6.0);
  EXPECT_LT(coarse.angular_kgm2ps, 3e-8);
}

}  // namespace
}  // namespace chaser::plant::multibody
