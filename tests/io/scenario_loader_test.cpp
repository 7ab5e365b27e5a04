#include "io/scenario_loader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include "core/constants.hpp"
#include "model/positive_span.hpp"
#include "model/thruster_geometry.hpp"
#include "scenario_test_util.hpp"

namespace chaser::io {
namespace {

using testing::has_error;
using testing::load_msr;
using testing::msr_text;

// The shipped scenario loads cleanly and holds the values of the MSR terminal rendezvous brief.
// Values written as decimals in the file compare exactly; converted angles to 1 ulp-level (1e-15).
TEST(ScenarioLoader, MsrScenarioLoadsWithExpectedValues) {
  const LoadResult r = load_msr();
  ASSERT_TRUE(r.errors.empty()) << format_errors(r.errors);
  ASSERT_TRUE(r.scenario.has_value());
  const model::Scenario& s = *r.scenario;
  EXPECT_EQ(s.name, "msr_terminal");
  EXPECT_EQ(s.seed, 1u);
  EXPECT_EQ(s.duration_s, 1200.0);
  EXPECT_EQ(s.control_period_s, 0.1);
  EXPECT_EQ(s.orbit.mu_m3ps2, 4.282837e13);
  EXPECT_EQ(s.orbit.body_radius_m, 3389.5e3);
  EXPECT_EQ(s.orbit.altitude_m, 500e3);
  EXPECT_EQ(s.chaser.mass_kg, 2500.0);
  EXPECT_EQ(s.chaser.inertia_kgm2, Vec3(2000.0, 2500.0, 3000.0).asDiagonal().toDenseMatrix());
  EXPECT_EQ(s.chaser.isp_s, 220.0);
  EXPECT_EQ(s.target.omega_inertial_radps, Vec3(0.0, 0.0, 0.001));
  EXPECT_EQ(s.target.q_inertial_from_target.coeffs(), Quat::Identity().coeffs());
  EXPECT_EQ(s.environment.force_bias_lvlh_N, Vec3(0.0, 2e-4, 0.0));
  EXPECT_TRUE(s.environment.gravity_gradient);
  EXPECT_EQ(s.sensors.gyro.bias_radps, Vec3(1e-6, -1e-6, 5e-7));
  EXPECT_TRUE(s.faults.empty());
  // Degrees in the file, radians inside.
  EXPECT_NEAR(s.thrusters.misalignment_sigma_rad, 0.1 * kPi / 180.0, 1e-15);
  EXPECT_NEAR(s.sensors.lidar.fov_half_angle_rad, 20.0 * kPi / 180.0, 1e-15);
  EXPECT_NEAR(s.guidance.corridor_half_angle_rad, 10.0 * kPi / 180.0, 1e-15);
  EXPECT_NEAR(s.guidance.capture_attitude_tol_rad, 2.0 * kPi / 180.0, 1e-15);
}

// Thruster geometry: directions are unit vectors after loading, T5 mirrors T1, branch B is branch
// A at 0.95 of the radius, and both branches positively span force-torque space (they are
// redundant, Fonod 2015 section II.B).
TEST(ScenarioLoader, MsrThrusterGeometry) {
  const LoadResult r = load_msr();
  ASSERT_TRUE(r.scenario.has_value()) << format_errors(r.errors);
  const model::ThrusterSetParams& set = r.scenario->thrusters;
  const Vec3 t1_dir = Vec3(0.36, 0.36, -1.0).normalized();
  EXPECT_LT((set.thrusters[0].direction_body - t1_dir).norm(), 1e-15);
  ASSERT_EQ(set.count, 16);
  for (int i = 0; i < set.count; ++i) {
    EXPECT_NEAR(set.thrusters[i].direction_body.norm(), 1.0, 1e-15);
    EXPECT_EQ(set.thrusters[i].max_thrust_N, 22.0);
  }
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(set.thrusters[i + 4].position_body_m, -set.thrusters[i].position_body_m);
    EXPECT_LT((set.thrusters[i + 4].direction_body + set.thrusters[i].direction_body).norm(), 1e-15);
  }
  for (int i = 0; i < 8; ++i) {
    EXPECT_LT((set.thrusters[i + 8].position_body_m - 0.95 * set.thrusters[i].position_body_m).norm(), 1e-15);
    EXPECT_EQ(set.thrusters[i + 8].direction_body, set.thrusters[i].direction_body);
  }
  ASSERT_EQ(set.groups.size(), 2u);
  EXPECT_EQ(set.groups[0].name, "A");
  EXPECT_FALSE(set.groups[0].standby);
  EXPECT_EQ(set.groups[1].name, "B");
  EXPECT_TRUE(set.groups[1].standby);
  EXPECT_EQ(model::group_thrusters(set, 0), 0x00FFu);
  EXPECT_EQ(model::group_thrusters(set, 1), 0xFF00u);
  EXPECT_EQ(model::initial_active_set(set), 0x00FFu);
  for (int group = 0; group < 2; ++group)
    EXPECT_TRUE(model::positive_span(model::configuration_columns(set, model::group_thrusters(set, group), Vec3::Zero())).spans);
}

// The brief: navigation, guidance and control in the file are model/gnc.hpp's defaults. This
// catches the file drifting from the header when either changes. capture_attitude_tol is written
// as 2 deg = 0.034907 rad in the file; the header rounds it to 0.0349 rad.
TEST(ScenarioLoader, MsrFlightSoftwareMatchesModelDefaults) {
  const LoadResult r = load_msr();
  ASSERT_TRUE(r.scenario.has_value()) << format_errors(r.errors);
  const model::Scenario& s = *r.scenario;
  const model::NavigationParams nav;
  EXPECT_EQ(s.navigation.position_process_noise_mps2, nav.position_process_noise_mps2);
  EXPECT_EQ(s.navigation.attitude_gain, nav.attitude_gain);
  EXPECT_EQ(s.navigation.gyro_bias_gain, nav.gyro_bias_gain);
  const model::GuidanceParams g;
  EXPECT_EQ(s.guidance.approach_axis_lvlh, g.approach_axis_lvlh);
  EXPECT_EQ(s.guidance.start_distance_m, g.start_distance_m);
  EXPECT_EQ(s.guidance.capture_distance_m, g.capture_distance_m);
  EXPECT_EQ(s.guidance.approach_duration_s, g.approach_duration_s);
  EXPECT_EQ(s.guidance.blend_time_s, g.blend_time_s);
  EXPECT_NEAR(s.guidance.corridor_half_angle_rad, g.corridor_half_angle_rad, 1e-15);
  EXPECT_EQ(s.guidance.corridor_min_distance_m, g.corridor_min_distance_m);
  EXPECT_EQ(s.guidance.capture_position_tol_m, g.capture_position_tol_m);
  EXPECT_EQ(s.guidance.capture_speed_tol_mps, g.capture_speed_tol_mps);
  EXPECT_NEAR(s.guidance.capture_attitude_tol_rad, g.capture_attitude_tol_rad, 1e-5);
  const model::ControlParams c;
  EXPECT_EQ(s.control.position_q_pos, c.position_q_pos);
  EXPECT_EQ(s.control.position_q_vel, c.position_q_vel);
  EXPECT_EQ(s.control.position_r_force, c.position_r_force);
  EXPECT_EQ(s.control.attitude_q_angle, c.attitude_q_angle);
  EXPECT_EQ(s.control.attitude_q_rate, c.attitude_q_rate);
  EXPECT_EQ(s.control.attitude_r_torque, c.attitude_r_torque);
  EXPECT_EQ(s.control.tmu_force_threshold_Ns, c.tmu_force_threshold_Ns);
  EXPECT_EQ(s.control.tmu_torque_threshold_Nms, c.tmu_torque_threshold_Nms);
  EXPECT_EQ(s.control.tmu_windup_periods, c.tmu_windup_periods);
  const model::InitialState init;
  EXPECT_EQ(s.initial.r_lvlh_m, init.r_lvlh_m);
  EXPECT_EQ(s.initial.v_lvlh_mps, init.v_lvlh_mps);
  EXPECT_EQ(s.initial.use_guidance_start, init.use_guidance_start);
  EXPECT_EQ(s.initial.omega_body_radps, init.omega_body_radps);
}

// The fdi section carries the paper's design and test settings (Fonod 2015, IV.A.1 and IV.C):
// eigenvalues 0.85 ... 0.95, h = 2, N_d = 10, J_th = 20, N = 10, N_c = 15, delays in [0, T).
TEST(ScenarioLoader, MsrFdiSectionHasThePapersSettings) {
  const LoadResult r = load_msr();
  ASSERT_TRUE(r.scenario.has_value()) << format_errors(r.errors);
  const model::FdiParams& f = r.scenario->fdi;
  EXPECT_EQ(f.eigenvalues, (std::array<double, 6>{0.85, 0.87, 0.89, 0.91, 0.93, 0.95}));
  EXPECT_EQ(f.taylor_order, 2);
  EXPECT_EQ(f.design_delay_max_s, r.scenario->control_period_s);
  EXPECT_EQ(f.glr_window, 10);
  EXPECT_EQ(f.glr_threshold, 20.0);
  EXPECT_EQ(f.isolation_window, 10);
  EXPECT_EQ(f.confirmation_window, 15);
  EXPECT_TRUE(f.position.enabled && f.attitude.enabled);
  EXPECT_EQ(f.position.residual_dimension, 1);
  EXPECT_GT(r.scenario->sensors.propellant.noise_sigma_kg, 0.0);
}

TEST(ScenarioLoader, TextAndFileGiveTheSameScenarioAndHash) {
  const LoadResult from_file = load_msr();
  const LoadResult from_text = load_scenario_text(msr_text());
  ASSERT_TRUE(from_text.scenario.has_value()) << format_errors(from_text.errors);
  EXPECT_EQ(from_text.hash, from_file.hash);
  EXPECT_EQ(from_text.scenario->chaser.mass_kg, from_file.scenario->chaser.mass_kg);
}

TEST(ScenarioLoader, ScalarOverride) {
  const LoadResult r = load_msr({"chaser.mass_kg=2400"});
  ASSERT_TRUE(r.scenario.has_value()) << format_errors(r.errors);
  EXPECT_EQ(r.scenario->chaser.mass_kg, 2400.0);
}

TEST(ScenarioLoader, ListOverride) {
  const LoadResult r = load_msr({"sensors.lidar.bias_m=[0.01,0,0]"});
  ASSERT_TRUE(r.scenario.has_value()) << format_errors(r.errors);
  EXPECT_EQ(r.scenario->sensors.lidar.bias_m, Vec3(0.01, 0.0, 0.0));
}

TEST(ScenarioLoader, DegreeOverrideIsConverted) {
  const LoadResult r = load_msr({"guidance.corridor_half_angle_deg=15"});
  ASSERT_TRUE(r.scenario.has_value()) << format_errors(r.errors);
  EXPECT_NEAR(r.scenario->guidance.corridor_half_angle_rad, 15.0 * kPi / 180.0, 1e-15);
}

// The demo's fault, then a list-index override of one of its keys; later overrides win.
TEST(ScenarioLoader, FaultListOverrideAndIndexedOverride) {
  const LoadResult r = load_msr({"faults=[{thruster: T8, kind: stuck_open, onset_s: 1000}]",
                                 "faults.0.onset_s=900"});
  ASSERT_TRUE(r.scenario.has_value()) << format_errors(r.errors);
  ASSERT_EQ(r.scenario->faults.size(), 1u);
  EXPECT_EQ(r.scenario->faults[0].thruster, 7);
  EXPECT_EQ(r.scenario->faults[0].kind, model::FaultKind::kStuckOpen);
  EXPECT_EQ(r.scenario->faults[0].onset_s, 900.0);
}

TEST(ScenarioLoader, LeakAndLossFaultsCarryTheirSizes) {
  const LoadResult r = load_msr({"faults=[{thruster: T3, kind: leak, onset_s: 10, leak_size: 0.2, "
                                 "leak_slope_per_s: 0.05}, {thruster: T12, kind: loss, onset_s: 20, "
                                 "loss_size: 0.6}, {thruster: T16, kind: stuck_closed, onset_s: 0}]"});
  ASSERT_TRUE(r.scenario.has_value()) << format_errors(r.errors);
  ASSERT_EQ(r.scenario->faults.size(), 3u);
  EXPECT_EQ(r.scenario->faults[0].kind, model::FaultKind::kLeak);
  EXPECT_EQ(r.scenario->faults[0].thruster, 2);
  EXPECT_EQ(r.scenario->faults[0].leak_size, 0.2);
  EXPECT_EQ(r.scenario->faults[0].leak_slope_per_s, 0.05);
  EXPECT_EQ(r.scenario->faults[1].kind, model::FaultKind::kLoss);
  EXPECT_EQ(r.scenario->faults[1].thruster, 11);
  EXPECT_EQ(r.scenario->faults[1].loss_size, 0.6);
  EXPECT_EQ(r.scenario->faults[2].kind, model::FaultKind::kStuckClosed);
  EXPECT_EQ(r.scenario->faults[2].thruster, 15);
}

TEST(ScenarioLoader, UnknownOverridePathIsAnError) {
  const LoadResult r = load_msr({"chasr.mass_kg=2400"});
  EXPECT_FALSE(r.scenario.has_value());
  EXPECT_TRUE(has_error(r, "chasr.mass_kg", "no key 'chasr' at the top level"));
  // A new last key is created, then reported as unknown with a suggestion.
  EXPECT_TRUE(has_error(load_msr({"chaser.inertia.0=1"}), "chaser.inertia.0", "no key 'inertia' in 'chaser'"));
  const LoadResult typo = load_msr({"chaser.mas_kg=2400"});
  EXPECT_TRUE(has_error(typo, "chaser.mas_kg", "did you mean 'mass_kg'"));
  EXPECT_EQ(typo.errors.size(), 1u);
}

TEST(ScenarioLoader, MalformedOverridesAreErrors) {
  EXPECT_TRUE(has_error(load_msr({"chaser.mass_kg"}), "chaser.mass_kg", "expected key.path=value"));
  EXPECT_TRUE(has_error(load_msr({"chaser..mass_kg=1"}), "chaser..mass_kg", "empty part"));
  EXPECT_TRUE(has_error(load_msr({"chaser.mass_kg=[1, 2"}), "chaser.mass_kg", "not valid YAML"));
  EXPECT_TRUE(has_error(load_msr({"thrusters.list.16.max_thrust_N=1"}), "thrusters.list.16.max_thrust_N",
                        "not an index of the list 'thrusters.list' (0..15)"));
  EXPECT_TRUE(has_error(load_msr({"name.x=1"}), "name.x", "is not a mapping or a list"));
  EXPECT_TRUE(has_error(load_msr({"faults.0.onset_s=1"}), "faults.0.onset_s", "is not an index of the list 'faults': it is empty"));
}

// The hash is a pure function of the canonical text: same input, same hash; an override that
// changes a value changes it; one that writes the same text, or a reordered and uncommented file,
// does not.
TEST(ScenarioLoader, HashIsStableAndTracksValues) {
  const LoadResult a = load_msr(), b = load_msr();
  EXPECT_TRUE(std::regex_match(a.hash, std::regex("[0-9a-f]{16}"))) << a.hash;
  EXPECT_EQ(a.hash, b.hash);
  EXPECT_NE(load_msr({"chaser.mass_kg=2400"}).hash, a.hash);
  EXPECT_NE(load_msr({"faults=[{thruster: T8, kind: stuck_open, onset_s: 1000}]"}).hash, a.hash);
  EXPECT_EQ(load_msr({"chaser.mass_kg=2500.0"}).hash, a.hash);
  const LoadResult canonical = load_scenario_text(a.canonical_yaml);
  ASSERT_TRUE(canonical.scenario.has_value()) << format_errors(canonical.errors);
  EXPECT_EQ(canonical.hash, a.hash);
}

TEST(ScenarioLoader, MissingFileIsAnError) {
  const LoadResult r = load_scenario_file("scenarios/does_not_exist.yaml");
  EXPECT_FALSE(r.scenario.has_value());
  EXPECT_TRUE(has_error(r, "scenarios/does_not_exist.yaml", "cannot open"));
  EXPECT_TRUE(has_error(load_scenario_file("scenarios"), "scenarios", "not a regular file"));
}

TEST(ScenarioLoader, InvalidYamlReportsLineAndColumn) {
  const LoadResult r = load_scenario_text("name: x\nseed: [1, 2\nduration_s: 3\n");
  EXPECT_FALSE(r.scenario.has_value());
  EXPECT_TRUE(has_error(r, "<text>", "invalid YAML at line 3, column 11"));
  EXPECT_TRUE(has_error(load_scenario_text(""), "<text>", "is empty"));
  EXPECT_TRUE(has_error(load_scenario_text("a: 1\n---\nb: 2\n"), "<text>", "exactly one YAML document"));
  EXPECT_TRUE(has_error(load_scenario_text("- 1\n- 2\n"), "<text>", "must be a mapping"));
  EXPECT_TRUE(has_error(load_scenario_text("[1, 2]: 3\n"), "(top level)", "keys must be plain names"));
}

TEST(ScenarioLoader, FormatErrorsOneLinePerProblem) {
  const std::string text = format_errors({{"chaser.mass_kg", "must be > 0 (got -5)"}, {"a.b", "c"}});
  EXPECT_EQ(text, "chaser.mass_kg: must be > 0 (got -5)\na.b: c\n");
}

}  // namespace
}  // namespace chaser::io
