#include "control/axis_design.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

#include "control/frequency_response.hpp"

namespace chaser::control {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

// The ENVISAT servicer's translation loop (docs/control.md, "Six-axis design"): 0.05 m/s^2 of
// authority, a 0.1 s delay, omega_B 0.05 rad/s, M = 2, A = 1e-3, 1 m of error for the authority.
AxisDesignSpec translation_spec() {
  return AxisDesignSpec{.name = "x", .authority = 0.05, .delay_s = 0.1, .bandwidth_radps = 0.05,
                        .peak_sensitivity = 2.0, .low_frequency_gain = 1e-3, .error_scale = 1.0};
}

TEST(AxisDesign, PadeIsAllPassWithTheClosedFormPhase) {
  // |(1 - j w tau/2) / (1 + j w tau/2)| = 1 and arg = -2 atan(w tau / 2), to rounding; it follows
  // e^{-j w tau} to (w tau)^3 / 12 in phase.
  const double tau = 0.2;
  const StateSpace p = pade_delay(tau);
  for (const double w : {1e-3, 0.1, 1.0, 5.0, 30.0}) {
    const std::complex<double> h = frequency_response(p, w)(0, 0);
    EXPECT_NEAR(std::abs(h), 1.0, 1e-14) << w;
    EXPECT_NEAR(std::arg(h), -2.0 * std::atan(w * tau / 2.0), 1e-14) << w;
    if (w * tau < 0.5) {
      EXPECT_NEAR(std::arg(h), -w * tau, std::pow(w * tau, 3) / 12.0 * 1.01 + 1e-15) << w;
    }
  }
  EXPECT_EQ(pade_delay(0.0).states(), 0);
}

TEST(AxisDesign, DelayedDoubleIntegratorResponse) {
  // G(jw) = e^{-jw tau} / (jw + eps)^2 with the Pade delay: magnitude 1 / (w^2 + eps^2).
  const double tau = 0.1, eps = 1e-4;
  const StateSpace g = delayed_double_integrator(tau, eps);
  for (const double w : {1e-3, 0.05, 1.0, 10.0}) {
    const std::complex<double> h = frequency_response(g, w)(0, 0);
    const std::complex<double> expected = frequency_response(pade_delay(tau), w)(0, 0) /
                                          ((std::complex<double>(eps, w)) * std::complex<double>(eps, w));
    EXPECT_NEAR(std::abs(h - expected), 0.0, 1e-12 * std::abs(expected)) << w;
  }
}

TEST(AxisDesign, TranslationLoopMeetsItsGammaAndStabilisesTheTruePlant) {
  const AxisDesign d = design_axis(translation_spec());
  ASSERT_TRUE(d.synthesis.ok()) << d.synthesis.message;
  // The controller is formed at gamma = 1.01 times the bisection's threshold: the achieved norm
  // (the independent sweep) lies between the optimum, no lower than the threshold less its tol,
  // and gamma.
  const double gamma = d.synthesis.gamma;
  EXPECT_DOUBLE_EQ(gamma, kAxisGammaBackoff * d.gamma_threshold);
  EXPECT_LE(d.closed_loop_norm, gamma * (1.0 + 1e-9));
  EXPECT_GE(d.closed_loop_norm, d.gamma_threshold * (1.0 - kAxisGammaRelTol));
  EXPECT_LT(d.max_real_pole_design, 0.0);
  EXPECT_LT(d.max_real_pole, 0.0);  // the true double integrator, Pade delay
  EXPECT_TRUE(d.ok());
  // Margins against the peak (S&P eqs. 2.40-2.41), and the bandwidth near omega_B.
  const LoopMargins& m = d.margins;
  EXPECT_GE(m.gain_margin_up, m.sensitivity_peak / (m.sensitivity_peak - 1.0) * (1.0 - 1e-9));
  EXPECT_GE(m.phase_margin_deg, 2.0 * std::asin(1.0 / (2.0 * m.sensitivity_peak)) * kDeg - 1e-7);
  EXPECT_GT(m.bandwidth_radps, 0.2 * d.spec.bandwidth_radps);
  EXPECT_LT(m.bandwidth_radps, 5.0 * d.spec.bandwidth_radps);
  // |S| stays under gamma / |W_S| at its peak (the synthesis bound, read on the true plant).
  const double ws_at_peak = std::abs(frequency_response(*d.weights.w_s, m.sensitivity_peak_radps)(0, 0));
  EXPECT_LE(m.sensitivity_peak * ws_at_peak, gamma * 1.01);
}

TEST(AxisDesign, MoreAuthorityBuysBandwidth) {
  // W_KS = error_scale / authority: with ten times the authority the same |K S| bound is ten times
  // looser and gamma can only fall.
  AxisDesignSpec spec = translation_spec();
  const AxisDesign weak = design_axis(spec);
  spec.authority *= 10.0;
  const AxisDesign strong = design_axis(spec);
  ASSERT_TRUE(weak.ok() && strong.ok());
  EXPECT_LE(strong.synthesis.gamma, weak.synthesis.gamma * (1.0 + 2.0 * kAxisGammaRelTol));
}

TEST(AxisDesign, RefusesBadSpecsNamingEveryProblem) {
  AxisDesignSpec spec = translation_spec();
  spec.authority = 0.0;
  spec.peak_sensitivity = 1.0;
  spec.low_frequency_gain = 1.0;
  try {
    design_axis(spec);
    FAIL() << "accepted a bad spec";
  } catch (const std::invalid_argument& e) {
    const std::string text = e.what();
    EXPECT_NE(text.find("authority"), std::string::npos) << text;
    EXPECT_NE(text.find("peak_sensitivity"), std::string::npos) << text;
    EXPECT_NE(text.find("low_frequency_gain"), std::string::npos) << text;
  }
}

}  // namespace
}  // namespace chaser::control
