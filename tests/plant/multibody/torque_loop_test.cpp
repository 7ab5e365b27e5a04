// The joints' inner torque loops (model/arm.hpp's torque_loop_bandwidth_radps): the torque each
// drive applies follows its demand through 1 / (s / w + 1), against the lag's closed-form step
// response. RK4 at the scene's 1 ms follows it to (w h)^5 / 120 per step: at 300 rad/s the largest
// error over the response is 3.2e-5 of the step (computed from RK4's amplification factor), so the
// bound 5e-5 of the step is RK4's own and a wrong time constant (1 % off gives 3.7e-3) fails it.
#include <cmath>

#include <gtest/gtest.h>

#include "model/arm.hpp"
#include "plant/multibody/mjcf.hpp"
#include "plant/multibody/mujoco_model.hpp"

namespace chaser::plant::multibody {
namespace {

TEST(TorqueLoop, TheAppliedTorqueFollowsTheDemandThroughAFirstOrderLag) {
  model::MultibodySceneParams scene;
  const double w_radps = scene.arm.torque_loop_bandwidth_radps;
  ASSERT_EQ(w_radps, 300.0);
  MujocoModel model(mjcf_of(scene));
  const mjModel& m = model.model();
  const int motor = model.actuator("motor4");
  EXPECT_EQ(m.actuator_dyntype[motor], mjDYN_FILTER);
  EXPECT_EQ(m.actuator_dynprm[motor * mjNDYN], 1.0 / w_radps);
  const int act = motor - (m.nu - m.na);  // MuJoCo 2.2: stateful actuators last
  const double step_Nm = 20.0;
  model.data().ctrl[motor] = step_Nm;
  double largest_error = 0.0;
  for (int k = 1; k <= 50; ++k) {  // 50 ms: 15 time constants
    model.step();
    const double t_s = model.data().time;
    const double expected_Nm = step_Nm * (1.0 - std::exp(-w_radps * t_s));
    largest_error = std::max(largest_error, std::abs(model.data().act[act] - expected_Nm));
  }
  EXPECT_LT(largest_error, 5e-5 * step_Nm);
  EXPECT_NEAR(model.data().act[act], step_Nm, 1e-5);
  // Every other drive has no demand and applies nothing.
  for (int j = 1; j <= model::kArmJoints; ++j) {
    if (j == 4) continue;
    EXPECT_EQ(model.data().act[model.actuator(("motor" + std::to_string(j)).c_str()) - (m.nu - m.na)], 0.0);
  }
}

TEST(TorqueLoop, TheDemandIsClampedAtTheDrivesMomentaryLimitSoTheTorqueNeverExceedsIt) {
  model::MultibodySceneParams scene;
  MujocoModel model(mjcf_of(scene));
  const int motor = model.actuator("motor2");
  const int act = motor - (model.model().nu - model.model().na);
  model.data().ctrl[motor] = -10.0 * scene.arm.torque_momentary_Nm;
  for (int k = 0; k < 100; ++k) {
    model.step();
    ASSERT_GE(model.data().act[act], -scene.arm.torque_momentary_Nm * (1.0 + 1e-12));
  }
  EXPECT_NEAR(model.data().act[act], -scene.arm.torque_momentary_Nm, 1e-6 * scene.arm.torque_momentary_Nm);
}

}  // namespace
}  // namespace chaser::plant::multibody
