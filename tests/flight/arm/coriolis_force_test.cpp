// The Coriolis and centrifugal force C(q, v) v (RNEA) against MuJoCo's qfrc_bias (gravity off in
// the scene) and against the mass matrix it must agree with: the power balance dT/dt = v' tau of
// T = v' H v / 2 and H dv/dt + C v = tau gives v' C v = v' (dH/dt) v / 2, with dH/dt by central
// differences of the CRBA's H along the motion (no MuJoCo in that one).
//
// Tolerances: MuJoCo 1e-9 relative to the largest entry of qfrc_bias (both are the RNEA on the
// same numbers, to rounding; the hub's inertia as MuJoCo compiled it, see
// floating_base_mass_matrix_test.cpp; measured 1.5e-14); the energy identity 1e-7 relative to |v|^2 max|dH/dt| (the central
// difference's truncation, h^2 = 1e-10 relative, and its rounding, 1e-16 / h = 1e-11).
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "core/rotation.hpp"
#include "flight/arm/coriolis_force.hpp"
#include "flight/arm/floating_base_mass_matrix.hpp"
#include "plant/multibody/mjcf.hpp"
#include "plant/multibody/mujoco_model.hpp"
#include "tests/flight/arm/arm_test_support.hpp"

namespace chaser::flight::arm {
namespace {

using plant::multibody::MujocoModel;
using plant::multibody::mjcf_of;

TEST(CoriolisForce, MatchesMujocosBiasForce) {
  for (const model::MultibodySceneParams& scene : testing::scenes()) {
    MujocoModel mujoco(mjcf_of(scene));
    const ServicerArmParams params = testing::servicer_arm_as_compiled(scene, mujoco);
    RandomStream random(20180601, "flight/arm/coriolis");
    double worst_relative = 0.0;
    for (int n = 0; n < 20; ++n) {
      const testing::Configuration c = testing::random_configuration(random, scene.arm);
      testing::set_state(mujoco, c);
      const ServicerVector bias = Eigen::Map<const ServicerVector>(mujoco.data().qfrc_bias);
      const ServicerVector force = coriolis_force(
          params, arm_kinematics(params, c.r_hub_world_m, c.q_world_from_hub, c.joint_angles_rad), c.velocity);
      worst_relative = std::max(worst_relative, (force - bias).cwiseAbs().maxCoeff() / bias.cwiseAbs().maxCoeff());
    }
    EXPECT_LT(worst_relative, 1e-9);  // measured: 1.5e-14
  }
}


TEST(CoriolisForce, DoesHalfTheWorkOfTheMassMatrixsRate) {
  const model::MultibodySceneParams scene = testing::skewed_scene();
  const ServicerArmParams params = servicer_arm_of(scene);
  const auto mass_matrix = [&params](const testing::Configuration& c) {
    const ArmKinematics k = arm_kinematics(params, c.r_hub_world_m, c.q_world_from_hub, c.joint_angles_rad);
    return floating_base_mass_matrix(params, k);
  };
  RandomStream random(20180601, "flight/arm/energy");
  const double h_s = 1e-5;
  double worst_relative = 0.0;
  for (int n = 0; n < 20; ++n) {
    const testing::Configuration c = testing::random_configuration(random, scene.arm);
    const ServicerMatrix H_rate = (mass_matrix(testing::moved(c, h_s)) - mass_matrix(testing::moved(c, -h_s))) / (2.0 * h_s);
    const ServicerVector force = coriolis_force(
        params, arm_kinematics(params, c.r_hub_world_m, c.q_world_from_hub, c.joint_angles_rad), c.velocity);
    const double scale = c.velocity.squaredNorm() * H_rate.cwiseAbs().maxCoeff();
    worst_relative = std::max(worst_relative,
                              std::abs(c.velocity.dot(force) - 0.5 * c.velocity.dot(H_rate * c.velocity)) / scale);
  }
  EXPECT_LT(worst_relative, 1e-7);  // measured: 3.4e-11
}

}  // namespace
}  // namespace chaser::flight::arm
