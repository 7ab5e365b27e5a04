// Bad scenarios: every rule of the loader reports its problem at the right key path, names what is
// allowed, and reports nothing else (no cascades, no silent defaults).
#include <gtest/gtest.h>

#include <functional>
#include <limits>

#include <yaml-cpp/yaml.h>

#include "core/random.hpp"
#include "io/scenario_loader.hpp"
#include "scenario_test_util.hpp"

namespace chaser::io {
namespace {

using testing::has_error;
using testing::load_msr;
using testing::msr_text;

struct BadCase {
  const char* label;
  std::vector<std::string> overrides;  // applied to the shipped MSR scenario
  const char* key_path;
  const char* fragment;                // must name the allowed range or type
};

// clang-format off
const BadCase kBadCases[] = {
  {"negative_mass", {"chaser.mass_kg=-5"}, "chaser.mass_kg", "must be > 0 (got -5)"},
  {"text_for_number", {"chaser.mass_kg=abc"}, "chaser.mass_kg", "must be a number > 0 (got 'abc')"},
  {"quoted_number", {"chaser.mass_kg=\"2500\""}, "chaser.mass_kg", "must be a number > 0 (got the quoted string"},
  {"infinite_number", {"orbit.altitude_m=.inf"}, "orbit.altitude_m", "must be a number > 0"},
  {"zero_isp", {"chaser.isp_s=0"}, "chaser.isp_s", "must be > 0 (got 0)"},
  {"list_for_scalar", {"chaser.isp_s=[220]"}, "chaser.isp_s", "must be a number > 0 (got a list of 1)"},
  {"zero_period", {"control_period_s=0"}, "control_period_s", "must be in [1e-09, 10] (got 0)"},
  // Below the clock's tick the period rounded to 0 ns and validation divided by it (SIGFPE).
  {"period_below_a_nanosecond", {"control_period_s=1e-320"}, "control_period_s", "must be in [1e-09, 10] (got 1e-320)"},
  {"sub_ns_period", {"control_period_s=1.5e-9"}, "control_period_s", "whole number of nanoseconds"},
  {"duration_below_a_nanosecond", {"duration_s=1e-320"}, "duration_s", "must be a positive multiple of control_period_s = 0.1 (got 1e-320)"},
  {"duration_not_multiple", {"duration_s=1200.05"}, "duration_s", "must be a positive multiple of control_period_s = 0.1 (got 1200.05)"},
  {"negative_duration", {"duration_s=-1"}, "duration_s", "must be in (0, 100000000]"},
  {"delay_max_at_period", {"thrusters.delay_max_s=0.1"}, "thrusters.delay_max_s", "must be in [0, control_period_s) = [0, 0.1) (got 0.1)"},
  {"min_on_sub_ns", {"thrusters.min_on_time_s=0.0050000005"}, "thrusters.min_on_time_s", "whole number of nanoseconds"},
  {"min_off_at_period", {"thrusters.min_off_time_s=0.2"}, "thrusters.min_off_time_s", "must be in [0, control_period_s) = [0, 0.1) (got 0.2)"},
  {"negative_rise", {"thrusters.rise_time_s=-0.001"}, "thrusters.rise_time_s", "must be >= 0"},
  {"thrust_sigma_large", {"thrusters.thrust_sigma=0.5"}, "thrusters.thrust_sigma", "must be in [0, 0.25]"},
  {"misalignment_large", {"thrusters.misalignment_sigma_deg=20"}, "thrusters.misalignment_sigma_deg", "must be in [0, 10]"},
  {"sensor_delay_fraction", {"sensors.lidar.delay_s=0.05"}, "sensors.lidar.delay_s", "must be a whole multiple of control_period_s = 0.1 in [0, 32 periods] = [0, 3.2] (got 0.05)"},
  {"sensor_delay_too_long", {"sensors.star_tracker.delay_s=3.3"}, "sensors.star_tracker.delay_s", "in [0, 32 periods]"},
  {"sensor_delay_negative", {"sensors.gyro.delay_s=-0.1"}, "sensors.gyro.delay_s", "must be >= 0 (got -0.1)"},
  {"negative_noise", {"sensors.star_tracker.noise_sigma_rad=-1e-5"}, "sensors.star_tracker.noise_sigma_rad", "must be >= 0"},
  {"env_noise_negative", {"environment.force_noise_sigma_N=-1"}, "environment.force_noise_sigma_N", "must be >= 0"},
  {"fov_too_wide", {"sensors.lidar.fov_half_angle_deg=120"}, "sensors.lidar.fov_half_angle_deg", "must be in (0, 90] (got 120)"},
  {"lidar_range_zero", {"sensors.lidar.range_max_m=0"}, "sensors.lidar.range_max_m", "must be in (0, 1000000] (got 0)"},
  {"corridor_90", {"guidance.corridor_half_angle_deg=90"}, "guidance.corridor_half_angle_deg", "must be in (0, 90) (got 90)"},
  {"capture_beyond_start", {"guidance.capture_distance_m=25"}, "guidance.capture_distance_m", "must be < guidance.start_distance_m = 20 (got 25)"},
  {"blend_too_long", {"guidance.blend_time_s=600"}, "guidance.blend_time_s", "must be <= guidance.approach_duration_s / 2 = 575"},
  {"zero_approach_axis", {"guidance.approach_axis_lvlh=[0,0,0]"}, "guidance.approach_axis_lvlh", "nonzero direction"},
  {"attitude_gain_above_1", {"navigation.attitude_gain=2"}, "navigation.attitude_gain", "must be in (0, 1] (got 2)"},
  {"lqr_input_weight_zero", {"control.position_r_force=0"}, "control.position_r_force", "must be > 0"},
  {"lqr_state_weight_negative", {"control.attitude_q_rate=-1"}, "control.attitude_q_rate", "must be >= 0"},
  {"windup_zero", {"control.tmu_windup_periods=0"}, "control.tmu_windup_periods", "must be > 0"},
  {"lqr_position_weight_zero", {"control.position_q_pos=0"}, "control.position_q_pos", "must be > 0 (got 0)"},
  {"fdi_eigenvalue_outside_unit_circle", {"fdi.eigenvalues=[0.85,0.87,0.89,0.91,0.93,1.0]"}, "fdi.eigenvalues.5", "must be in (-1, 1) (got 1)"},
  {"fdi_eigenvalues_repeated", {"fdi.eigenvalues=[0.9,0.9,0.89,0.91,0.93,0.95]"}, "fdi.eigenvalues", "must be 6 distinct values"},
  {"fdi_eigenvalues_short", {"fdi.eigenvalues=[0.9,0.8]"}, "fdi.eigenvalues", "must be a list of 6 numbers, each in (-1, 1) (got a list of 2)"},
  {"fdi_glr_window_long", {"fdi.glr_window=129"}, "fdi.glr_window", "must be a whole number in [2, 128] (got 129)"},
  {"fdi_residual_dimension", {"fdi.attitude.residual_dimension=0"}, "fdi.attitude.residual_dimension", "must be a whole number in [1, 3] (got 0)"},
  {"fdi_isolation_method_unknown", {"fdi.isolation_method=guess"}, "fdi.isolation_method", "must be one of paper, signature, deficit (got 'guess')"},
  {"fdi_sigma0_zero", {"fdi.position.sigma0=0"}, "fdi.position.sigma0", "must be > 0 (got 0)"},
  {"fdi_design_delay_beyond_period", {"fdi.design_delay_max_s=0.15"}, "fdi.design_delay_max_s", "must be in (0, control_period_s = 0.1] (got 0.15)"},
  {"propellant_noise_negative", {"sensors.propellant.noise_sigma_kg=-1"}, "sensors.propellant.noise_sigma_kg", "must be >= 0"},
  {"short_vector", {"chaser.com_body_m=[0,0]"}, "chaser.com_body_m", "must be a list of 3 numbers [x, y, z] (got a list of 2)"},
  {"scalar_for_vector", {"chaser.com_body_m=5"}, "chaser.com_body_m", "must be a list of 3 numbers [x, y, z] (got '5')"},
  {"vector_element_text", {"sensors.lidar.bias_m=[0, x, 0]"}, "sensors.lidar.bias_m.1", "must be a number (got 'x')"},
  {"quaternion_not_unit", {"target.q_inertial_from_target=[1,0,0,0.1]"}, "target.q_inertial_from_target", "norm within 1e-06 of 1"},
  {"quaternion_length", {"initial.q_lvlh_from_body=[1,0,0]"}, "initial.q_lvlh_from_body", "unit quaternion [w, x, y, z] (got a list of 3)"},
  {"inertia_asymmetric", {"chaser.inertia_kgm2=[[2000,10,0],[0,2500,0],[0,0,3000]]"}, "chaser.inertia_kgm2", "must be symmetric"},
  {"inertia_indefinite", {"chaser.inertia_kgm2=[[-1,0,0],[0,2500,0],[0,0,3000]]"}, "chaser.inertia_kgm2", "must be positive definite"},
  {"inertia_triangle", {"chaser.inertia_kgm2=[[1000,0,0],[0,1000,0],[0,0,3000]]"}, "chaser.inertia_kgm2", "triangle inequality"},
  {"inertia_row_length", {"chaser.inertia_kgm2=[[1,0,0],[0,1],[0,0,1]]"}, "chaser.inertia_kgm2.1", "list of 3 numbers"},
  {"inertia_not_matrix", {"chaser.inertia_kgm2=2000"}, "chaser.inertia_kgm2", "a 3x3 matrix"},
  {"bool_as_yes", {"environment.gravity_gradient=yes"}, "environment.gravity_gradient", "must be true or false (got 'yes')"},
  {"negative_seed", {"seed=-1"}, "seed", "must be a non-negative integer"},
  {"fractional_seed", {"seed=1.5"}, "seed", "must be a non-negative integer"},
  {"empty_name", {"name=\"\""}, "name", "must be a non-empty string"},
  // The name becomes a folder under --out (--preset comrade-table5): no separator, no climbing out.
  {"name_climbs_out", {"name=../../x"}, "name", "must be a plain name: letters, digits, '_', '-' and '.' only; not '.' or '..' (got '../../x')"},
  {"name_absolute", {"name=/tmp/x"}, "name", "must be a plain name"},
  {"name_parent", {"name=.."}, "name", "must be a plain name"},
  {"name_with_space", {"name=\"a b\""}, "name", "must be a plain name"},
  {"section_not_mapping", {"orbit=5"}, "orbit", "must be a mapping of keys (got '5')"},
  {"thruster_zero_direction", {"thrusters.list.3.direction_body=[0,0,0]"}, "thrusters.list.3.direction_body", "must be a nonzero direction"},
  {"thruster_direction_overflows", {"thrusters.list.3.direction_body=[1.5e308,1.5e308,0]"}, "thrusters.list.3.direction_body", "must be a direction [x, y, z] with a norm in [1e-150, 1e+150], which normalises to full precision (got norm inf)"},
  {"thruster_direction_underflows", {"thrusters.list.3.direction_body=[1e-320,0,0]"}, "thrusters.list.3.direction_body", "with a norm in [1e-150, 1e+150], which normalises to full precision (got norm 1e-320)"},
  {"thruster_direction_huge", {"thrusters.list.3.direction_body=[1e200,0,1e200]"}, "thrusters.list.3.direction_body", "with a norm in [1e-150, 1e+150], which normalises to full precision (got norm 1.414213562373095e+200)"},
  {"thruster_direction_nan", {"thrusters.list.3.direction_body=[.nan,0,1]"}, "thrusters.list.3.direction_body.0", "must be a number (got '.nan')"},
  {"thruster_direction_inf", {"thrusters.list.3.direction_body=[0,1e999,1]"}, "thrusters.list.3.direction_body.1", "must be a number (got '1e999')"},
  {"thruster_position_far", {"thrusters.list.3.position_body_m=[1e300,0,0]"}, "thrusters.list.3.position_body_m.0", "must be in [-1000, 1000] (got 1e+300)"},
  {"thruster_thrust_huge", {"thrusters.list.3.max_thrust_N=1e300"}, "thrusters.list.3.max_thrust_N", "must be in (0, 10000000] (got 1e+300)"},
  {"com_far", {"chaser.com_body_m=[0,0,-1e300]"}, "chaser.com_body_m.2", "must be in [-1000, 1000] (got -1e+300)"},
  {"thruster_zero_thrust", {"thrusters.list.3.max_thrust_N=0"}, "thrusters.list.3.max_thrust_N", "must be in (0, 10000000] (got 0)"},
  {"thruster_out_of_order", {"thrusters.list.3.name=T5"}, "thrusters.list.3.name", "must be T4"},
  {"thruster_old_branch_key", {"thrusters.list.9.branch=A"}, "thrusters.list.9.branch", "unknown key (allowed here: name, group,"},
  {"standby_group_unknown", {"thrusters.standby_groups=[C]"}, "thrusters.standby_groups.0", "must name a group of thrusters.list (A, B) (got 'C')"},
  {"thruster_list_empty", {"thrusters.list=[]"}, "thrusters.list", "must be a list of 1..32 thrusters T1..TN (got a list of 0)"},
  {"branch_a_not_spanning", {"thrusters.list.2.direction_body=[1,0.36,-0.36]"}, "thrusters.list", "the set that flies at the start, group A (T1..T8), cannot produce force and torque in every direction"},
  {"fault_thruster_17", {"faults=[{thruster: T17, kind: stuck_open, onset_s: 10}]"}, "faults.0.thruster", "must name one of T1..T16 (thrusters.list has 16) (got T17)"},
  {"fault_thruster_0", {"faults=[{thruster: T0, kind: stuck_open, onset_s: 10}]"}, "faults.0.thruster", "must be a thruster name T1..TN, N the number of thrusters.list entries (got 'T0')"},
  {"fault_thruster_x", {"faults=[{thruster: X, kind: stuck_open, onset_s: 10}]"}, "faults.0.thruster", "must be a thruster name T1..TN, N the number of thrusters.list entries (got 'X')"},
  {"active_check_enabled_text", {"fdi.active_check.enabled=sometimes"}, "fdi.active_check.enabled", "must be true or false"},
  {"active_check_bound_zero", {"fdi.active_check.max_unverified_s=0"}, "fdi.active_check.max_unverified_s", "must be > 0 (got 0)"},
  {"active_check_bound_below_period", {"fdi.active_check.max_unverified_s=0.05"}, "fdi.active_check.max_unverified_s", "must be >= control_period_s = 0.1 (got 0.05)"},
  {"active_check_informative_below_min_on", {"fdi.active_check.informative_on_time_s=0.004"}, "fdi.active_check.informative_on_time_s", "must be in [thrusters.min_on_time_s = 0.005, control_period_s = 0.1] (got 0.004)"},
  {"active_check_informative_beyond_period", {"fdi.active_check.informative_on_time_s=0.2"}, "fdi.active_check.informative_on_time_s", "must be in [thrusters.min_on_time_s = 0.005, control_period_s = 0.1] (got 0.2)"},
  {"active_check_pulse_not_informative", {"fdi.active_check.pulse_s=0.005", "fdi.active_check.informative_on_time_s=0.006"}, "fdi.active_check.pulse_s", "must be in [informative_on_time_s = 0.006, control_period_s = 0.1] (got 0.005)"},
  {"active_check_pulse_beyond_period", {"fdi.active_check.pulse_s=0.2"}, "fdi.active_check.pulse_s", "must be in [informative_on_time_s = 0.005, control_period_s = 0.1] (got 0.2)"},
  {"active_check_keep_quiet_negative", {"fdi.active_check.keep_quiet_range_m=-1"}, "fdi.active_check.keep_quiet_range_m", "must be >= 0 (got -1)"},
  {"active_check_arm_inside_keep_quiet", {"fdi.active_check.arm_range_m=1.5"}, "fdi.active_check.arm_range_m", "must be > keep_quiet_range_m = 2 (got 1.5)"},
  {"active_check_arm_zero", {"fdi.active_check.arm_range_m=0"}, "fdi.active_check.arm_range_m", "must be > 0 (got 0)"},
  {"active_check_recheck_zero", {"fdi.active_check.recheck_fraction=0"}, "fdi.active_check.recheck_fraction", "must be in (0, 1] (got 0)"},
  {"active_check_recheck_above_one", {"fdi.active_check.recheck_fraction=1.5"}, "fdi.active_check.recheck_fraction", "must be in (0, 1] (got 1.5)"},
  {"active_check_missing_key", {"fdi.active_check={enabled: true, max_unverified_s: 25, informative_on_time_s: 0.005, pulse_s: 0.005}"}, "fdi.active_check.keep_quiet_range_m", "missing key (expected a number >= 0)"},
  {"active_check_without_fdi", {"fdi.active_check.enabled=true", "fdi.position.enabled=false", "fdi.attitude.enabled=false", "fdi.deficit.detection=false"}, "fdi.active_check.enabled", "no FDI scheme watches the checks"},
  {"active_check_typo", {"fdi.active_check.pulse_ms=5"}, "fdi.active_check.pulse_ms", "did you mean 'pulse_s'?"},
  {"recovery_unknown", {"fdi.recovery=branch"}, "fdi.recovery", "must be one of none, switch_group, exclude (got 'branch')"},
  {"fdi_on_sixteen_active", {"thrusters.standby_groups=[]", "fdi.recovery=none"}, "fdi", "watch exactly 8 active thrusters; the set that flies at the start, groups A, B (T1..T16), has 16"},
  {"fault_kind_unknown", {"faults=[{thruster: T8, kind: melted, onset_s: 10}]"}, "faults.0.kind", "must be one of stuck_open, stuck_closed, leak, loss (got 'melted')"},
  {"fault_duplicate", {"faults=[{thruster: T8, kind: stuck_open, onset_s: 10}, {thruster: T8, kind: loss, onset_s: 20, loss_size: 0.5}]"}, "faults.1.thruster", "duplicate fault on T8 (also faults.0)"},
  {"fault_onset_late", {"faults=[{thruster: T8, kind: stuck_open, onset_s: 1300}]"}, "faults.0.onset_s", "must be in [0, duration_s] = [0, 1200] (got 1300)"},
  {"fault_onset_negative", {"faults=[{thruster: T8, kind: stuck_open, onset_s: -1}]"}, "faults.0.onset_s", "must be >= 0"},
  {"fault_leak_size", {"faults=[{thruster: T8, kind: leak, onset_s: 10, leak_size: 1.5, leak_slope_per_s: 0.1}]"}, "faults.0.leak_size", "must be in (0, 1] (got 1.5)"},
  {"fault_leak_slope", {"faults=[{thruster: T8, kind: leak, onset_s: 10, leak_size: 0.5, leak_slope_per_s: 0}]"}, "faults.0.leak_slope_per_s", "must be > 0 (got 0)"},
  {"fault_leak_missing_slope", {"faults=[{thruster: T8, kind: leak, onset_s: 10, leak_size: 0.5}]"}, "faults.0.leak_slope_per_s", "missing key (expected a number > 0)"},
  {"fault_loss_size", {"faults=[{thruster: T8, kind: loss, onset_s: 10, loss_size: 0}]"}, "faults.0.loss_size", "must be in (0, 1] (got 0)"},
  {"fault_size_wrong_kind", {"faults=[{thruster: T8, kind: stuck_open, onset_s: 10, leak_size: 0.2}]"}, "faults.0.leak_size", "only allowed when kind is leak"},
  {"fault_unknown_key", {"faults=[{thruster: T8, kind: stuck_open, onset_s: 10, severity: 2}]"}, "faults.0.severity", "unknown key (allowed here: thruster, kind, onset_s"},
  {"faults_not_list", {"faults=T8"}, "faults", "must be a list of faults"},
  {"typo_key", {"chaser.mas_kg=2400"}, "chaser.mas_kg", "did you mean 'mass_kg'?"},
};
// clang-format on

class BadScenario : public ::testing::TestWithParam<BadCase> {};

// One wrong value gives exactly one error, at its key path, naming what is allowed.
TEST_P(BadScenario, ReportsOneErrorAtKeyPathWithAllowedRange) {
  const BadCase& c = GetParam();
  const LoadResult r = load_msr(c.overrides);
  EXPECT_FALSE(r.scenario.has_value());
  EXPECT_TRUE(has_error(r, c.key_path, c.fragment));
  EXPECT_EQ(r.errors.size(), 1u) << format_errors(r.errors);
}

INSTANTIATE_TEST_SUITE_P(Rules, BadScenario, ::testing::ValuesIn(kBadCases),
                         [](const auto& info) { return std::string(info.param.label); });

// Several problems in one file are all reported in one pass, each at its own path.
TEST(ScenarioValidation, ReportsEveryProblemAtOnce) {
  const LoadResult r = load_msr({"chaser.mass_kg=-5", "orbit.altitude_m=abc",
                                 "sensors.lidar.delay_s=0.05", "guidance.corridor_half_angle_deg=95",
                                 "faults=[{thruster: T17, kind: melted, onset_s: -1}]",
                                 "thrusters.list.0.bogus=1"});
  EXPECT_FALSE(r.scenario.has_value());
  EXPECT_TRUE(has_error(r, "chaser.mass_kg", "must be > 0"));
  EXPECT_TRUE(has_error(r, "orbit.altitude_m", "must be a number > 0"));
  EXPECT_TRUE(has_error(r, "sensors.lidar.delay_s", "whole multiple"));
  EXPECT_TRUE(has_error(r, "guidance.corridor_half_angle_deg", "in (0, 90)"));
  EXPECT_TRUE(has_error(r, "faults.0.thruster", "T1..T16"));
  EXPECT_TRUE(has_error(r, "faults.0.kind", "stuck_open"));
  EXPECT_TRUE(has_error(r, "faults.0.onset_s", ">= 0"));
  EXPECT_TRUE(has_error(r, "thrusters.list.0.bogus", "unknown key"));
  EXPECT_EQ(r.errors.size(), 8u) << format_errors(r.errors);
}

// Branch B with every nozzle at the centre of mass produces no torque: M has rank 3. The set that
// flies at the start is fine; the one a recovery would switch to is not, and the scenario says so
// before the run.
// fdi.recovery: exclude flies every start set less one thruster, so each must push and turn
// everywhere: MSR's branch A does so without T4 or T8 only (`chaser thrusters`' N-1 table); each of
// the six other sets is named.
TEST(ScenarioValidation, ExcludeNeedsEverySingleLossToSpan) {
  const LoadResult r = load_msr({"fdi.recovery=exclude", "fdi.position.enabled=false", "fdi.attitude.enabled=false"});
  EXPECT_FALSE(r.scenario.has_value());
  EXPECT_EQ(r.errors.size(), 6u) << format_errors(r.errors);
  EXPECT_TRUE(has_error(r, "thrusters.list", "the set that flies without T1 (fdi.recovery: exclude), T2..T8, cannot "
                                             "produce force and torque in every direction"))
      << format_errors(r.errors);
  EXPECT_TRUE(has_error(r, "thrusters.list", "the set that flies without T7 (fdi.recovery: exclude)"));
  EXPECT_FALSE(has_error(r, "thrusters.list", "the set that flies without T8 (fdi.recovery: exclude)"));
}

TEST(ScenarioValidation, BranchWithoutTorqueIsRejected) {
  std::vector<std::string> overrides;
  for (int i = 8; i < 16; ++i)
    overrides.push_back("thrusters.list." + std::to_string(i) + ".position_body_m=[0,0,0]");
  const LoadResult r = load_msr(overrides);
  EXPECT_TRUE(has_error(r, "thrusters.list", "after a fault in group A (fdi.recovery: switch_group), group B (T9..T16), "
                                             "cannot produce force and torque"));
  EXPECT_TRUE(has_error(r, "thrusters.list", "M has rank 3 of 6"));
  EXPECT_EQ(r.errors.size(), 1u) << format_errors(r.errors);
}

// ---- Every key of the schema: walk the shipped file's tree ----

// Paths of every mapping in the document (list elements by index), and of every key in them.
void collect_paths(const YAML::Node& node, const std::string& path, std::vector<std::string>& maps,
                   std::vector<std::string>& keys) {
  if (node.IsMap()) {
    maps.push_back(path);
    for (const auto& kv : node) {
      const std::string child = path.empty() ? kv.first.Scalar() : path + "." + kv.first.Scalar();
      keys.push_back(child);
      collect_paths(kv.second, child, maps, keys);
    }
  } else if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i)
      collect_paths(node[i], path + "." + std::to_string(i), maps, keys);
  }
}

