// The pendulum analogue of model/slosh.hpp: its length and wall from the fill, its frequency under a
// steady acceleration (closed form), its agreement with the spring-mass for small swings, its
// conserved quantities, and the wall's hold (a static balance in closed form).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "core/constants.hpp"
#include "model/slosh.hpp"
#include "tests/plant/slosh_system.hpp"

namespace chaser::model {
namespace {

using slosh_harness::angular_momentum;
using slosh_harness::chaser_body;
using slosh_harness::energy;
using slosh_harness::FullState;
using slosh_harness::linear_momentum;
using slosh_harness::measured_period;
using slosh_harness::rk4_step;
using slosh_harness::System;

constexpr double kXi = 1.84118378134066;  // j'_{1,1}, Abramowitz and Stegun Table 9.5
constexpr double kGEff = 0.1;             // [m/s^2] the design acceleration of the fills below

struct Tank {
  CylindricalTank tank;
  SloshTankFill fill;
  SloshTankParams pendulum;
};

// R = 0.4 m and 300 kg at fill h (0.45 m: a middle fill, L < R; 0.05 m: a shallow one, L > R).
Tank tank_at_fill(double fill_height_m, double damping_ratio, double capillary_mps2) {
  Tank t;
  t.tank = {Vec3(0.0, 0.7, 0.4), Vec3::UnitZ(), 0.4};
  t.fill = slosh_tank_from_fill(t.tank, 300.0, fill_height_m, kGEff, damping_ratio);
  t.pendulum = pendulum_analogue(t.fill, t.tank, kGEff, capillary_mps2);
  return t;
}

// The pendulum swung by theta from its axis towards e (lateral unit), at rest in the body.
SloshState swung(const SloshTankParams& p, double theta, const Vec3& e) {
  const Vec3 rod = std::cos(theta) * p.axis_body - std::sin(theta) * e;  // mass to hinge
  return {p.pendulum_length_m * (p.axis_body - rod), Vec3::Zero()};
}

double swing_angle(const SloshTankParams& p, const SloshState& s) {
  const Vec3 hinge_to_mass = s.s_body_m - p.pendulum_length_m * p.axis_body;
  return std::acos(std::clamp(-hinge_to_mass.normalized().dot(p.axis_body), -1.0, 1.0));
}

// A body so heavy (1e9 kg, 1e9 kg m^2) that the tank's acceleration is F / M whatever the mass does.
RigidBodyMassProps anvil() {
  RigidBodyMassProps body;
  body.mass_kg = 1e9;
  body.inertia_com_body_kgm2 = 1e9 * Mat3::Identity();
  return body;
}

// Test 1. Dodge 2000, ch. 3: L = g / omega1^2 = (R / xi1) coth(xi1 h / R), so small swings under g_eff
// are the spring-mass's (m1 g_eff / L = k1); the wall at 90 deg while L <= R, at asin(R / L) beyond;
// its spring at 10 omega1, at most 5 rad/s (here omega1 = 0.67 and 0.32 rad/s: both sides of the cap).
// Round-off only: 1e-12.
TEST(SloshPendulum, LengthAndWallFromTheFill) {
  for (const double h : {0.45, 0.05}) {
    const Tank t = tank_at_fill(h, 0.005, 0.0);
    const double r = t.tank.radius_m, length = r / (kXi * std::tanh(kXi * h / r));
    EXPECT_NEAR(t.pendulum.pendulum_length_m, length, 1e-12 * length) << "h " << h;
    EXPECT_NEAR(t.pendulum.mass_kg * kGEff / length, t.fill.slosh.stiffness_Npm, 1e-12 * t.fill.slosh.stiffness_Npm);
    EXPECT_EQ(t.pendulum.stiffness_Npm, 0.0);
    EXPECT_EQ(t.pendulum.damping_Nspm, t.fill.slosh.damping_Nspm);
    EXPECT_EQ(t.pendulum.anchor_body_m, t.fill.slosh.anchor_body_m);
    const double wall = length > r ? std::asin(r / length) : 0.5 * kPi;
    EXPECT_NEAR(t.pendulum.wall_angle_rad, wall, 1e-12) << "h " << h;
    const double wall_omega = std::min(10.0 * t.fill.omega_radps, 5.0);  // 5 rad/s: 0.5 rad per 0.1 s substep
    EXPECT_NEAR(t.pendulum.wall_stiffness_Npm, t.pendulum.mass_kg * wall_omega * wall_omega,
                1e-12 * t.pendulum.wall_stiffness_Npm);
  }
  EXPECT_LT(tank_at_fill(0.45, 0.005, 0.0).pendulum.pendulum_length_m, 0.4);  // both wall cases are covered
  EXPECT_GT(tank_at_fill(0.05, 0.005, 0.0).pendulum.pendulum_length_m, 0.4);
}

// Test 2. The closed form: under a steady axial acceleration a the pendulum swings at sqrt(a / L)
// (the spring-mass at omega1 whatever a is), and surface tension alone holds it at sqrt(g_c / L).
// Half the design acceleration, four times it, and the capillary hold alone (g_c = 3e-4 m/s^2).
// Tolerance 1e-4 relative: the finite swing (0.01 rad) lengthens the period by theta^2 / 16 = 6e-6,
// the anvil's finite mass shifts it by m1 / M = 3e-7, and RK4 at 400 steps a period by ~1e-10.
TEST(SloshPendulum, FrequencyFollowsTheActualAcceleration) {
  struct Case {
    double accel_mps2, capillary_mps2;
  };
  for (const Case c : {Case{0.5 * kGEff, 0.0}, Case{4.0 * kGEff, 0.0}, Case{0.0, 3e-4}}) {
    const Tank t = tank_at_fill(0.45, 0.0, c.capillary_mps2);
    System sys;
    sys.body = anvil();
    sys.body.com_body_m = t.pendulum.anchor_body_m;  // no torque from the thrust
    sys.tanks = {t.pendulum};
    sys.force_body_N = sys.body.mass_kg * c.accel_mps2 * t.pendulum.axis_body;
    FullState x;
    x.slosh = {swung(t.pendulum, 0.01, Vec3::UnitX())};
    const double omega = std::sqrt((c.accel_mps2 + c.capillary_mps2) / t.pendulum.pendulum_length_m);
    const double period = 2.0 * kPi / omega, h = period / 400.0;
    const double measured = measured_period(sys, x, 0, Vec3::UnitX(), h, 4 * 400 + 10);
    EXPECT_NEAR(measured, period, 1e-4 * period) << "a " << c.accel_mps2 << ", g_c " << c.capillary_mps2;
  }
}

// Test 3. Small swings under a steady thrust at the design acceleration: the pendulum and the
// spring-mass move the chaser alike. A chaser-like body (1500 kg, turned inertia, its CoM on the
// tank's axis so that only the swing turns it), one 300 kg tank swung 2 mm, 3 periods at
// h = 0.01 s. The two differ at second order in the swing (the pendulum's mass rises L(1 - cos theta),
// its tension changes with the swing): 2 mm on L = 0.22 m is theta = 0.009, theta^2 = 8e-5. Measured:
// 9.9e-5 of the body's largest rate and 8.5e-5 of the swing; tolerance 1e-3 of each.
TEST(SloshPendulum, SmallSwingsUnderThrustMatchTheSpringMass) {
  const Tank t = tank_at_fill(0.45, 0.005, 0.0);
  System pendulum, spring;
  pendulum.body = spring.body = chaser_body();
  // The body's CoM on the tank's axis, so that the thrust along it turns nothing: only the swing does.
  pendulum.body.com_body_m = spring.body.com_body_m = t.pendulum.anchor_body_m - 0.5 * t.pendulum.axis_body;
  pendulum.tanks = {t.pendulum};
  spring.tanks = {t.fill.slosh};
  // The tank feels F / (M + m1) along its axis: the design acceleration.
  pendulum.force_body_N = spring.force_body_N = (pendulum.body.mass_kg + t.pendulum.mass_kg) * kGEff * Vec3::UnitZ();
  const double swing_m = 0.002;
  FullState xp, xs;
  xp.slosh = {swung(t.pendulum, swing_m / t.pendulum.pendulum_length_m, Vec3::UnitX())};
  xs.slosh = {{swing_m * Vec3::UnitX(), Vec3::Zero()}};
  const double h = 0.01;
  const int steps = static_cast<int>(3.0 * 2.0 * kPi / t.fill.omega_radps / h);
  double rate_scale = 0.0, rate_gap = 0.0, swing_gap = 0.0;
  for (int k = 0; k < steps; ++k) {
    rk4_step(pendulum, xp, h);
    rk4_step(spring, xs, h);
    rate_scale = std::max(rate_scale, xs.omega_body_radps.norm());
    rate_gap = std::max(rate_gap, (xp.omega_body_radps - xs.omega_body_radps).norm());
    const Vec3 lateral_p = xp.slosh[0].s_body_m - t.pendulum.axis_body * t.pendulum.axis_body.dot(xp.slosh[0].s_body_m);
    swing_gap = std::max(swing_gap, (lateral_p - xs.slosh[0].s_body_m).norm());
  }
  ASSERT_GT(rate_scale, 1e-5);  // the swing does turn the chaser
  EXPECT_LT(rate_gap, 1e-3 * rate_scale);
  EXPECT_LT(swing_gap, 1e-3 * swing_m);
}

// Test 4. A free tumbling chaser with two pendulum tanks (one tilted, one shallow: L > R), damping
// off, capillary hold on: the tumble flings both masses into their walls. The rod, the capillary
// pair and the wall's spring act on mass and body at one point, so linear and angular momentum are
// conserved, and energy with the capillary's and the wall's potential. The masses strike their walls
// hard (0.19 rad in); the wall's force is continuous but kinked at contact, which costs RK4 its order
// there, and the step back onto the sphere is a first-order projection. Measured at 5 ms: energy
// 4.5e-6, momentum 2.1e-8, angular momentum 2.4e-9 relative; at 2.5 ms 8.8e-7, 4.8e-9, 5.9e-10
// (a discretisation error, shrinking ~4.5x a halving, not a leak in the model). Tolerances 4x those.
TEST(SloshPendulum, FreeTumbleWithWallContactConservesMomentumAndEnergy) {
  System sys;
  sys.body = chaser_body();
  const CylindricalTank left{Vec3(0.0, 0.7, 0.4), Vec3::UnitZ(), 0.4};
  const CylindricalTank right{Vec3(0.1, -0.7, 0.3), Vec3(0.1, 0.2, 1.0).normalized(), 0.4};
  const SloshTankFill left_fill = slosh_tank_from_fill(left, 300.0, 0.45, kGEff, 0.0);
  const SloshTankFill right_fill = slosh_tank_from_fill(right, 60.0, 0.05, kGEff, 0.0);
  sys.tanks = {pendulum_analogue(left_fill, left, kGEff, 3e-4), pendulum_analogue(right_fill, right, kGEff, 3e-4)};
  for (SloshTankParams& p : sys.tanks) p.wall_damping_Nspm = 0.0;
  FullState x;
  x.v_inertial_mps = Vec3(0.02, 0.01, -0.03);
  x.omega_body_radps = Vec3(0.3, -0.2, 0.4);
  x.slosh = {swung(sys.tanks[0], 0.2, Vec3::UnitX()), swung(sys.tanks[1], 0.1, Vec3::UnitY())};
  const Vec3 p0 = linear_momentum(sys, x), h0 = angular_momentum(sys, x);
  const double e0 = energy(sys, x);
  double energy_error = 0.0, momentum_error = 0.0, angular_error = 0.0;
  std::array<double, 2> deepest{};  // largest swing beyond each wall [rad]
  for (int k = 0; k < 20000; ++k) {  // 100 s
    rk4_step(sys, x, 0.005);
    energy_error = std::max(energy_error, std::abs(energy(sys, x) - e0));
    momentum_error = std::max(momentum_error, (linear_momentum(sys, x) - p0).norm());
    angular_error = std::max(angular_error, (angular_momentum(sys, x) - h0).norm());
    for (std::size_t i = 0; i < 2; ++i)
      deepest[i] = std::max(deepest[i], swing_angle(sys.tanks[i], x.slosh[i]) - sys.tanks[i].wall_angle_rad);
  }
  EXPECT_GT(deepest[0], 0.0);  // both masses did reach their walls
  EXPECT_GT(deepest[1], 0.0);
  EXPECT_LT(energy_error, 2e-5 * e0);
  EXPECT_LT(momentum_error, 1e-7 * p0.norm());
  EXPECT_LT(angular_error, 1e-8 * h0.norm());
}

// Test 5. The wall holds: on the anvil, a steady specific force drives the mass into its wall and
// the damped swing settles where the wall's spring balances the force's component along the arc's
// outward tangent t = sin(theta) n + cos(theta) rho:  k_w depth = m (f . t), depth = L (theta - wall).
// Middle fill (wall at 90 deg): the chaser accelerating along -n at 0.05 m/s^2 pushes the liquid
// up, f . t = (0.05 - g_c) sin(theta). Shallow fill (wall at asin(R / L)): a lateral 0.05 m/s^2,
// f . t = 0.05 cos(theta) - g_c sin(theta). Balance to 1e-6 relative once settled (the swing's
// damping ratio is 0.3 here, 300 s is ~30 of its time constants); the mass's lateral offset stays
// within R but for the wall's give.
TEST(SloshPendulum, TheWallHoldsTheMassAgainstASteadyForce) {
  const double capillary = 3e-4, accel = 0.05;
  for (const double h : {0.45, 0.05}) {
    const Tank t = tank_at_fill(h, 0.3, capillary);
    const SloshTankParams& p = t.pendulum;
    System sys;
    sys.body = anvil();
    sys.body.com_body_m = p.anchor_body_m;
    sys.tanks = {p};
    const bool middle = p.pendulum_length_m <= t.tank.radius_m;
    const Vec3 body_accel = middle ? Vec3(-accel * p.axis_body) : Vec3(-accel * Vec3::UnitX());
    sys.force_body_N = sys.body.mass_kg * body_accel;
    FullState x;
    x.slosh = {swung(p, 0.3, Vec3::UnitX())};
    double widest = 0.0;
    for (int k = 0; k < 60000; ++k) {  // 300 s
      rk4_step(sys, x, 0.005);
      const Vec3 s = x.slosh[0].s_body_m;
      widest = std::max(widest, (s - p.axis_body * p.axis_body.dot(s)).norm());
    }
    const double theta = swing_angle(p, x.slosh[0]);
    const double along_tangent = middle ? (accel - capillary) * std::sin(theta)
                                        : accel * std::cos(theta) - capillary * std::sin(theta);
    const double depth = p.mass_kg * along_tangent / p.wall_stiffness_Npm;
    ASSERT_GT(depth, 0.0);
    EXPECT_NEAR(p.pendulum_length_m * (theta - p.wall_angle_rad), depth, 1e-6 * depth) << "h " << h;
    EXPECT_LT(x.slosh[0].s_dot_body_mps.norm(), 1e-9);
    EXPECT_LT(widest, 1.03 * t.tank.radius_m) << "h " << h;  // the wall is a penalty: it gives a little
  }
}

}  // namespace
}  // namespace chaser::model
