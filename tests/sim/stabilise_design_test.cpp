// The stabilisation's H-infinity loops as comrade_capture designs them (control/composite_design.hpp):
// the couple's authority is the thrusters' pure couple about the weakest body axis (checked against
// the attainable set directly), each loop meets its margins on the angular impulse's double
// integrator with the exact delay, and stays stable over the robustness grid of a momentum estimated
// with the inertia 20 % off (a measurement gain in [0.8, 1.2] times the thrust's 1 %) and the
// valves' delay range.
#include "control/composite_design.hpp"

#include <gtest/gtest.h>

#include "control/loop_mu.hpp"
#include "control/six_axis_design.hpp"
#include "io/scenario_loader.hpp"
#include "model/recovery.hpp"
#include "model/thruster_geometry.hpp"
#include "model/thruster_set_analysis.hpp"

namespace chaser::control {
namespace {

model::Scenario capture_with_hinf_stabilisation() {
  const io::LoadResult loaded =
      io::load_scenario_file("scenarios/comrade_capture.yaml", {"capture.stabilise.law=hinf"});
  EXPECT_TRUE(loaded.scenario.has_value()) << io::format_errors(loaded.errors);
  return *loaded.scenario;
}

TEST(CompositeDesign, TheAuthorityIsThePureCoupleAboutTheWeakestBodyAxis) {
  const model::Scenario s = capture_with_hinf_stabilisation();
  const auto specs = composite_specs(s);
  const model::AttainableAxes axes = model::attainable_axes(model::configuration_columns(
      s.thrusters, model::initial_configuration(s.thrusters).active, s.chaser.com_body_m));
  double weakest = 1e300;
  for (int k = 6; k < 12; ++k) weakest = std::min(weakest, axes.value[static_cast<std::size_t>(k)]);
  for (const AxisDesignSpec& spec : specs) {
    EXPECT_EQ(spec.authority, weakest);
    EXPECT_EQ(spec.delay_s, loop_delay_s(s));
    EXPECT_EQ(spec.error_scale, 2000.0);
  }
  EXPECT_GT(weakest, 20.0);  // tens of N m: the 300 s reference asks ~30
}

TEST(CompositeDesign, EachLoopMeetsItsMarginsAndStaysStableOverTheGrid) {
  const model::Scenario s = capture_with_hinf_stabilisation();
  const AxisDesign design = design_axis(composite_specs(s)[0]);  // the three are alike
  ASSERT_TRUE(design.ok()) << design.synthesis.message;
  EXPECT_GT(design.margins.phase_margin_deg, 30.0);
  EXPECT_GT(design.margins.gain_margin_up, 2.0);  // 6 dB
  EXPECT_LT(design.margins.gain_margin_down, 0.5);
  const RobustnessResult grid = robust_stability_grid(design, composite_uncertainty(s, 0.2));
  EXPECT_LT(grid.worst_max_real_pole, 0.0);
  EXPECT_GT(grid.min_phase_margin_deg, 20.0);
}

// And by the structured singular value, as the synchronisation's loops are (control/loop_mu.hpp):
// the box of the inertia 20 % off and the valves' delays, gain real, delay a covering disk; the
// mixed bound's margin above 1 guarantees stability over the whole box, not only its grid points.
TEST(CompositeDesign, TheMuBoundGuaranteesTheBox) {
  const model::Scenario s = capture_with_hinf_stabilisation();
  const AxisDesign design = design_axis(composite_specs(s)[0]);
  const LoopMu mu = loop_mu(design, composite_uncertainty(s, 0.2));
  ASSERT_TRUE(mu.ok()) << mu.message;
  EXPECT_GT(mu.margin_mixed(), 1.0);  // measured 4.77 (complex 4.77): the box may grow 4.8-fold
  EXPECT_GE(mu.margin_mixed(), mu.margin_complex());  // the mixed bound is never above the complex one
}

}  // namespace
}  // namespace chaser::control