struct SchemaPaths {
  std::vector<std::string> maps, keys;
};

SchemaPaths msr_paths() {
  SchemaPaths p;
  collect_paths(YAML::Load(msr_text()), "", p.maps, p.keys);
  return p;
}

// The MSR file without the key at `path` (dot-separated, list indices as numbers).
std::string without_key(const std::string& path) {
  YAML::Node root = YAML::Load(msr_text());
  YAML::Node node(root);
  std::size_t start = 0;
  for (std::size_t dot; (dot = path.find('.', start)) != std::string::npos; start = dot + 1) {
    const std::string segment = path.substr(start, dot - start);
    YAML::Node next = node.IsSequence() ? node[std::stoul(segment)] : node[segment];
    node.reset(next);
  }
  node.remove(path.substr(start));
  YAML::Emitter out;
  out << root;
  return out.c_str();
}

// The keys a scenario may leave out (docs/scenario.md): a thruster's redundancy group, the standby
// groups, the single-loss requirement, and the active checks' window and recheck level.
bool optional_key(const std::string& key) {
  const auto ends_with = [&](const std::string& tail) {
    return key.size() >= tail.size() && key.compare(key.size() - tail.size(), tail.size(), tail) == 0;
  };
  return key == "thrusters.standby_groups" || key == "thrusters.tolerates_single_loss" ||
         key == "fdi.active_check.arm_range_m" || key == "fdi.active_check.recheck_fraction" ||
         (key.rfind("thrusters.list.", 0) == 0 && ends_with(".group"));
}

