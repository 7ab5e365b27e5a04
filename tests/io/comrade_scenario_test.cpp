// The COMRADE scenarios (issue 17): both load, their optional sections read into the model, and
// every new key reports a bad value at its key path with the allowed range, one error per problem.
#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "io/scenario_loader.hpp"
#include "scenario_test_util.hpp"

namespace chaser::io {
namespace comrade_scenario_test {

using testing::has_error;
constexpr const char* kEnvisat = "scenarios/comrade_envisat.yaml";
constexpr const char* kAssist = "scenarios/comrade_assist.yaml";

TEST(ComradeScenario, EnvisatLoadsWithItsEarthOrbitAndTumblingTarget) {
  const LoadResult r = load_scenario_file(kEnvisat, {});
  ASSERT_TRUE(r.errors.empty()) << format_errors(r.errors);
  const model::Scenario& s = *r.scenario;
  ASSERT_TRUE(s.orbit.earth.has_value());
  ASSERT_TRUE(s.target.body.has_value());
  EXPECT_EQ(s.orbit.earth->epoch_tt.year, 2027);
  EXPECT_EQ(s.orbit.earth->epoch_tt.hour, 12);
  EXPECT_NEAR(s.orbit.earth->inclination_rad, 98.4 * kDegToRad, 1e-15);
  EXPECT_EQ(s.orbit.earth->target.residual_dipole_body_Am2, Vec3(5.0, 5.0, 5.0));
  EXPECT_EQ(s.target.body->spin_case, model::SpinCase::s1);
  EXPECT_NEAR(s.target.body->spin_rate_radps, 2.5 * kDegToRad, 1e-15);
  EXPECT_EQ(s.target.body->inertia_kgm2(0, 2), -2171.4);
  EXPECT_EQ(s.thrusters.count, 24);
  EXPECT_TRUE(s.thrusters.tolerates_single_loss);  // validated: every 23 span
}

TEST(ComradeScenario, AssistLoadsAndSpinCasesOverride) {
  const LoadResult assist = load_scenario_file(kAssist, {});
  ASSERT_TRUE(assist.errors.empty()) << format_errors(assist.errors);
  EXPECT_EQ(assist.scenario->target.body->spin_case, model::SpinCase::given);
  EXPECT_FALSE(assist.scenario->orbit.earth->drag);
  for (const char* spin : {"S2", "S3", "given"}) {
    const LoadResult r = load_scenario_file(kEnvisat, {std::string("target.body.spin_case=") + spin});
    EXPECT_TRUE(r.errors.empty()) << spin << ": " << format_errors(r.errors);
  }
}

// control.allocation_norm: 1 (the default, Fonod 2015's least propellant), 2 or inf.
TEST(ComradeScenario, AllocationNormIsSelectable) {
  const LoadResult plain = load_scenario_file(kEnvisat, {});
  ASSERT_TRUE(plain.errors.empty()) << format_errors(plain.errors);
  EXPECT_EQ(plain.scenario->control.allocation_norm, model::AllocationNorm::kOne);
  const std::pair<const char*, model::AllocationNorm> norms[] = {
      {"1", model::AllocationNorm::kOne}, {"2", model::AllocationNorm::kTwo}, {"inf", model::AllocationNorm::kInfinity}};
  for (const auto& [text, norm] : norms) {
    const LoadResult r = load_scenario_file(kEnvisat, {std::string("control.allocation_norm=") + text});
    ASSERT_TRUE(r.errors.empty()) << text << ": " << format_errors(r.errors);
    EXPECT_EQ(r.scenario->control.allocation_norm, norm) << text;
  }
}

// The circular-orbit scenario has neither section and needs none.
TEST(ComradeScenario, MsrHasNoEarthOrbit) {
  const LoadResult r = testing::load_msr();
  ASSERT_TRUE(r.errors.empty());
  EXPECT_FALSE(r.scenario->orbit.earth.has_value());
  EXPECT_FALSE(r.scenario->target.body.has_value());
}

struct BadCase {
  const char* label;
  std::vector<std::string> overrides;  // applied to comrade_envisat.yaml
  const char* key_path;
  const char* fragment;
};

// clang-format off
const BadCase kBadCases[] = {
  {"epoch_text", {"orbit.earth.epoch_tt=tomorrow"}, "orbit.earth.epoch_tt", "must be a TT date and time 'YYYY-MM-DDThh:mm:ss' in years [1900, 2100] (got 'tomorrow')"},
  {"epoch_feb_30", {"orbit.earth.epoch_tt=2027-02-29T00:00:00"}, "orbit.earth.epoch_tt", "(got '2027-02-29T00:00:00')"},
  {"epoch_year", {"orbit.earth.epoch_tt=2150-01-01T00:00:00"}, "orbit.earth.epoch_tt", "in years [1900, 2100]"},
  {"epoch_trailing", {"orbit.earth.epoch_tt=2027-03-20T12:00:00Z"}, "orbit.earth.epoch_tt", "must be a TT date"},
  {"inclination", {"orbit.earth.inclination_deg=190"}, "orbit.earth.inclination_deg", "must be in [0, 180] (got 190)"},
  {"raan", {"orbit.earth.raan_deg=360"}, "orbit.earth.raan_deg", "must be in [0, 360) (got 360)"},
  {"j2", {"orbit.earth.j2=-1e-3"}, "orbit.earth.j2", "must be in [0, 0.01] (got -0.001)"},
  {"drag_text", {"orbit.earth.drag=maybe"}, "orbit.earth.drag", "must be true or false"},
  {"reflectivity", {"orbit.earth.chaser.reflectivity=3"}, "orbit.earth.chaser.reflectivity", "must be in [1, 2] (got 3)"},
  {"ballistic", {"orbit.earth.target.ballistic_coefficient_kgpm2=0"}, "orbit.earth.target.ballistic_coefficient_kgpm2", "must be in (0, 1000000] (got 0)"},
  {"dipole", {"orbit.earth.target.residual_dipole_body_Am2=[0,0,2e4]"}, "orbit.earth.target.residual_dipole_body_Am2.2", "must be in [-10000, 10000] (got 20000)"},
  {"not_earth_mu", {"orbit.mu_m3ps2=4.282837e13"}, "orbit.mu_m3ps2", "must be the Earth's, 3.986004418e14 (within 1e-6), with orbit.earth (got 42828370000000)"},
  {"not_earth_radius", {"orbit.body_radius_m=3389.5e3"}, "orbit.body_radius_m", "must be the Earth's, 6378137"},
  {"spin_case", {"target.body.spin_case=S4"}, "target.body.spin_case", "must be one of given, S1, S2, S3 (got 'S4')"},
  {"spin_rate", {"target.body.spin_rate_deg_s=45"}, "target.body.spin_rate_deg_s", "must be in [0, 30] (got 45)"},
  {"target_mass", {"target.body.mass_kg=0"}, "target.body.mass_kg", "must be > 0 (got 0)"},
  {"target_inertia", {"target.body.inertia_kgm2=[[1,0,0],[0,1,0],[0,0,3]]"}, "target.body.inertia_kgm2", "triangle inequality"},
  {"unknown_key", {"orbit.earth.j3=1e-6"}, "orbit.earth.j3", "unknown key"},
  {"g_eff", {"chaser.slosh.g_eff_mps2=0"}, "chaser.slosh.g_eff_mps2", "must be in (0, 10] (got 0)"},
  {"slosh_model", {"chaser.slosh.model=pendulm"}, "chaser.slosh.model", "must be one of spring_mass, pendulum (got 'pendulm')"},
  {"surface_tension", {"chaser.slosh.tanks=[{bottom_centre_body_m: [0,0,0], axis_body: [0,0,1], radius_m: 0.4, height_m: 0.9, liquid_mass_kg: 150, density_kgpm3: 1004, damping_ratio: 0.005, surface_tension_Npm: -0.1}]"}, "chaser.slosh.tanks.0.surface_tension_Npm", "must be in [0, 1] (got -0.1)"},
  {"no_tanks", {"chaser.slosh.tanks=[]"}, "chaser.slosh.tanks", "must be a list of 1 to 4 tanks"},
  {"tank_radius", {"chaser.slosh.tanks=[{bottom_centre_body_m: [0,0,0], axis_body: [0,0,1], radius_m: -0.4, height_m: 0.9, liquid_mass_kg: 150, density_kgpm3: 1004, damping_ratio: 0.005}]"}, "chaser.slosh.tanks.0.radius_m", "must be in (0, 10] (got -0.4)"},
  {"tank_damping", {"chaser.slosh.tanks=[{bottom_centre_body_m: [0,0,0], axis_body: [0,0,1], radius_m: 0.4, height_m: 0.9, liquid_mass_kg: 150, density_kgpm3: 1004, damping_ratio: 1}]"}, "chaser.slosh.tanks.0.damping_ratio", "must be in [0, 1) (got 1)"},
  {"tank_axis", {"chaser.slosh.tanks=[{bottom_centre_body_m: [0,0,0], axis_body: [0,0,0], radius_m: 0.4, height_m: 0.9, liquid_mass_kg: 150, density_kgpm3: 1004, damping_ratio: 0.005}]"}, "chaser.slosh.tanks.0.axis_body", "must be a nonzero direction [x, y, z] (got [0, 0, 0])"},
  {"overfull", {"chaser.slosh.tanks=[{bottom_centre_body_m: [0,0,0], axis_body: [0,0,1], radius_m: 0.45, height_m: 0.9, liquid_mass_kg: 1000, density_kgpm3: 1004, damping_ratio: 0.005}]"}, "chaser.slosh.tanks.0.liquid_mass_kg", "m of the tank, more than its height_m 0.9"},
  {"liquid_heavier_than_chaser", {"chaser.slosh.tanks=[{bottom_centre_body_m: [0,0,0], axis_body: [0,0,1], radius_m: 1.0, height_m: 1.0, liquid_mass_kg: 1700, density_kgpm3: 1004, damping_ratio: 0.005}]"}, "chaser.slosh.tanks", "hold 1700 kg of liquid: must be less than chaser.mass_kg 1600"},
  {"tanks_too_far", {"chaser.slosh.tanks=[{bottom_centre_body_m: [5,0,0], axis_body: [0,0,1], radius_m: 0.45, height_m: 0.9, liquid_mass_kg: 150, density_kgpm3: 1004, damping_ratio: 0.005}]"}, "chaser.slosh.tanks", "more than the smallest principal moment of chaser.inertia_kgm2 (1300)"},
  {"hinf_bandwidth", {"control.hinf.translation.bandwidth_radps=0"}, "control.hinf.translation.bandwidth_radps", "must be > 0 (got 0)"},
  {"hinf_nyquist", {"control.hinf.rotation.bandwidth_radps=40"}, "control.hinf.rotation.bandwidth_radps", "must be < pi / control_period_s = 31.41592653589793 rad/s (got 40)"},
  {"hinf_peak", {"control.hinf.translation.peak_sensitivity=1"}, "control.hinf.translation.peak_sensitivity", "must be in (1, 10] (got 1)"},
  {"hinf_low_gain", {"control.hinf.rotation.low_frequency_gain=0"}, "control.hinf.rotation.low_frequency_gain", "must be in (0, 1) (got 0)"},
  {"hinf_scale", {"control.hinf.rotation.error_scale_rad=-1"}, "control.hinf.rotation.error_scale_rad", "must be > 0 (got -1)"},
  {"keep_out_extent", {"target.body.keep_out=[{centre_target_m: [0,0,0], half_extents_m: [1,0,1]}]"}, "target.body.keep_out.0.half_extents_m.1", "must be in (0, 1000] (got 0)"},
  {"keep_out_count", {"target.body.keep_out=[]"}, "target.body.keep_out", "must be a list of 1 to 4 boxes"},
  {"keep_out_radius", {"chaser.keep_out_radius_m=-1"}, "chaser.keep_out_radius_m", "must be in [0, 1000] (got -1)"},
  {"control_law", {"control.law=pid"}, "control.law", "must be one of lqr, hinf (got 'pid')"},
  {"input_disturbance", {"control.hinf.translation.input_disturbance=11"}, "control.hinf.translation.input_disturbance", "must be in [0, 10] (got 11)"},
  {"allocation_norm", {"control.allocation_norm=3"}, "control.allocation_norm", "must be one of 1, 2, inf (got '3')"},
  {"allocation_norm_text", {"control.allocation_norm=infinity"}, "control.allocation_norm", "must be one of 1, 2, inf (got 'infinity')"},
  {"robust_points", {"control.hinf.robustness.points_per_range=1"}, "control.hinf.robustness.points_per_range", "must be in [2, 20] (got 1)"},
  {"robust_mass", {"control.hinf.robustness.mass_uncertainty=0.5"}, "control.hinf.robustness.mass_uncertainty", "must be in [0, 0.5) (got 0.5)"},
  {"robust_fraction", {"control.hinf.robustness.translation_modes=[{name: slosh, frequency_lo_radps: 0.05, frequency_hi_radps: 0.16, modal_fraction: 1, damping: 0.005}]"}, "control.hinf.robustness.translation_modes.0.modal_fraction", "must be in [0, 1) (got 1)"},
  {"robust_range", {"control.hinf.robustness.rotation_modes=[{name: arm, frequency_lo_radps: 12, frequency_hi_radps: 6, modal_fraction: 0.05, damping: 0.005}]"}, "control.hinf.robustness.rotation_modes.0.frequency_hi_radps", "must be >= frequency_lo_radps = 12 (got 6)"},
};
// clang-format on

class BadComrade : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadComrade, ReportsOneErrorAtKeyPathWithAllowedRange) {
  const BadCase& c = GetParam();
  const LoadResult r = load_scenario_file(kEnvisat, c.overrides);
  EXPECT_FALSE(r.scenario.has_value());
  EXPECT_TRUE(has_error(r, c.key_path, c.fragment));
  EXPECT_EQ(r.errors.size(), 1u) << format_errors(r.errors);
}

INSTANTIATE_TEST_SUITE_P(Rules, BadComrade, ::testing::ValuesIn(kBadCases),
                         [](const auto& info) { return std::string(info.param.label); });

// MSR's circular-orbit file with one Earth-orbit key added: that one error and no other.
void expect_only_error_on_msr(const std::string& override_text, const std::string& key, const std::string& text) {
  const LoadResult r = load_scenario_file(testing::kMsrPath, {override_text});
  EXPECT_TRUE(has_error(r, key, text)) << format_errors(r.errors);
  EXPECT_EQ(r.errors.size(), 1u) << format_errors(r.errors);
}

// orbit.earth and target.body come together: a file with one alone is told which one is missing.
TEST(ComradeScenario, EarthOrbitAndTargetBodyComeTogether) {
  expect_only_error_on_msr("target.body={mass_kg: 100, inertia_kgm2: [[1,0,0],[0,1,0],[0,0,1]], "
                           "gravity_gradient: false, spin_case: given, spin_rate_deg_s: 0, "
                           "grasp_point_target_m: [0,0,0], capture_point_target_m: [0,0,0]}",
                           "orbit.earth", "must be given with target.body");
}

// Slosh is part of the Earth-orbit plant: a circular-orbit file with chaser.slosh is told so.
TEST(ComradeScenario, SloshNeedsTheEarthOrbit) {
  expect_only_error_on_msr("chaser.slosh={g_eff_mps2: 0.01, tanks: [{bottom_centre_body_m: [0,0,0], "
                           "axis_body: [0,0,1], radius_m: 0.4, height_m: 0.9, liquid_mass_kg: 100, "
                           "density_kgpm3: 1004, damping_ratio: 0.005}]}",
                           "chaser.slosh", "only with orbit.earth");
}

// The shipped ENVISAT servicer's two tanks read as written.
TEST(ComradeScenario, EnvisatChaserHasTwoSloshingTanks) {
  const LoadResult r = load_scenario_file(kEnvisat, {});
  ASSERT_TRUE(r.errors.empty()) << format_errors(r.errors);
  ASSERT_TRUE(r.scenario->chaser.slosh.has_value());
  const model::SloshParams& slosh = *r.scenario->chaser.slosh;
  ASSERT_EQ(slosh.tanks.size(), 2u);
  EXPECT_EQ(slosh.g_eff_mps2, 0.005);
  EXPECT_EQ(slosh.tanks[1].bottom_centre_body_m, Vec3(-0.5, 0.0, -0.45));
  EXPECT_EQ(slosh.tanks[0].liquid_mass_kg, 150.0);
}

// control.hinf reads as written; a scenario without it has none.
TEST(ComradeScenario, EnvisatHasAnHinfDesign) {
  const LoadResult r = load_scenario_file(kEnvisat, {});
  ASSERT_TRUE(r.errors.empty()) << format_errors(r.errors);
  ASSERT_TRUE(r.scenario->control.hinf.has_value());
  const model::HinfDesignParams& h = *r.scenario->control.hinf;
  EXPECT_EQ(h.translation.bandwidth_radps, 0.04);
  EXPECT_EQ(h.translation.error_scale, 0.5);
  EXPECT_EQ(h.rotation.bandwidth_radps, 0.2);
  EXPECT_EQ(h.rotation.error_scale, 0.035);
  EXPECT_EQ(h.rotation.low_frequency_gain, 1e-3);
  ASSERT_TRUE(h.robustness.has_value());
  EXPECT_EQ(h.robustness->points_per_range, 5);
  ASSERT_EQ(h.robustness->rotation_modes.size(), 2u);
  EXPECT_EQ(h.robustness->rotation_modes[1].name, "stowed_arm");
  EXPECT_EQ(h.robustness->translation_modes[0].modal_fraction, 0.12);
  EXPECT_FALSE(testing::load_msr().scenario->control.hinf.has_value());
}

}  // namespace comrade_scenario_test
}  // namespace chaser::io
