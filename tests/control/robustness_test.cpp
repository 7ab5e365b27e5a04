#include "control/robustness.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <stdexcept>

#include "control/frequency_response.hpp"
#include "control/six_axis_design.hpp"

namespace chaser::control {
namespace {

AxisDesign translation_design() {
  return design_axis(AxisDesignSpec{.name = "x", .authority = 0.055, .delay_s = 0.0625, .bandwidth_radps = 0.04,
                                    .peak_sensitivity = 2.0, .low_frequency_gain = 1e-3, .error_scale = 0.5});
}

// F(s) against the two-mass system it stands for: m s^2 x_b / F with x_b / F = (m_m s^2 + c s + k) /
// (s^2 (m_b m_m s^2 + m (c s + k))), c = 2 zeta m_m omega_z, to rounding.
TEST(Robustness, ModeFactorIsTheTwoMassSystem) {
  const double m_b = 1400.0, m_m = 194.0, k = m_m * 0.12 * 0.12, zeta = 0.02, m = m_b + m_m;
  const double c = 2.0 * zeta * m_m * 0.12;
  const StateSpace f = mode_factor(0.12, m_m / m, zeta);
  for (const double w : {1e-4, 0.05, 0.12, 0.128, 0.2, 3.0, 100.0}) {
    const std::complex<double> s(0.0, w);
    const std::complex<double> physical = m * (m_m * s * s + c * s + k) / (m_b * m_m * s * s + m * (c * s + k));
    const std::complex<double> model = frequency_response(f, w)(0, 0);
    EXPECT_NEAR(std::abs(model - physical), 0.0, 1e-12 * std::abs(physical)) << w;
  }
  EXPECT_NEAR(std::abs(frequency_response(f, 1e-9)(0, 0)), 1.0, 1e-12);       // the whole mass
  EXPECT_NEAR(std::abs(frequency_response(f, 1e6)(0, 0)), m / m_b, 1e-6);      // the body alone
}

// The grid's pole verdicts agree with the nominal loop's gain margin: a gain box up to half the
// margin is stable everywhere, one up to twice the margin is not, and its worst point is the top.
TEST(Robustness, GainBoxAgreesWithTheGainMargin) {
  const AxisDesign d = translation_design();
  ASSERT_TRUE(d.ok());
  const double gm = d.margins.gain_margin_up;
  ASSERT_TRUE(std::isfinite(gm));
  AxisUncertainty box{.gain_lo = 1.0, .gain_hi = 0.5 * gm, .delay_lo_s = 0.0625, .delay_hi_s = 0.0625, .modes = {}};
  const RobustnessResult safe = robust_stability_grid(d, box);
  EXPECT_EQ(safe.points, 5);
  EXPECT_TRUE(safe.robustly_stable());
  EXPECT_GT(safe.min_gain_margin_up, 1.9);  // the margin left at k = gm / 2, ~2
  box.gain_hi = 2.0 * gm;
  const RobustnessResult unsafe = robust_stability_grid(d, box);
  EXPECT_GT(unsafe.unstable, 0);
  EXPECT_DOUBLE_EQ(unsafe.worst_pole_point.gain, 2.0 * gm);
}

// The nominal point alone reproduces the design's own figures.
TEST(Robustness, NominalPointIsTheDesign) {
  const AxisDesign d = translation_design();
  const AxisUncertainty box{.gain_lo = 1.0, .gain_hi = 1.0, .delay_lo_s = 0.0625, .delay_hi_s = 0.0625, .modes = {}};
  const RobustnessResult r = robust_stability_grid(d, box);
  EXPECT_EQ(r.points, 1);
  EXPECT_NEAR(r.worst_max_real_pole, d.max_real_pole, 1e-12);
  EXPECT_NEAR(r.min_phase_margin_deg, d.margins.phase_margin_deg, 1e-9);
}

// ENVISAT's translation loop over its box: +-10 % gain, the valves' delay range, the propellant's
// slosh between 0.08 and 0.16 rad/s carrying 12 % of the mass: 5^3 points, all stable.
TEST(Robustness, EnvisatTranslationWithSloshIsStable) {
  const AxisDesign d = translation_design();
  const AxisUncertainty box{.gain_lo = 0.9, .gain_hi = 1.1, .delay_lo_s = 0.0525, .delay_hi_s = 0.0725,
                            .modes = {{"slosh", 0.08, 0.16, 0.12, 0.005}}};
  const RobustnessResult r = robust_stability_grid(d, box);
  EXPECT_EQ(r.points, 125);
  EXPECT_TRUE(r.robustly_stable());
  EXPECT_GT(r.min_phase_margin_deg, 29.0);  // S&P eq. 2.41's bound for the design's |S| < 2, kept across the box
}

// The scenario's box: the gain range from the mass and thrust knowledge, the delay over the valves'
// range, each family's modes.
TEST(Robustness, AxisBoxFromTheScenario) {
  model::Scenario s;
  s.control_period_s = 0.1;
  s.thrusters.delay_max_s = 0.02;
  s.thrusters.rise_time_s = 0.005;
  const model::HinfRobustnessParams box{.mass_uncertainty = 0.05, .thrust_uncertainty = 0.01, .points_per_range = 4,
                                        .translation_modes = {{"slosh", 0.05, 0.16, 0.12, 0.005}},
                                        .rotation_modes = {{"slosh", 0.05, 0.16, 0.03, 0.005}, {"arm", 6.0, 12.0, 0.05, 0.005}}};
  const AxisUncertainty x = axis_uncertainty(s, box, 0), rz = axis_uncertainty(s, box, 5);
  EXPECT_DOUBLE_EQ(x.gain_lo, 0.99 / 1.05);
  EXPECT_DOUBLE_EQ(x.gain_hi, 1.01 / 0.95);
  EXPECT_DOUBLE_EQ(x.delay_lo_s, 0.05 + 0.0025);
  EXPECT_DOUBLE_EQ(x.delay_hi_s, 0.05 + 0.0025 + 0.02);
  EXPECT_EQ(x.points_per_range, 4);
  ASSERT_EQ(x.modes.size(), 1u);
  EXPECT_EQ(x.modes[0].modal_fraction, 0.12);
  ASSERT_EQ(rz.modes.size(), 2u);
  EXPECT_EQ(rz.modes[1].name, "arm");
}

TEST(Robustness, RefusesABadBox) {
  const AxisDesign d = translation_design();
  AxisUncertainty box{.gain_lo = 2.0, .gain_hi = 1.0, .delay_lo_s = -1.0, .delay_hi_s = 0.0,
                      .modes = {{"arm", 5.0, 1.0, 1.5, 0.01}}};
  try {
    robust_stability_grid(d, box);
    FAIL() << "accepted a bad box";
  } catch (const std::invalid_argument& e) {
    const std::string text = e.what();
    EXPECT_NE(text.find("gain range"), std::string::npos) << text;
    EXPECT_NE(text.find("delay range"), std::string::npos) << text;
    EXPECT_NE(text.find("mode 'arm': frequency range"), std::string::npos) << text;
    EXPECT_NE(text.find("mode 'arm': modal_fraction"), std::string::npos) << text;
  }
}

}  // namespace
}  // namespace chaser::control
