#include "plant/rigid_body.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/rotation.hpp"
#include "plant/propagator.hpp"

namespace chaser::plant {
namespace {

// Attitude-only dynamics: no gravity (mu = 0, n = 0), gravity gradient off.
DynamicsParams attitude_params(const Mat3& inertia) {
  DynamicsParams p;
  p.inertia_kgm2 = inertia;
  p.inertia_inv = inertia.inverse();
  return p;
}

RigidState spinning_body(const Vec3& omega_body_radps) {
  RigidState x;
  x.q_inertial_from_body = quat_from_rotation_vector(Vec3(0.3, -0.5, 0.2));
  x.omega_body_radps = omega_body_radps;
  x.mass_kg = 2500.0;
  return x;
}

// Euler's equations by hand: I = diag(1, 2, 3), omega = (1, 1, 1): I omega = (1, 2, 3),
// omega x I omega = (1, -2, 1), so with no torque omega' = -I^-1 (1, -2, 1) = (-1, 1, -1/3).
TEST(RigidBody, EulerEquationsByHand) {
  const Mat3 inertia = Vec3(1.0, 2.0, 3.0).asDiagonal();
  const Vec3 zero_torque = euler_angular_acceleration_body(inertia, inertia.inverse(), Vec3(1, 1, 1), Vec3::Zero());
  EXPECT_LT((zero_torque - Vec3(-1.0, 1.0, -1.0 / 3.0)).norm(), 1e-15);
  const Vec3 at_rest = euler_angular_acceleration_body(inertia, inertia.inverse(), Vec3::Zero(), Vec3(2, 4, 6));
  EXPECT_LT((at_rest - Vec3(2.0, 2.0, 2.0)).norm(), 1e-15);
}

// q' = 1/2 q (x) (0, omega) is the derivative of q(t) = q0 (x) exp(omega t) at t = 0 (body-axes
// rate). Central difference with dt = 1e-5 s: truncation ~dt^2 |omega|^3 ~ 1e-10, round-off ~1e-11.
TEST(RigidBody, QuaternionKinematicsIsBodyRateDerivative) {
  const Quat q0 = quat_from_rotation_vector(Vec3(0.4, 1.1, -0.7));
  const Vec3 omega(0.3, -0.8, 0.5);
  const double dt = 1e-5;
  const Eigen::Vector4d numeric = ((q0 * quat_from_rotation_vector(omega * dt)).coeffs() -
                                   (q0 * quat_from_rotation_vector(-omega * dt)).coeffs()) /
                                  (2.0 * dt);
  EXPECT_LT((quat_derivative(q0, omega) - numeric).norm(), 1e-9);
}

// Test 3. Torque-free asymmetric body tumbling at ~0.05 rad/s on every axis: the inertial angular
// momentum and the rotational energy are invariants of the exact motion. Over 1000 s in 0.1 s
// pieces (one RK4 step each) they drift by RK4 truncation only, whose phase error is
// (|omega| h)^5 / 120 ~ 4e-13 per step; the invariants move far less (measured 4e-12 relative for
// the momentum, 2e-14 for the energy): bound 1e-10. The quaternion is re-normalised every piece,
// so its norm stays 1 to round-off (bound 1e-12, brief).
TEST(RigidBody, TorqueFreeMotionConservesMomentumAndEnergy) {
  const Mat3 inertia = Vec3(2000.0, 2500.0, 3000.0).asDiagonal();
  const DynamicsParams p = attitude_params(inertia);
  RigidState x = spinning_body(Vec3(0.05, -0.04, 0.06));
  const Vec3 h0 = angular_momentum_inertial(inertia, x.q_inertial_from_body, x.omega_body_radps);
  const double e0 = rotational_energy(inertia, x.omega_body_radps);
  double worst_norm_error = 0.0;
  for (int k = 0; k < 10000; ++k) {
    propagate_piece(p, x, 0.1 * k, 0.1, PieceInput{});
    worst_norm_error = std::max(worst_norm_error, std::abs(x.q_inertial_from_body.norm() - 1.0));
  }
  const Vec3 h1 = angular_momentum_inertial(inertia, x.q_inertial_from_body, x.omega_body_radps);
  EXPECT_LT((h1 - h0).norm() / h0.norm(), 1e-10);
  EXPECT_LT(std::abs(rotational_energy(inertia, x.omega_body_radps) - e0) / e0, 1e-10);
  EXPECT_LT(worst_norm_error, 1e-12);
  EXPECT_GT((x.omega_body_radps - Vec3(0.05, -0.04, 0.06)).norm(), 1e-3);  // it did tumble
}

// Torque-free axisymmetric body (I1 = I2): the body rate cones about the symmetry axis at
// lambda = (I3 - I1) / I1 * omega3, omega1 + i omega2 = omega_perp exp(i lambda t), omega3 constant.
// This closed form fixes the sign of the gyroscopic term. After 1000 s (4 turns of the cone) RK4's
// phase error is 1e4 * (lambda h)^5 / 120 = 8e-12 rad, i.e. 4e-13 rad/s on omega_perp = 0.05 rad/s
// (measured 4.1e-13): bound 2e-12 rad/s.
TEST(RigidBody, AxisymmetricBodyConesAtTheClosedFormRate) {
  const Mat3 inertia = Vec3(2000.0, 2000.0, 3000.0).asDiagonal();
  const DynamicsParams p = attitude_params(inertia);
  RigidState x = spinning_body(Vec3(0.05, 0.0, 0.05));
  for (int k = 0; k < 10000; ++k) propagate_piece(p, x, 0.1 * k, 0.1, PieceInput{});
  const double lambda = (3000.0 - 2000.0) / 2000.0 * 0.05, t = 1000.0;
  const Vec3 expected(0.05 * std::cos(lambda * t), 0.05 * std::sin(lambda * t), 0.05);
  EXPECT_LT((x.omega_body_radps - expected).norm(), 2e-12);
}

}  // namespace
}  // namespace chaser::plant
