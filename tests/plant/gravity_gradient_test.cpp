#include "plant/gravity_gradient.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "core/rotation.hpp"
#include "plant/propagator.hpp"

namespace chaser::plant {
namespace {

constexpr double kMu = 4.282837e13;      // [m^3/s^2] Mars
constexpr double kR = 3389.5e3 + 500e3;  // [m]
const Mat3 kInertia = Vec3(2000.0, 2500.0, 3000.0).asDiagonal();  // [kg m^2]

Vec3 torque_at(const Vec3& r_body_m, const Mat3& inertia) {
  return gravity_gradient_torque_body(gravity_gradient_gain(kMu, r_body_m.squaredNorm()), r_body_m, inertia);
}

// Test 6. Body turned by theta about z from LVLH, zenith = LVLH x: r_hat_body = (cos, -sin, 0),
// I r_hat = (I1 cos, -I2 sin, 0), r_hat x I r_hat = (0, 0, (I1 - I2) sin cos), so
//   C_z = 3 mu / R^3 (I1 - I2) sin(theta) cos(theta) = -3 mu / R^3 * 500 / 2 at 45 deg (~ -1.6e-4 N m).
// The hand value and the formula differ only by round-off: bound 1e-14 relative.
TEST(GravityGradient, HandValueAt45Degrees) {
  const double theta = 0.25 * kPi;
  const Vec3 r_body = kR * Vec3(std::cos(theta), -std::sin(theta), 0.0);
  const Vec3 torque = torque_at(r_body, kInertia);
  const double expected = 3.0 * kMu / (kR * kR * kR) * (2000.0 - 2500.0) * 0.5;
  EXPECT_NEAR(torque.z(), expected, 1e-14 * std::abs(expected));
  EXPECT_NEAR(torque.x(), 0.0, 1e-14 * std::abs(expected));
  EXPECT_NEAR(torque.y(), 0.0, 1e-14 * std::abs(expected));
}

// No torque when a principal axis points at zenith (either way), whatever the roll about it.
TEST(GravityGradient, VanishesWithAPrincipalAxisAtZenith) {
  for (const Vec3& axis : {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(0, -1, 0)}) {
    EXPECT_EQ(torque_at(kR * axis, kInertia), Vec3::Zero());
  }
  // A general inertia (principal axes along the columns of a rotation R): no torque with its
  // second principal axis at zenith; round-off of the rotated products ~1e-16 * 3000 * 3 mu / R^3.
  const Mat3 rot = quat_from_rotation_vector(Vec3(0.3, -0.7, 0.5)).toRotationMatrix();
  const Mat3 inertia = rot * Vec3(2000.0, 2500.0, 3000.0).asDiagonal() * rot.transpose();
  const double scale = 3.0 * kMu / (kR * kR * kR) * 3000.0;
  EXPECT_LT(torque_at(kR * rot.col(1), inertia).norm(), 1e-14 * scale);
  EXPECT_GT(torque_at(kR * (rot.col(1) + 0.1 * rot.col(0)), inertia).norm(), 1e-3 * scale);
}

// propagate_piece applies it, in the right frame: a quarter orbit into the run (LVLH x is then
// inertial y), a chaser at the target turned 45 deg about LVLH z and turning with LVLH (omega = n
// about z) spins up about body z at C_z / I3 over 1 s. With the gravity gradient off, omega stays
// exactly (0, 0, n) (a principal axis: no gyroscopic torque). Over 1 s the torque itself changes by
// ~(omega t)^2 ~ 1e-10 relative, so the bound is 1e-6 relative to the spin-up.
TEST(GravityGradient, PropagatorAppliesItWhenEnabled) {
  DynamicsParams p = make_dynamics_params(model::Scenario{});
  p.inertia_kgm2 = kInertia;
  p.inertia_inv = kInertia.inverse();
  const double n = p.orbit.mean_motion_radps(), t0 = 0.5 * kPi / n;
  RigidState x;
  x.mass_kg = 2500.0;
  x.q_inertial_from_body = p.orbit.q_inertial_from_lvlh(t0) * quat_from_rotation_vector(Vec3(0.0, 0.0, 0.25 * kPi));
  x.omega_body_radps = Vec3(0.0, 0.0, n);
  RigidState off = x;
  p.gravity_gradient = true;
  propagate_piece(p, x, t0, 1.0, PieceInput{});
  const double spin_up = 3.0 * p.orbit.mu_m3ps2() / std::pow(p.orbit.radius_m(), 3) * (2000.0 - 2500.0) * 0.5 / 3000.0;
  EXPECT_NEAR(x.omega_body_radps.z() - n, spin_up, 1e-6 * std::abs(spin_up));
  EXPECT_LT(x.omega_body_radps.head<2>().norm(), 1e-6 * std::abs(spin_up));
  p.gravity_gradient = false;
  propagate_piece(p, off, t0, 1.0, PieceInput{});
  EXPECT_EQ(off.omega_body_radps, Vec3(0.0, 0.0, n));
}

}  // namespace
}  // namespace chaser::plant
