#include "control/loop_margins.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace chaser::control {
namespace loop_margins_test {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = 180.0 / kPi;

// k / (s + 1)^3 as three first-order lags in series.
StateSpace triple_lag(double k) {
  StateSpace g;
  g.a = Eigen::MatrixXd::Zero(3, 3);
  g.a(0, 0) = g.a(1, 1) = g.a(2, 2) = -1.0;
  g.a(1, 0) = g.a(2, 1) = 1.0;
  g.b = Eigen::MatrixXd::Zero(3, 1);
  g.b(0, 0) = 1.0;
  g.c = Eigen::MatrixXd::Zero(1, 3);
  g.c(0, 2) = k;
  g.d = Eigen::MatrixXd::Zero(1, 1);
  return g;
}

// 1 / (s (s + a)): x1' = x2, x2' = -a x2 + u, y = x1.
StateSpace integrator_lag(double a) {
  StateSpace g;
  g.a = (Eigen::MatrixXd(2, 2) << 0.0, 1.0, 0.0, -a).finished();
  g.b = (Eigen::MatrixXd(2, 1) << 0.0, 1.0).finished();
  g.c = (Eigen::MatrixXd(1, 2) << 1.0, 0.0).finished();
  g.d = Eigen::MatrixXd::Zero(1, 1);
  return g;
}

StateSpace integrator() {
  return StateSpace{Eigen::MatrixXd::Zero(1, 1), Eigen::MatrixXd::Ones(1, 1), Eigen::MatrixXd::Ones(1, 1),
                    Eigen::MatrixXd::Zero(1, 1)};
}

// The bisections stop at 1e-12 in ln w; the figures are smooth in w, so 1e-9 relative is far above
// what they leave and far below any error of method (a wrong crossing is off by percent).
constexpr double kRel = 1e-9;

TEST(LoopMargins, TripleLagMatchesTheClosedForms) {
  // L = 2 / (s + 1)^3: phase -180 deg at w = sqrt(3), |L| = 2 / 8 there: GM = 4.
  // |L| = 1 at (w^2 + 1)^(3/2) = 2: w_c = sqrt(2^(2/3) - 1), PM = 180 deg - 3 atan(w_c).
  const LoopMargins m = loop_margins({triple_lag(2.0), static_gain(Eigen::MatrixXd::Ones(1, 1)), 0.0}, 1e-3, 1e3);
  const double wc = std::sqrt(std::pow(2.0, 2.0 / 3.0) - 1.0);
  EXPECT_NEAR(m.gain_margin_up, 4.0, 4.0 * kRel);
  EXPECT_NEAR(m.phase_crossover_radps, std::sqrt(3.0), std::sqrt(3.0) * kRel);
  EXPECT_NEAR(m.gain_crossover_radps, wc, wc * kRel);
  EXPECT_NEAR(m.phase_margin_deg, 180.0 - 3.0 * std::atan(wc) * kDeg, 1e-7);
  EXPECT_EQ(m.gain_margin_down, 0.0);  // |L| < 1 at every phase crossover
}

TEST(LoopMargins, IntegratorWithLagHasInfiniteGainMargin) {
  // L = 1 / (s (s + 1)): the phase tends to -180 deg but never reaches it; |L| = 1 at
  // w^2 (w^2 + 1) = 1, w_c^2 = (sqrt(5) - 1) / 2; PM = 90 deg - atan(w_c).
  const LoopMargins m =
      loop_margins({integrator_lag(1.0), static_gain(Eigen::MatrixXd::Ones(1, 1)), 0.0}, 1e-4, 1e4);
  const double wc = std::sqrt((std::sqrt(5.0) - 1.0) / 2.0);
  EXPECT_TRUE(std::isinf(m.gain_margin_up));
  EXPECT_NEAR(m.gain_crossover_radps, wc, wc * kRel);
  EXPECT_NEAR(m.phase_margin_deg, 90.0 - std::atan(wc) * kDeg, 1e-7);
}

TEST(LoopMargins, ExactDelayOnAnIntegrator) {
  // L = e^{-s tau} / s: w_c = 1, PM = 90 deg - tau [rad], delay margin = PM [rad] / 1;
  // phase -180 deg at w = pi / (2 tau), where |L| = 2 tau / pi: GM = pi / (2 tau).
  const double tau = 0.3;
  const LoopMargins m = loop_margins({integrator(), static_gain(Eigen::MatrixXd::Ones(1, 1)), tau}, 1e-3, 1e3);
  EXPECT_NEAR(m.gain_crossover_radps, 1.0, kRel);
  EXPECT_NEAR(m.phase_margin_deg, 90.0 - tau * kDeg, 1e-7);
  EXPECT_NEAR(m.delay_margin_s, kPi / 2.0 - tau, 1e-9);
  EXPECT_NEAR(m.gain_margin_up, kPi / (2.0 * tau), kPi / (2.0 * tau) * kRel);
  EXPECT_NEAR(m.phase_crossover_radps, kPi / (2.0 * tau), kPi / (2.0 * tau) * kRel);
}

TEST(LoopMargins, PeaksAndBandwidthOfAFirstOrderLoop) {
  // L = 1 / s: S = s / (s + 1), T = 1 / (s + 1). |S| = w / sqrt(w^2 + 1) reaches 1/sqrt(2) at w = 1;
  // M_S -> 1 from below at high frequency, M_T -> 1 at low frequency (both suprema, at the ends).
  const LoopMargins m = loop_margins({integrator(), static_gain(Eigen::MatrixXd::Ones(1, 1)), 0.0}, 1e-3, 1e3);
  EXPECT_NEAR(m.bandwidth_radps, 1.0, kRel);
  EXPECT_NEAR(m.sensitivity_peak, 1e3 / std::sqrt(1e6 + 1.0), 1e-12);
  EXPECT_NEAR(m.complementary_peak, 1.0 / std::sqrt(1e-6 + 1.0), 1e-12);
}

TEST(LoopMargins, MarginsRespectTheSensitivityPeakBounds) {
  // S&P eqs. 2.40-2.41: GM >= M_S / (M_S - 1), PM >= 2 arcsin(1 / (2 M_S)), on loops with a
  // resonant sensitivity: L = k / (s + 1)^3 for several k.
  for (const double k : {1.0, 2.0, 4.0, 6.0}) {
    const LoopMargins m =
        loop_margins({triple_lag(k), static_gain(Eigen::MatrixXd::Ones(1, 1)), 0.0}, 1e-3, 1e3);
    const double ms = m.sensitivity_peak;
    ASSERT_GT(ms, 1.0) << k;
    EXPECT_GE(m.gain_margin_up, ms / (ms - 1.0) * (1.0 - 1e-9)) << k;
    if (std::isfinite(m.phase_margin_deg)) {
      EXPECT_GE(m.phase_margin_deg, 2.0 * std::asin(1.0 / (2.0 * ms)) * kDeg - 1e-7) << k;
    }
  }
}

TEST(LoopMargins, LowFrequencyPhaseCrossoverIsADownwardMargin) {
  // A double integrator under lead control: L = 4 (s + 0.5) / (s^2 (s + 2)), arg L = -180 deg +
  // atan(w / 0.5) - atan(w / 2) > -180 deg for every w > 0: no phase crossover, no gain margin.
  StateSpace g;
  g.a = (Eigen::MatrixXd(3, 3) << 0, 1, 0, 0, 0, 1, 0, 0, -2).finished();  // 1 / (s^2 (s + 2))
  g.b = (Eigen::MatrixXd(3, 1) << 0, 0, 1).finished();
  g.c = (Eigen::MatrixXd(1, 3) << 2.0, 4.0, 0.0).finished();  // numerator 4 s + 2 = 4 (s + 0.5)
  g.d = Eigen::MatrixXd::Zero(1, 1);
  const LoopMargins lead = loop_margins({g, static_gain(Eigen::MatrixXd::Ones(1, 1)), 0.0}, 1e-4, 1e4);
  EXPECT_TRUE(std::isinf(lead.gain_margin_up));
  EXPECT_EQ(lead.gain_margin_down, 0.0);
  // A lag K = (s + 0.01) / (s + 0.005) takes up to 19.5 deg near w = 0.007 rad/s, where the lead has
  // given back 0.8 deg: arg L dips below -180 deg where |L| >> 1, a downward margin in (0, 1); the
  // upward one stays unbounded.
  const StateSpace lag{Eigen::MatrixXd::Constant(1, 1, -0.005), Eigen::MatrixXd::Ones(1, 1),
                       Eigen::MatrixXd::Constant(1, 1, 0.005), Eigen::MatrixXd::Ones(1, 1)};  // 1 + 0.005 / (s + 0.005)
  const LoopMargins lagged = loop_margins({g, lag, 0.0}, 1e-5, 1e4);
  EXPECT_GT(lagged.gain_margin_down, 0.0);
  EXPECT_LT(lagged.gain_margin_down, 1e-2);  // |L| > 100 at 0.01 rad/s and below
  EXPECT_TRUE(std::isinf(lagged.gain_margin_up));
}

TEST(LoopMargins, RefusesBadInput) {
  const StateSpace one = static_gain(Eigen::MatrixXd::Ones(1, 1));
  EXPECT_THROW(loop_margins({static_gain(Eigen::MatrixXd::Ones(2, 1)), one, 0.0}, 1e-3, 1e3), std::invalid_argument);
  EXPECT_THROW(loop_margins({integrator(), one, -1.0}, 1e-3, 1e3), std::invalid_argument);
  EXPECT_THROW(loop_margins({integrator(), one, 0.0}, 1e3, 1e-3), std::invalid_argument);
  EXPECT_THROW(loop_margins({integrator(), one, 0.0}, 0.0, 1e3), std::invalid_argument);
}

}  // namespace loop_margins_test
}  // namespace chaser::control
