// The extended task's kinematics against finite differences (no shared code): the Jacobian's rate
// applied to w, the transport theorem of compose, and the Coriolis factorisation's skew symmetry
// that the compliance controller's proof rests on.
//
// Tolerances: central differences at h = 1e-5 s carry a truncation of h^2 |x'''| ~ 1e-10 of the
// quantities' size and a rounding of 1e-16 / h ~ 1e-11: 1e-7 relative leaves a factor of 100.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "core/rotation.hpp"
#include "flight/arm/coriolis_force.hpp"
#include "flight/arm/floating_base_mass_matrix.hpp"
#include "flight/arm/task_space.hpp"
#include "tests/flight/arm/arm_test_support.hpp"

namespace chaser::flight::arm {
namespace {


ArmKinematics kinematics_of(const ServicerArmParams& params, const testing::Configuration& c) {
  return arm_kinematics(params, c.r_hub_world_m, c.q_world_from_hub, c.joint_angles_rad);
}

ServicerVector random_vector(RandomStream& random) {
  ServicerVector w;
  for (int k = 0; k < kServicerDofs; ++k) w(k) = random.normal();
  return w;
}

TEST(TaskSpace, JacobianRateMatchesCentralDifferences) {
  const model::MultibodySceneParams scene = testing::skewed_scene();
  const ServicerArmParams params = servicer_arm_of(scene);
  RandomStream random(20180601, "flight/arm/task-rate");
  const double h_s = 1e-5;
  double worst = 0.0;
  for (int n = 0; n < 20; ++n) {
    const testing::Configuration c = testing::random_configuration(random, scene.arm);
    const ServicerVector w = random_vector(random);
    const TaskVector numeric = (extended_jacobian(kinematics_of(params, testing::moved(c, h_s))) * w -
                                extended_jacobian(kinematics_of(params, testing::moved(c, -h_s))) * w) /
                               (2.0 * h_s);
    const TaskVector analytic = extended_jacobian_rate_times(kinematics_of(params, c), c.velocity, w);
    worst = std::max(worst, (analytic - numeric).cwiseAbs().maxCoeff() / numeric.cwiseAbs().maxCoeff());
  }
  EXPECT_LT(worst, 1e-7);
}

// The extended Jacobian's rows are the hub's twist, the tool's twist (tool_jacobian) and joint 3's rate.
TEST(TaskSpace, ExtendedJacobianRowsAreTheTasksVelocities) {
  const model::MultibodySceneParams scene = testing::skewed_scene();
  const ServicerArmParams params = servicer_arm_of(scene);
  RandomStream random(20180601, "flight/arm/task-rows");
  const testing::Configuration c = testing::random_configuration(random, scene.arm);
  const ArmKinematics k = kinematics_of(params, c);
  const TaskVector x_rate = extended_jacobian(k) * c.velocity;
  EXPECT_LT((x_rate.head<3>() - c.velocity.head<3>()).norm(), 1e-14);
  EXPECT_LT((x_rate.segment<3>(3) - k.world_from_hub * c.velocity.segment<3>(3)).norm(), 1e-14);
  EXPECT_LT((x_rate.segment<6>(6) - tool_jacobian(k) * c.velocity).norm(), 1e-12);
  EXPECT_EQ(x_rate(12), c.velocity(kBaseDofs + kRedundancyJoint));
}

// w' (dH/dt - 2 C(q, v)) w = 0 for every w, and C(q, v) v is the RNEA's force; C is linear in w.
TEST(TaskSpace, CoriolisFactorisationMakesTheMassMatrixRateMinusTwiceItSkew) {
  const model::MultibodySceneParams scene = testing::skewed_scene();
  const ServicerArmParams params = servicer_arm_of(scene);
  RandomStream random(20180601, "flight/arm/skew");
  const double h_s = 1e-5;
  double worst = 0.0, worst_linear = 0.0;
  for (int n = 0; n < 20; ++n) {
    const testing::Configuration c = testing::random_configuration(random, scene.arm);
    const ArmKinematics k = kinematics_of(params, c);
    const ServicerMatrix H_rate = (floating_base_mass_matrix(params, kinematics_of(params, testing::moved(c, h_s))) -
                                   floating_base_mass_matrix(params, kinematics_of(params, testing::moved(c, -h_s)))) /
                                  (2.0 * h_s);
    ServicerMatrix C;
    for (int j = 0; j < kServicerDofs; ++j)
      C.col(j) = coriolis_times(params, k, c.velocity, ServicerVector::Unit(j));
    const ServicerMatrix N = H_rate - 2.0 * C;
    worst = std::max(worst, (N + N.transpose()).cwiseAbs().maxCoeff() / H_rate.cwiseAbs().maxCoeff());
    const ServicerVector w = random_vector(random);
    worst_linear = std::max(worst_linear, (C * w - coriolis_times(params, k, c.velocity, w)).norm() / (C * w).norm());
    EXPECT_LT((C * c.velocity - coriolis_force(params, k, c.velocity)).norm(), 1e-9 * (C * c.velocity).norm());
  }
  EXPECT_LT(worst, 1e-7);
  EXPECT_LT(worst_linear, 1e-12);
}

// A frame moving along a circle inside a tumbling frame, both given as functions of time: compose's
// velocity, acceleration, angular velocity and angular acceleration against central differences of
// its positions and attitudes.
TEST(TaskSpace, ComposeIsTheTransportTheorem) {
  const auto parent_at = [](double t) {
    FrameMotion p;
    const Vec3 w0(0.03, -0.05, 0.07);
    p.r_m = Vec3(1.0 + 0.1 * t, -2.0 + 0.05 * t * t, 0.5);
    p.v_mps = Vec3(0.1, 0.1 * t, 0.0);
    p.a_mps2 = Vec3(0.0, 0.1, 0.0);
    // A turn about a fixed axis, so that the attitude is the exponential of the angle's integral.
    const Vec3 axis = w0.normalized();
    const double rate = w0.norm() + 0.01 * t;
    p.q_world_from_frame = quat_from_rotation_vector(axis * (w0.norm() * t + 0.005 * t * t));
    p.omega_radps = axis * rate;
    p.alpha_radps2 = axis * 0.01;
    return p;
  };
  const auto child_at = [](double t) {
    FrameMotion c;
    c.r_m = Vec3(2.0 * std::cos(0.2 * t), 2.0 * std::sin(0.2 * t), 0.3 * t);
    c.v_mps = Vec3(-0.4 * std::sin(0.2 * t), 0.4 * std::cos(0.2 * t), 0.3);
    c.a_mps2 = Vec3(-0.08 * std::cos(0.2 * t), -0.08 * std::sin(0.2 * t), 0.0);
    const Vec3 axis = Vec3(1.0, 2.0, -1.0).normalized();
    c.q_world_from_frame = quat_from_rotation_vector(axis * 0.04 * t * t);
    c.omega_radps = axis * 0.08 * t;
    c.alpha_radps2 = axis * 0.08;
    return c;
  };
  const double h = 1e-4;
  for (const double t : {0.0, 3.0, 11.0}) {
    const FrameMotion now = compose(parent_at(t), child_at(t));
    const FrameMotion ahead = compose(parent_at(t + h), child_at(t + h));
    const FrameMotion behind = compose(parent_at(t - h), child_at(t - h));
    EXPECT_LT((now.v_mps - (ahead.r_m - behind.r_m) / (2 * h)).norm(), 1e-7);
    EXPECT_LT((now.a_mps2 - (ahead.v_mps - behind.v_mps) / (2 * h)).norm(), 1e-7);
    EXPECT_LT((now.alpha_radps2 - (ahead.omega_radps - behind.omega_radps) / (2 * h)).norm(), 1e-7);
    // omega from the attitudes: q' = (omega; 0) q / 2 in world axes, so omega = 2 (q' q^-1).vec.
    const Quat q_rate = Quat((ahead.q_world_from_frame.coeffs() - behind.q_world_from_frame.coeffs()) / (2 * h));
    const Vec3 omega = 2.0 * (q_rate * now.q_world_from_frame.conjugate()).vec();
    EXPECT_LT((now.omega_radps - omega).norm(), 1e-7);
  }
}

}  // namespace
}  // namespace chaser::flight::arm
