#include "model/slosh.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "core/constants.hpp"
#include "core/rotation.hpp"
#include "plant/rigid_body.hpp"
#include "tests/plant/slosh_system.hpp"

namespace chaser::model {
namespace slosh_test {

using slosh_harness::FullState;
using slosh_harness::System;
using slosh_harness::angular_momentum;
using slosh_harness::chaser_body;
using slosh_harness::energy;
using slosh_harness::linear_momentum;
using slosh_harness::measured_period;
using slosh_harness::rk4_step;

// The header's equations as written: the 6x6 system for (a_c, omega') with lambda eliminated, then
// each mass. coupled_accelerations solves the same equations through the axial forces (k x k); this
// plain form is its reference.
SloshAccelerations reference_accelerations(const RigidBodyMassProps& body, const std::vector<SloshTankParams>& tanks,
                                           const std::vector<SloshState>& states, const Vec3& omega,
                                           const Vec3& force, const Vec3& torque) {
  Mat6 a = Mat6::Zero();
  a.topLeftCorner<3, 3>() = body.mass_kg * Mat3::Identity();
  a.bottomRightCorner<3, 3>() = body.inertia_com_body_kgm2;
  Vec6 rhs;
  rhs.head<3>() = force;
  rhs.tail<3>() = torque - omega.cross(body.inertia_com_body_kgm2 * omega);
  std::vector<Vec3> r(tanks.size()), f(tanks.size()), cc(tanks.size());
  for (std::size_t i = 0; i < tanks.size(); ++i) {
    const Vec3& n = tanks[i].axis_body;
    const Mat3 lateral = Mat3::Identity() - n * n.transpose();
    const Vec3 s = lateral * states[i].s_body_m, s_dot = lateral * states[i].s_dot_body_mps;
    r[i] = tanks[i].anchor_body_m + s - body.com_body_m;
    f[i] = -tanks[i].stiffness_Npm * s - tanks[i].damping_Nspm * s_dot;
    cc[i] = omega.cross(omega.cross(r[i])) + 2.0 * omega.cross(s_dot);
    Vec6 j;
    j << n, r[i].cross(n);
    a += tanks[i].mass_kg * j * j.transpose();
    const double b = n.dot(cc[i]);
    rhs.head<3>() -= f[i] + tanks[i].mass_kg * b * n;
    rhs.tail<3>() -= r[i].cross(f[i]) + tanks[i].mass_kg * b * r[i].cross(n);
  }
  const Vec6 x = a.fullPivLu().solve(rhs);
  SloshAccelerations out;
  out.a_com_body_mps2 = x.head<3>();
  out.omega_dot_body_radps2 = x.tail<3>();
  for (std::size_t i = 0; i < tanks.size(); ++i) {
    const Vec3& n = tanks[i].axis_body;
    const Vec3 frame = out.a_com_body_mps2 + out.omega_dot_body_radps2.cross(r[i]) + cc[i];
    const Vec3 free = f[i] / tanks[i].mass_kg - frame;
    out.s_ddot_body_mps2[i] = free - n * n.dot(free);
    out.axial_force_N[i] = tanks[i].mass_kg * n.dot(frame);
  }
  return out;
}

SloshTankParams point_tank(const Vec3& anchor, const Vec3& axis, double mass, double stiffness, double damping) {
  return {anchor, axis.normalized(), mass, stiffness, damping};
}

// Two tanks from their fills (R = 0.4 m, 300 kg each, g_eff = 0.1 m/s^2: omega1 ~ 0.66 rad/s),
// at different places, one axis tilted.
System two_tank_system(double damping_ratio) {
  System sys;
  sys.body = chaser_body();
  CylindricalTank left{Vec3(0.0, 0.7, 0.4), Vec3::UnitZ(), 0.4};
  CylindricalTank right{Vec3(0.1, -0.7, 0.3), Vec3(0.1, 0.2, 1.0).normalized(), 0.4};
  sys.tanks.push_back(slosh_tank_from_fill(left, 300.0, 0.45, 0.1, damping_ratio).slosh);
  sys.tanks.push_back(slosh_tank_from_fill(right, 300.0, 0.30, 0.1, damping_ratio).slosh);
  return sys;
}

FullState tumbling_state(const System& sys) {
  FullState x;
  x.r_inertial_m = Vec3(10.0, -5.0, 2.0);
  x.v_inertial_mps = Vec3(0.02, 0.01, -0.03);
  x.q_inertial_from_body = quat_from_rotation_vector(Vec3(0.3, -0.5, 0.2));
  x.omega_body_radps = Vec3(0.05, -0.03, 0.08);
  const Vec3 s0 = Vec3(0.06, -0.02, 0.0), v0 = Vec3(-0.01, 0.03, 0.0);
  for (const SloshTankParams& t : sys.tanks) {
    const Mat3 p = Mat3::Identity() - t.axis_body * t.axis_body.transpose();
    x.slosh.push_back({p * s0, p * v0});
  }
  return x;
}

constexpr double kXi = 1.84118378134066;  // j'_{1,1}, Abramowitz and Stegun Table 9.5

// Test 1. Dodge 2000, ch. 3, written out here with the diameter d = 2R as Dodge writes it, at a
// shallow and a middle fill (h/R = 0.6 and 1.6; R = 0.5 m, 200 kg, g_eff = 0.02 m/s^2, zeta = 0.005).
// The same formulas in another arrangement agree to round-off: 1e-14 relative. Two independent
// forms as well: Abramson's Table 6.1 rounds the constants (m1 = m d/(4.4 h) tanh(3.68 h/d),
// k1 = m g tanh^2(3.68 h/d)/(1.19 h)), so 1e-3 and 5e-3 relative; and Dodge's pendulum puts its
// bob at hinge minus length, H - L, H = h/2 - d/(2 xi)(tanh(xi h/d) - 1/sinh(2 xi h/d)),
// L = g/omega^2 = d/(2 xi tanh(2 xi h/d)) from the liquid's centre: 1e-14 m.
TEST(SloshTankFromFill, MatchesDodgeAndAbramsonAtTwoFills) {
  const double r = 0.5, d = 1.0, m = 200.0, g = 0.02, zeta = 0.005;
  const CylindricalTank tank{Vec3(0.1, 0.2, 0.3), Vec3(0.0, 0.6, 0.8), r};
  for (const double h : {0.3, 0.8}) {
    const SloshTankFill fill = slosh_tank_from_fill(tank, m, h, g, zeta);
    const double omega = std::sqrt(2.0 * g * kXi / d * std::tanh(2.0 * kXi * h / d));
    const double m1 = m * d / h * std::tanh(2.0 * kXi * h / d) / (kXi * (kXi * kXi - 1.0));
    const double l1 = h / 2.0 - d / kXi * std::tanh(kXi * h / d);
    EXPECT_NEAR(fill.omega_radps, omega, 1e-14 * omega);
    EXPECT_NEAR(fill.slosh.mass_kg, m1, 1e-14 * m1);
    EXPECT_NEAR(fill.slosh_height_m, h / 2.0 + l1, 1e-14 * h);
    EXPECT_NEAR(fill.slosh.stiffness_Npm, m1 * omega * omega, 1e-14 * m1 * omega * omega);
    EXPECT_NEAR(fill.slosh.damping_Nspm, 2.0 * zeta * m1 * omega, 1e-14 * m1 * omega);
    EXPECT_NEAR(fill.fixed_mass_kg, m - m1, 1e-13 * m);
    // The liquid's centre of mass stays at h/2, in the body too.
    EXPECT_NEAR(fill.fixed_mass_kg * fill.fixed_height_m + m1 * fill.slosh_height_m, m * h / 2.0, 1e-14 * m * h);
    const Vec3 centre = (fill.fixed_mass_kg * fill.fixed_mass_body_m + m1 * fill.slosh.anchor_body_m) / m;
    EXPECT_LT((centre - (tank.bottom_centre_body_m + h / 2.0 * tank.axis_body)).norm(), 1e-14);
    EXPECT_EQ(fill.slosh.axis_body, tank.axis_body);

    const double a = 3.68 * h / d;
    EXPECT_NEAR(fill.slosh.mass_kg, m * d / (4.4 * h) * std::tanh(a), 1e-3 * m1);
    EXPECT_NEAR(fill.slosh.stiffness_Npm, m * g / (1.19 * h) * std::pow(std::tanh(a), 2), 5e-3 * m1 * omega * omega);
    const double hinge = h / 2.0 - d / (2.0 * kXi) * (std::tanh(kXi * h / d) - 1.0 / std::sinh(2.0 * kXi * h / d));
    const double length = d / (2.0 * kXi * std::tanh(2.0 * kXi * h / d));
    EXPECT_NEAR(fill.slosh_height_m - h / 2.0, hinge - length, 1e-14);
    EXPECT_NEAR(g / (omega * omega), length, 1e-14);
  }
}

// Test 2. Limits. Deep (h = 20 R): tanh(36.8) = 1 in double, so omega1^2 = g xi/R,
// m1/m = 2R/(xi (xi^2 - 1) h), L1 = h/2 - 2R/xi, to round-off (1e-14 relative). Shallow
// (h = 1e-4 R): tanh(x)/x = 1 - x^2/3 with x ~ 2e-4, so m1/m -> 2/(xi^2 - 1) = 0.838 within 2e-8
// (bound 1e-7), and the slosh mass sits on the bottom: h1 = xi^2 h^3/(12 R^2) to O(h^5), and the
// difference h - (2R/xi) tanh(...) keeps h's round-off, 1e-20 m: bound 1e-19 m.
TEST(SloshTankFromFill, DeepAndShallowLimits) {
  const double r = 0.5, m = 200.0, g = 0.02;
  const CylindricalTank tank{Vec3::Zero(), Vec3::UnitZ(), r};
  const double deep_h = 20.0 * r;
  const SloshTankFill deep = slosh_tank_from_fill(tank, m, deep_h, g, 0.0);
  EXPECT_NEAR(deep.omega_radps * deep.omega_radps, g * kXi / r, 1e-14 * g * kXi / r);
  const double deep_m1 = m * 2.0 * r / (kXi * (kXi * kXi - 1.0) * deep_h);
  EXPECT_NEAR(deep.slosh.mass_kg, deep_m1, 1e-14 * deep_m1);
  EXPECT_NEAR(deep.slosh_height_m, deep_h - 2.0 * r / kXi, 1e-14 * deep_h);
  EXPECT_EQ(deep.slosh.damping_Nspm, 0.0);

  const double shallow_h = 1e-4 * r;
  const SloshTankFill shallow = slosh_tank_from_fill(tank, m, shallow_h, g, 0.0);
  EXPECT_NEAR(shallow.slosh.mass_kg / m, 2.0 / (kXi * kXi - 1.0), 1e-7);
  EXPECT_NEAR(shallow.slosh_height_m, kXi * kXi * std::pow(shallow_h, 3) / (12.0 * r * r), 1e-19);
}

// Test 3. Body of 1e12 kg and kg m^2 (held): a displaced mass oscillates at sqrt(k/m). The body's
// share shifts it by m/(2M) = 5e-11; RK4's frequency error is (omega h)^4/120 ~ 4e-11 at h = 0.01 s;
// the chord crossings add ~(omega h)^2 h/6 ~ 1e-7 s each, over a 200 s span: 1e-6 relative (brief)
// is far above all three (measured -1.7e-10).
TEST(Slosh, HeldBodyOscillatesAtSqrtKOverM) {
  System sys;
  sys.body.mass_kg = 1e12;
  sys.body.inertia_com_body_kgm2 = 1e12 * Mat3::Identity();
  sys.tanks.push_back(point_tank(Vec3(0.3, 0.5, 1.0), Vec3::UnitZ(), 100.0, 50.0, 0.0));
  FullState x;
  x.slosh.push_back({Vec3(0.05, 0.0, 0.0), Vec3::Zero()});
  const double period = measured_period(sys, x, 0, Vec3::UnitX(), 0.01, 20000);
  const double expected = 2.0 * kPi / std::sqrt(50.0 / 100.0);
  EXPECT_NEAR(period, expected, 1e-6 * expected);
}

// Test 4. Free body, mass anchored at the body's CoM on a tilted axis, displaced along one lateral
// direction: no torque (r x f = s x f = 0), so the two bodies oscillate against each other at
// omega^2 = k (1/m + 1/M). Same error budget as test 3: 1e-6 relative (measured 7.3e-11). The rate
// stays at round-off (s x f vanishes but for the rounding of the products).
TEST(Slosh, FreeBodyTranslationFollowsTheReducedMass) {
  System sys;
  sys.body = chaser_body();
  sys.body.mass_kg = 500.0;
  const Vec3 axis = Vec3(0.2, 0.3, 1.0).normalized();
  sys.tanks.push_back(point_tank(sys.body.com_body_m, axis, 100.0, 50.0, 0.0));
  const Vec3 e = axis.unitOrthogonal();
  FullState x;
  x.slosh.push_back({0.05 * e, Vec3::Zero()});
  const double period = measured_period(sys, x, 0, e, 0.01, 20000);
  const double expected = 2.0 * kPi / std::sqrt(50.0 * (1.0 / 100.0 + 1.0 / 500.0));
  EXPECT_NEAR(period, expected, 1e-6 * expected);
  for (int k = 0; k < 1000; ++k) rk4_step(sys, x, 0.01);
  EXPECT_LT(x.omega_body_radps.norm(), 1e-15);
}

// Test 5. The full coupled system, free: two tanks at different places (one axis tilted),
// non-diagonal inertia, spin 0.1 rad/s, slosh displaced and moving, no damping; 600 s of RK4 at
// h = 0.01 s. Linear and angular momentum (about the system's CoM) are invariants of the exact
// motion; RK4 moves them by its truncation only (omega h <= 0.007: (omega h)^5/120 ~ 1e-13 per step
// on the state, far less on the invariants): bound 1e-10 relative (brief). The energy's RK4 drift is
// (omega h)^6/144 ~ 1e-15 per step, 6e4 steps: bound 1e-10 relative. The constraint n . s = 0 is
// linear, so RK4 adds nothing to it but round-off: the additions to s' round (eps |s'| ~ 1e-17 m/s
// each, a random walk of 2.4e5 of them, ~2e-15 m/s), integrated over 600 s: ~1e-12 m; bound 1e-11 m
// (s and s' are projected before use, so this cannot feed back). Measured: momenta 2.6e-13 and
// 2.4e-13, energy 3.8e-12, axial 1.8e-13 m.
TEST(Slosh, FreeTumblingSystemConservesMomentumAndEnergy) {
  const System sys = two_tank_system(0.0);
  FullState x = tumbling_state(sys);
  const Vec3 p0 = linear_momentum(sys, x), h0 = angular_momentum(sys, x);
  const double e0 = energy(sys, x);
  double worst_p = 0.0, worst_h = 0.0, worst_e = 0.0, worst_axial = 0.0;
  for (int k = 0; k < 60000; ++k) {
    rk4_step(sys, x, 0.01);
    worst_p = std::max(worst_p, (linear_momentum(sys, x) - p0).norm() / p0.norm());
    worst_h = std::max(worst_h, (angular_momentum(sys, x) - h0).norm() / h0.norm());
    worst_e = std::max(worst_e, std::abs(energy(sys, x) - e0) / e0);
    for (std::size_t i = 0; i < sys.tanks.size(); ++i)
      worst_axial = std::max(worst_axial, std::abs(sys.tanks[i].axis_body.dot(x.slosh[i].s_body_m)));
  }
  EXPECT_LT(worst_p, 1e-10);
  EXPECT_LT(worst_h, 1e-10);
  EXPECT_LT(worst_e, 1e-10);
  EXPECT_LT(worst_axial, 1e-11);
  // It did slosh and tumble: the rate moved and both masses exchanged momentum with the body.
  EXPECT_GT((x.omega_body_radps - Vec3(0.05, -0.03, 0.08)).norm(), 1e-3);
}

// Test 6. The same system with zeta = 0.05. The dampers take energy every step and never give it
// back (bound: a rise of 1e-13 of the energy per step, above RK4's own 1e-15); the momenta stay
// (1e-10, as in test 5); and the energy lost is the dampers' work, sum c_i |s_i'|^2 integrated by
// the trapezoid rule: its error (2 omega1 h)^2/12 ~ 2e-5 relative, bound 1e-4 relative. Measured:
// no rise at all, momenta 1.5e-13, 3.8 % of the energy lost, work balance 4.6e-7.
TEST(Slosh, DampedSloshLosesEnergyMonotonicallyAndKeepsMomentum) {
  const System sys = two_tank_system(0.05);
  FullState x = tumbling_state(sys);
  const auto damper_power = [&sys](const FullState& y) {
    double power = 0.0;
    for (std::size_t i = 0; i < sys.tanks.size(); ++i)
      power += sys.tanks[i].damping_Nspm * y.slosh[i].s_dot_body_mps.squaredNorm();
    return power;
  };
  const Vec3 p0 = linear_momentum(sys, x), h0 = angular_momentum(sys, x);
  const double e0 = energy(sys, x), h = 0.01;
  double previous = e0, worst_rise = 0.0, worst_p = 0.0, worst_h = 0.0, work = 0.0;
  for (int k = 0; k < 60000; ++k) {
    const double power_before = damper_power(x);
    rk4_step(sys, x, h);
    work += 0.5 * h * (power_before + damper_power(x));
    const double e = energy(sys, x);
    worst_rise = std::max(worst_rise, (e - previous) / e0);
    previous = e;
    worst_p = std::max(worst_p, (linear_momentum(sys, x) - p0).norm() / p0.norm());
    worst_h = std::max(worst_h, (angular_momentum(sys, x) - h0).norm() / h0.norm());
  }
  EXPECT_LT(worst_rise, 1e-13);
  EXPECT_LT(worst_p, 1e-10);
  EXPECT_LT(worst_h, 1e-10);
  EXPECT_GT(e0 - previous, 0.01 * e0);  // it did lose energy
  EXPECT_NEAR(e0 - previous, work, 1e-4 * work);
}

// Test 7. Thrust along a tank axis through the system's CoM, nothing moving: everything accelerates
// together at F / M_total, each tank holds its mass with lambda_i = m_i F / M_total, and the slosh
// stays at rest. Round-off: 1e-14 relative.
TEST(Slosh, AxialThrustIsCarriedByTheConstraint) {
  System sys;
  sys.body.mass_kg = 800.0;
  sys.body.inertia_com_body_kgm2 = chaser_body().inertia_com_body_kgm2;
  sys.body.com_body_m = Vec3(0.0, 0.0, 0.5);
  sys.tanks.push_back(point_tank(Vec3(0.0, 0.6, 0.8), Vec3::UnitZ(), 100.0, 40.0, 2.0));
  sys.tanks.push_back(point_tank(Vec3(0.0, -0.6, 0.8), Vec3::UnitZ(), 100.0, 40.0, 2.0));
  const double total = 1000.0;
  const Vec3 system_com =
      (800.0 * sys.body.com_body_m + 100.0 * Vec3(0.0, 0.6, 0.8) + 100.0 * Vec3(0.0, -0.6, 0.8)) / total;
  ASSERT_LT((system_com - Vec3(0.0, 0.0, 0.56)).norm(), 1e-15);
  const std::vector<SloshState> rest(2);
  const Vec3 force(0.0, 0.0, 20.0);
  // The torque about the body's CoM that puts the line of action through the system's CoM.
  const Vec3 torque = (system_com - sys.body.com_body_m).cross(force);
  const SloshAccelerations acc = coupled_accelerations(sys.body, sys.tanks, rest, Vec3::Zero(), force, torque);
  EXPECT_LT((acc.a_com_body_mps2 - force / total).norm(), 1e-14 * force.norm() / total);
  EXPECT_LT(acc.omega_dot_body_radps2.norm(), 1e-14 * force.norm() / total);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(acc.axial_force_N[i], 100.0 * 20.0 / total, 1e-14 * 2.0);
    EXPECT_LT(acc.s_ddot_body_mps2[i].norm(), 1e-14 * force.norm() / total);
  }
}

// Test 8. Determinism: the same inputs give the same bits, call after call and run after run.
TEST(Slosh, SameInputsGiveIdenticalBits) {
  const System sys = two_tank_system(0.01);
  const FullState x0 = tumbling_state(sys);
  const SloshAccelerations a = coupled_accelerations(sys.body, sys.tanks, x0.slosh, x0.omega_body_radps,
                                                     Vec3(1.0, -2.0, 3.0), Vec3(0.1, 0.2, -0.3));
  const SloshAccelerations b = coupled_accelerations(sys.body, sys.tanks, x0.slosh, x0.omega_body_radps,
                                                     Vec3(1.0, -2.0, 3.0), Vec3(0.1, 0.2, -0.3));
  EXPECT_EQ(a.a_com_body_mps2, b.a_com_body_mps2);
  EXPECT_EQ(a.omega_dot_body_radps2, b.omega_dot_body_radps2);
  for (int i = 0; i < kMaxSloshTanks; ++i) {
    EXPECT_EQ(a.s_ddot_body_mps2[i], b.s_ddot_body_mps2[i]);
    EXPECT_EQ(a.axial_force_N[i], b.axial_force_N[i]);
  }
  FullState x = x0, y = x0;
  for (int k = 0; k < 1000; ++k) {
    rk4_step(sys, x, 0.01);
    rk4_step(sys, y, 0.01);
  }
  EXPECT_EQ(x.q_inertial_from_body.coeffs(), y.q_inertial_from_body.coeffs());
  EXPECT_EQ(x.omega_body_radps, y.omega_body_radps);
  for (std::size_t i = 0; i < x.slosh.size(); ++i) EXPECT_EQ(x.slosh[i].s_body_m, y.slosh[i].s_body_m);
}

// Test 9. The kernel against the header's 6x6 form (reference_accelerations, solved by full-pivot LU),
// for one to four tanks with axes off the body axes, displaced and moving, the body tumbling and
// pushed. Both are exact algebra; what differs is round-off in systems whose condition number is
// ~1e2 here (slosh masses 40-300 kg beside 1500 kg): measured 1e-16 relative, bound 1e-12.
TEST(Slosh, AxialForceSolutionMatchesTheSixBySixForm) {
  const RigidBodyMassProps body = chaser_body();
  const std::vector<SloshTankParams> all = {
      point_tank(Vec3(0.0, 0.7, 0.6), Vec3::UnitZ(), 300.0, 20.0, 0.5),
      point_tank(Vec3(0.1, -0.7, 0.5), Vec3(0.1, 0.2, 1.0), 250.0, 15.0, 0.2),
      point_tank(Vec3(0.8, 0.1, -0.2), Vec3(1.0, 0.0, 0.3), 40.0, 3.0, 0.05),
      point_tank(Vec3(-0.6, 0.2, 1.1), Vec3(-0.2, 1.0, 0.4), 120.0, 9.0, 0.0)};
  const Vec3 omega(0.05, -0.03, 0.08), force(10.0, -20.0, 35.0), torque(1.0, 2.0, -0.5);
  for (std::size_t count = 1; count <= all.size(); ++count) {
    const std::vector<SloshTankParams> tanks(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(count));
    std::vector<SloshState> states;
    for (std::size_t i = 0; i < count; ++i) {
      const double k = static_cast<double>(i + 1);
      states.push_back({Vec3(0.05 * k, -0.03, 0.02 * k), Vec3(-0.01, 0.02 * k, 0.005)});  // projected by both
    }
    const SloshAccelerations fast = coupled_accelerations(body, tanks, states, omega, force, torque);
    const SloshAccelerations ref = reference_accelerations(body, tanks, states, omega, force, torque);
    const double a_scale = force.norm() / body.mass_kg, w_scale = ref.omega_dot_body_radps2.norm();
    EXPECT_LT((fast.a_com_body_mps2 - ref.a_com_body_mps2).norm(), 1e-12 * a_scale) << count << " tanks";
    EXPECT_LT((fast.omega_dot_body_radps2 - ref.omega_dot_body_radps2).norm(), 1e-12 * w_scale) << count;
    for (std::size_t i = 0; i < count; ++i) {
      EXPECT_LT((fast.s_ddot_body_mps2[i] - ref.s_ddot_body_mps2[i]).norm(),
                1e-12 * ref.s_ddot_body_mps2[i].norm()) << count << " tanks, tank " << i;
      EXPECT_NEAR(fast.axial_force_N[i], ref.axial_force_N[i], 1e-12 * force.norm()) << count << ", " << i;
    }
    for (std::size_t i = count; i < kMaxSloshTanks; ++i) EXPECT_EQ(fast.axial_force_N[i], 0.0);
  }
}

}  // namespace slosh_test
}  // namespace chaser::model