// Every other key of the shipped file is required: removing any one is reported as missing, at its
// path, with the expected type, and as the only problem.
TEST(ScenarioValidation, EveryKeyIsRequired) {
  const SchemaPaths p = msr_paths();
  ASSERT_GT(p.keys.size(), 150u);  // 16 thrusters x 5 keys plus the rest
  int optional = 0;
  for (const std::string& key : p.keys) {
    if (optional_key(key)) {
      ++optional;
      continue;
    }
    const LoadResult r = load_scenario_text(without_key(key));
    EXPECT_TRUE(has_error(r, key, "missing key (expected "));
    EXPECT_EQ(r.errors.size(), 1u) << key << ":\n" << format_errors(r.errors);
  }
  EXPECT_EQ(optional, 20);  // 16 groups, standby_groups, tolerates_single_loss, arm_range_m, recheck_fraction
}

// The optional keys' defaults: without tolerates_single_loss nothing is required of single losses;
// without groups and standby groups every thruster flies from the start (a set of 16, which the
// eight-lane FDI cannot watch, so it is switched off here, with recovery).
TEST(ScenarioValidation, OptionalThrusterKeysHaveDefaults) {
  const LoadResult no_requirement = load_scenario_text(without_key("thrusters.tolerates_single_loss"));
  ASSERT_TRUE(no_requirement.scenario.has_value()) << format_errors(no_requirement.errors);
  EXPECT_FALSE(no_requirement.scenario->thrusters.tolerates_single_loss);

  std::string text = without_key("thrusters.standby_groups");
  const LoadResult one_set = load_scenario_text(text, {"fdi.recovery=none", "fdi.position.enabled=false",
                                                       "fdi.attitude.enabled=false", "fdi.deficit.detection=false",
                                                       "fdi.active_check.enabled=false"});
  ASSERT_TRUE(one_set.scenario.has_value()) << format_errors(one_set.errors);
  EXPECT_EQ(model::initial_active_set(one_set.scenario->thrusters), model::first_thrusters(16));
}

