#include "control/frequency_response.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace chaser::control {
namespace {

using Eigen::MatrixXd;

// k / (tau s + 1): a = -1/tau, b = 1, c = k/tau.
StateSpace first_order(double gain, double tau_s) {
  return StateSpace{MatrixXd::Constant(1, 1, -1.0 / tau_s), MatrixXd::Constant(1, 1, 1.0),
                    MatrixXd::Constant(1, 1, gain / tau_s), MatrixXd::Zero(1, 1)};
}

// omega_n^2 / (s^2 + 2 zeta omega_n s + omega_n^2), controllable canonical form.
StateSpace second_order(double omega_n_radps, double zeta) {
  StateSpace g;
  g.a.resize(2, 2);
  g.a << 0.0, 1.0, -omega_n_radps * omega_n_radps, -2.0 * zeta * omega_n_radps;
  g.b = (MatrixXd(2, 1) << 0.0, 1.0).finished();
  g.c = (MatrixXd(1, 2) << omega_n_radps * omega_n_radps, 0.0).finished();
  g.d = MatrixXd::Zero(1, 1);
  return g;
}

// 1e-12 relative: each value is one 1x1 or 2x2 complex LU solve and a product, a few roundings of
// relative size eps = 2.2e-16 amplified by cond(j omega I - A), which stays below ~1e2 here
// (zeta = 0.3); the closed forms are a handful of operations. Measured worst: printed below.
constexpr double kClosedFormTolerance = 1e-12;

TEST(FrequencyResponse, FirstOrderMatchesClosedForm) {
  const double gain = 3.0, tau_s = 0.7;
  const StateSpace g = first_order(gain, tau_s);
  double worst = 0.0;
  for (double omega : log_grid(1e-4, 1e4, 161)) {
    const double expected = gain / std::sqrt(1.0 + omega * tau_s * omega * tau_s);
    const double relative = std::abs(sigma_max(g, omega) - expected) / expected;
    worst = std::max(worst, relative);
    EXPECT_LE(relative, kClosedFormTolerance) << "omega = " << omega;
  }
  std::printf("first order: worst relative error %.2e\n", worst);
}

TEST(FrequencyResponse, SecondOrderMatchesClosedForm) {
  const double omega_n = 2.5, zeta = 0.3;
  const StateSpace g = second_order(omega_n, zeta);
  double worst = 0.0;
  for (double omega : log_grid(1e-3, 1e3, 241)) {
    const double wn2 = omega_n * omega_n;
    const double expected =
        wn2 / std::sqrt((wn2 - omega * omega) * (wn2 - omega * omega) + 4.0 * zeta * zeta * wn2 * omega * omega);
    const double relative = std::abs(sigma_max(g, omega) - expected) / expected;
    worst = std::max(worst, relative);
    EXPECT_LE(relative, kClosedFormTolerance) << "omega = " << omega;
  }
  std::printf("second order: worst relative error %.2e\n", worst);
}

// The peak of a lightly damped second-order system is 1 / (2 zeta sqrt(1 - zeta^2)), at
// omega_n sqrt(1 - 2 zeta^2). Tolerance 1e-12 relative: the golden section brackets the peak's
// omega to 1e-10 relative, which costs ~(1e-10)^2 / zeta^2 <= 1e-14 in the norm at zeta = 1e-3
// (the peak's curvature grows as 1 / zeta^2); what is left is the rounding of one evaluation near
// the resonance, ~cond(j omega I - A) eps ~ eps / zeta ~ 2e-13. Measured: <= 2e-16 (printed).
TEST(FrequencyResponse, NormOfLightlyDampedSecondOrderIsItsResonancePeak) {
  for (double zeta : {0.2, 0.05, 0.01, 1e-3}) {
    const double omega_n = 7.0;
    const HinfNormEstimate est = hinf_norm_estimate(second_order(omega_n, zeta));
    const double expected = 1.0 / (2.0 * zeta * std::sqrt(1.0 - zeta * zeta));
    const double relative = std::abs(est.norm - expected) / expected;
    std::printf("zeta %.0e: norm %.15g, closed form %.15g, relative %.1e, omega %.12g (expected %.12g), "
                "%d evaluations\n",
                zeta, est.norm, expected, relative, est.omega_peak_radps, omega_n * std::sqrt(1.0 - 2.0 * zeta * zeta),
                est.evaluations);
    EXPECT_LE(relative, 1e-12) << "zeta = " << zeta;
  }
}

// The D term and DC count: a high-pass with feedthrough 2 has its supremum at omega -> inf, a
// low-pass its at omega = 0. Exact to rounding (1e-14).
TEST(FrequencyResponse, NormIncludesBothEndsOfTheAxis) {
  const StateSpace high_pass{MatrixXd::Constant(1, 1, -1.0), MatrixXd::Constant(1, 1, 1.0),
                             MatrixXd::Constant(1, 1, -1.0), MatrixXd::Constant(1, 1, 2.0)};  // (2s + 1)/(s + 1)
  EXPECT_NEAR(hinf_norm_estimate(high_pass).norm, 2.0, 1e-14);
  EXPECT_NEAR(hinf_norm_estimate(first_order(4.0, 3.0)).norm, 4.0, 1e-14);
}

TEST(FrequencyResponse, PolesAreTheEigenvaluesOfA) {
  const Eigen::VectorXcd p = poles(second_order(2.0, 0.5));
  ASSERT_EQ(p.size(), 2);
  EXPECT_NEAR(p(0).real(), -1.0, 1e-14);
  EXPECT_NEAR(std::abs(p(0).imag()), std::sqrt(3.0), 1e-14);
  EXPECT_NEAR(max_real_pole(second_order(2.0, 0.5)), -1.0, 1e-14);
}

}  // namespace
}  // namespace chaser::control
