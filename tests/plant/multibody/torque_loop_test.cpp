// The joints' inner torque loops (model/arm.hpp's torque_loop_bandwidth_radps): the torque each
// drive applies follows its demand through 1 / (s / w + 1).
//
// Two references. The activation's equation is linear and decoupled from the bodies, so MuJoCo's
// RK4 at step h advances it exactly by the classical RK4 recurrence with the demand held: after k
// steps of a demand u, act = u (1 - R^k) with R = 1 - z + z^2/2 - z^3/6 + z^4/24, z = w h (to
// rounding). And the lag's closed form u (1 - exp(-w t)) differs from that recurrence by at most
// max_k |R^k - exp(-k z)| u, RK4's own error, computed here from R (3.2e-5 of the step at
// 300 rad/s and 1 ms); a time constant 1 % off would be 3.7e-3 of the step away.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "model/arm.hpp"
#include "plant/multibody/mjcf.hpp"
#include "plant/multibody/mujoco_model.hpp"

namespace chaser::plant::multibody {
namespace {

double rk4_decay_factor(double z) { return 1.0 - z + z * z / 2.0 - z * z * z / 6.0 + z * z * z * z / 24.0; }

TEST(TorqueLoop, TheAppliedTorqueFollowsTheDemandThroughAFirstOrderLag) {
  model::MultibodySceneParams scene;
  const double w_radps = scene.arm.torque_loop_bandwidth_radps;
  MujocoModel model(mjcf_of(scene));
  const mjModel& m = model.model();
  const int motor = model.actuator("motor4");
  EXPECT_EQ(m.actuator_dyntype[motor], mjDYN_FILTER);
  EXPECT_EQ(m.actuator_dynprm[motor * mjNDYN], 1.0 / w_radps);
  const int act = activation_index(m, motor);
  const double step_Nm = 20.0, z = w_radps * scene.timestep_s, R = rk4_decay_factor(z);
  model.data().ctrl[motor] = step_Nm;
  double rk4_bound = 0.0, largest_from_recurrence = 0.0, largest_from_closed_form = 0.0;
  double decay = 1.0;  // R^k
  for (int k = 1; k <= 50; ++k) {  // 50 ms: 15 time constants
    model.step();
    decay *= R;
    const double applied_Nm = model.data().act[act];
    rk4_bound = std::max(rk4_bound, std::abs(decay - std::exp(-k * z)));
    largest_from_recurrence = std::max(largest_from_recurrence, std::abs(applied_Nm - step_Nm * (1.0 - decay)));
    largest_from_closed_form =
        std::max(largest_from_closed_form, std::abs(applied_Nm - step_Nm * (1.0 - std::exp(-w_radps * model.data().time))));
  }
  EXPECT_LT(largest_from_recurrence, 1e-12 * step_Nm);
  EXPECT_LE(largest_from_closed_form, (rk4_bound + 1e-12) * step_Nm);
  EXPECT_LT(rk4_bound, 1e-4);  // the lag is resolved by the step: w h = 0.3 at the defaults
  // Every other drive has no demand and applies nothing.
  for (int j = 1; j <= model::kArmJoints; ++j) {
    if (j == 4) continue;
    EXPECT_EQ(model.data().act[activation_index(m, model.actuator(("motor" + std::to_string(j)).c_str()))], 0.0);
  }
}

TEST(TorqueLoop, TheDemandIsClampedAtTheDrivesMomentaryLimitSoTheTorqueNeverExceedsIt) {
  model::MultibodySceneParams scene;
  MujocoModel model(mjcf_of(scene));
  const int motor = model.actuator("motor2");
  const int act = activation_index(model.model(), motor);
  model.data().ctrl[motor] = -10.0 * scene.arm.torque_momentary_Nm;
  for (int k = 0; k < 100; ++k) {
    model.step();
    ASSERT_GE(model.data().act[act], -scene.arm.torque_momentary_Nm * (1.0 + 1e-12));
  }
  EXPECT_NEAR(model.data().act[act], -scene.arm.torque_momentary_Nm, 1e-6 * scene.arm.torque_momentary_Nm);
}

// With the jaws' servos in the scene (they have no state and come first), the index still finds
// each joint's activation: a demand on motor1 moves the first activation and nothing else.
TEST(TorqueLoop, EachJointsActivationIsFoundWithTheJawsInTheScene) {
  model::MultibodySceneParams scene;
  scene.grasp_contact = true;
  MujocoModel model(mjcf_of(scene));
  const mjModel& m = model.model();
  ASSERT_EQ(m.nu, model::kArmJoints + 2);
  ASSERT_EQ(m.na, model::kArmJoints);
  const int motor1 = model.actuator("motor1");
  EXPECT_EQ(activation_index(m, motor1), 0);
  model.data().ctrl[motor1] = 5.0;
  model.step();
  EXPECT_GT(model.data().act[0], 0.0);
  for (int a = 1; a < m.na; ++a) EXPECT_EQ(model.data().act[a], 0.0) << a;
}

}  // namespace
}  // namespace chaser::plant::multibody