// Without arm_range_m the checks run all along the approach; without recheck_fraction a suspect is
// rechecked from half the detector's threshold (docs/scenario.md).
TEST(ScenarioValidation, OptionalActiveCheckKeysHaveDefaults) {
  const LoadResult no_recheck = load_scenario_text(without_key("fdi.active_check.recheck_fraction"));
  ASSERT_TRUE(no_recheck.scenario.has_value()) << format_errors(no_recheck.errors);
  EXPECT_EQ(no_recheck.scenario->fdi.active_check.recheck_fraction, 0.5);
  const LoadResult no_window = load_scenario_text(without_key("fdi.active_check.arm_range_m"));
  ASSERT_TRUE(no_window.scenario.has_value()) << format_errors(no_window.errors);
  EXPECT_EQ(no_window.scenario->fdi.active_check.arm_range_m, std::numeric_limits<double>::infinity());
}

// An unknown key is caught in every mapping of the schema, the top level and list entries included.
TEST(ScenarioValidation, UnknownKeyIsCaughtEverywhere) {
  const SchemaPaths p = msr_paths();
  for (const std::string& map : p.maps) {
    const std::string key = map.empty() ? "zz_unknown" : map + ".zz_unknown";
    const LoadResult r = load_msr({key + "=1"});
    EXPECT_TRUE(has_error(r, key, "unknown key (allowed here: "));
    EXPECT_EQ(r.errors.size(), 1u) << key << ":\n" << format_errors(r.errors);
  }
}

