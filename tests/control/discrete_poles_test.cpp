#include "control/discrete_poles.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "core/linear_models.hpp"
#include "core/riccati.hpp"

namespace chaser::control {
namespace {

constexpr double kT = 0.1;  // [s] MSR's control period

// The continuous LQR of a double integrator m x'' = u with weights q_pos, q_vel, r closes the loop at
// w_n^2 = sqrt(q_pos / r) / m and (2 zeta w_n)^2 = q_vel / (r m^2) + 2 w_n^2 (docs/gnc.md).
struct SecondOrder {
  double natural_radps;
  double damping;
};
SecondOrder continuous_double_integrator(double q_pos, double q_vel, double r, double mass) {
  const double wn2 = std::sqrt(q_pos / r) / mass;
  const double wn = std::sqrt(wn2);
  return {wn, std::sqrt(q_vel / (r * mass * mass) + 2.0 * wn2) / (2.0 * wn)};
}

Eigen::MatrixXd lqr_gain(const DiscreteLinear6& m, const Eigen::MatrixXd& b, double q_pos, double q_vel, double r) {
  Vec6 q;
  q << Vec3::Constant(q_pos), Vec3::Constant(q_vel);
  return dlqr(m.Ad, b, Mat6(q.asDiagonal()), r * Mat3::Identity()).K;
}

// A scalar loop whose pole is z = 0.9: s = ln 0.9 / T, real, so zeta = 1 and 1 / (zeta w_n) = -T / ln 0.9.
TEST(DiscreteLoopPoles, ARealPoleReadsAsItsLogarithm) {
  const Eigen::MatrixXd a = Eigen::MatrixXd::Constant(1, 1, 1.0), b = Eigen::MatrixXd::Constant(1, 1, 0.5),
                        k = Eigen::MatrixXd::Constant(1, 1, 0.2);
  const DiscreteLoopPoles p = discrete_loop_poles(a, b, k, kT);
  ASSERT_TRUE(p.stable());
  ASSERT_EQ(p.poles.size(), 1u);
  EXPECT_NEAR(p.poles[0].s.real(), std::log(0.9) / kT, 1e-14);
  EXPECT_EQ(p.poles[0].s.imag(), 0.0);
  EXPECT_NEAR(p.poles[0].damping, 1.0, 1e-15);
  EXPECT_NEAR(p.poles[0].time_constant_s, -kT / std::log(0.9), 1e-13);
}

// MSR's attitude loop (docs/gnc.md's weights, inertia diag(2000, 2500, 3000) kg m^2): each axis is a
// double integrator in its moment, so the discrete LQR's three pole pairs are the continuous closed
// form's, one per axis, up to the ZOH's O((w_n T)^2) (2.7e-4 for the fastest axis, 0.165 rad/s x
// 0.1 s; scipy's DARE on the same model agrees to 1e-5): tolerance 5e-4 relative.
TEST(DiscreteLoopPoles, TheAttitudeLqrClosesAtTheDoubleIntegratorsClosedForm) {
  const Vec3 moments(2000.0, 2500.0, 3000.0);
  const DiscreteLinear6 m = discrete_attitude(moments.asDiagonal(), kT);
  const DiscreteLoopPoles p = discrete_loop_poles(m.Ad, m.Bd, lqr_gain(m, m.Bd, 3000.0, 1.7e5, 1.0), kT);
  ASSERT_TRUE(p.stable());
  ASSERT_EQ(p.poles.size(), 3u);  // three complex pairs, each listed once
  for (int k = 0; k < 3; ++k) {
    const double moment = moments(2 - k);  // slowest first: the largest moment's axis
    const SecondOrder expected = continuous_double_integrator(3000.0, 1.7e5, 1.0, moment);
    const LoopPole& pole = p.poles[static_cast<std::size_t>(k)];
    EXPECT_NEAR(pole.natural_radps, expected.natural_radps, 5e-4 * expected.natural_radps) << moment;
    EXPECT_NEAR(pole.damping, expected.damping, 5e-4 * expected.damping) << moment;
    EXPECT_NEAR(pole.time_constant_s, 1.0 / (pole.damping * pole.natural_radps), 1e-12 * pole.time_constant_s);
  }
}

// MSR's position loop (2,500 kg): without an orbit rate the closed form, as the attitude's; on MSR's
// orbit (n = 8.5e-4 rad/s) HCW couples x and z through 2 n, and the poles stay within 2 n of it.
TEST(DiscreteLoopPoles, ThePositionLqrIsTheDoubleIntegratorsShiftedByTheOrbitRate) {
  constexpr double kMass = 2500.0, kN = 8.532e-4;
  const SecondOrder expected = continuous_double_integrator(16.0, 12000.0, 1.0, kMass);
  for (const double n : {0.0, kN}) {
    const DiscreteLinear6 m = discrete_hcw(n, kT);
    const Eigen::MatrixXd b = m.Bd / kMass;  // the design's input is force
    const DiscreteLoopPoles p = discrete_loop_poles(m.Ad, b, lqr_gain(m, b, 16.0, 12000.0, 1.0), kT);
    ASSERT_TRUE(p.stable());
    ASSERT_EQ(p.poles.size(), 3u);
    for (const LoopPole& pole : p.poles) {
      if (n == 0.0) {
        EXPECT_NEAR(pole.natural_radps, expected.natural_radps, 5e-4 * expected.natural_radps) << pole.s;
        EXPECT_NEAR(pole.damping, expected.damping, 5e-4 * expected.damping) << pole.s;
      } else {
        EXPECT_NEAR(pole.natural_radps, expected.natural_radps, 2.0 * n) << pole.s;
        EXPECT_GT(pole.damping, 0.85) << pole.s;
      }
    }
  }
}

// A gain of the wrong sign is reported unstable; mismatched sizes are refused.
TEST(DiscreteLoopPoles, AnUnstableLoopIsReportedAndBadSizesRefused) {
  const DiscreteLinear6 m = discrete_attitude(Vec3(2000.0, 2500.0, 3000.0).asDiagonal(), kT);
  const Eigen::MatrixXd k = lqr_gain(m, m.Bd, 3000.0, 1.7e5, 1.0);
  EXPECT_FALSE(discrete_loop_poles(m.Ad, m.Bd, -k, kT).stable());
  EXPECT_THROW(discrete_loop_poles(m.Ad, m.Bd, k.transpose(), kT), std::invalid_argument);
  EXPECT_THROW(discrete_loop_poles(m.Ad, m.Bd, k, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace chaser::control