TEST(ScenarioValidation, DuplicateKeyIsAnError) {
  std::string text = msr_text();
  text.replace(text.find("  isp_s:"), 0, "  mass_kg: 1.0\n");
  const LoadResult r = load_scenario_text(text);
  EXPECT_TRUE(has_error(r, "chaser.mass_kg", "duplicate key (first at line"));
  EXPECT_EQ(r.errors.size(), 1u) << format_errors(r.errors);
}


// Robustness: 300 random corruptions of the shipped file (a byte deleted, replaced by YAML
// punctuation, or a line duplicated) never throw or crash, and every result is consistent: a
// scenario if and only if no error, and every error carries a key path and a message.
TEST(ScenarioValidation, RandomCorruptionsNeverCrash) {
  const std::string base = msr_text();
  RandomStream rng(5, "io/corruption");
  const std::string punctuation = ":-[]{},#&*!|>'\"%@` \n\t0";
  for (int trial = 0; trial < 300; ++trial) {
    std::string text = base;
    for (int edit = 0; edit < 3; ++edit) {
      const std::size_t at = static_cast<std::size_t>(rng.uniform() * static_cast<double>(text.size()));
      const double kind = rng.uniform();
      if (kind < 0.4) {
        text.erase(at, 1);
      } else if (kind < 0.8) {
        text[at] = punctuation[static_cast<std::size_t>(rng.uniform() * punctuation.size())];
      } else {
        const std::size_t begin = text.rfind('\n', at) + 1, end = text.find('\n', at);
        text.insert(begin, text.substr(begin, end - begin + 1));
      }
    }
    LoadResult r;
    ASSERT_NO_THROW(r = load_scenario_text(text)) << text;
    EXPECT_EQ(r.scenario.has_value(), r.errors.empty());
    for (const ScenarioError& e : r.errors) EXPECT_FALSE(e.key_path.empty() || e.message.empty());
  }
}

}  // namespace
}  // namespace chaser::io
