// The capture section, the arm camera and the arm's stowed angles (docs/scenario.md): the shipped
// comrade_capture reads back, and each bad value is refused with its key path and what is allowed.
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "io/scenario_loader.hpp"
#include "scenario_test_util.hpp"

namespace chaser::io {
namespace capture_section_test {

constexpr const char* kCapture = "scenarios/comrade_capture.yaml";

using testing::has_error;

TEST(CaptureSection, TheShippedScenarioReadsBack) {
  const LoadResult r = load_scenario_file(kCapture);
  ASSERT_TRUE(r.scenario) << format_errors(r.errors);
  const model::Scenario& s = *r.scenario;
  ASSERT_TRUE(s.capture && s.sensors.arm_camera && s.chaser.arm);
  EXPECT_EQ(s.capture->start_s, 2760.0);
  EXPECT_EQ(s.capture->law, model::CaptureLaw::kCompliance);
  EXPECT_EQ(s.capture->joint_rate_hz, 1000.0);
  EXPECT_EQ(s.sensors.arm_camera->period_s, 0.1);
  EXPECT_NEAR(s.chaser.arm->stowed_rad[5], 20.0 * model::kArmDegToRad, 1e-15);
  EXPECT_FALSE(load_scenario_file("scenarios/comrade_sync.yaml").scenario->capture);  // optional
  ASSERT_TRUE(s.capture->rigidise);
  EXPECT_EQ(s.capture->rigidise->damping_Nms_per_rad, 2000.0);
  EXPECT_EQ(s.capture->rigidise->saturation, model::RigidiseSaturation::kLinear);
  EXPECT_EQ(s.chaser.arm->brake_holding_torque_Nm, 500.0);  // the default
  ASSERT_TRUE(s.capture->stabilise);
  EXPECT_EQ(s.capture->stabilise->duration_s, 300.0);
  EXPECT_EQ(s.capture->stabilise->bandwidth_radps, 0.02);
  EXPECT_FALSE(s.capture->escape);  // optional
  const LoadResult escaping = load_scenario_file(kCapture, {"capture.escape={command_s: 2870, safe_distance_m: 40}"});
  ASSERT_TRUE(escaping.scenario) << format_errors(escaping.errors);
  const model::EscapeParams& e = *escaping.scenario->capture->escape;
  EXPECT_EQ(e.command_s, 2870.0);
  EXPECT_EQ(e.safe_distance_m, 40.0);
  EXPECT_TRUE(e.on_failed_grasp);  // the defaults
  EXPECT_EQ(e.withdraw_backoff_m, 4.0);
  EXPECT_TRUE(e.brake_when_stowed);
  EXPECT_EQ(e.brake_rate_degps, 0.02);
  EXPECT_EQ(e.braked_step_s, 0.01);
  EXPECT_EQ(e.total_s(), 930.0);
  const LoadResult driven = load_scenario_file(
      kCapture, {"capture.escape={brake_when_stowed: false, brake_rate_degps: 0.1, braked_step_s: 0.05}"});
  ASSERT_TRUE(driven.scenario) << format_errors(driven.errors);
  EXPECT_FALSE(driven.scenario->capture->escape->brake_when_stowed);
  EXPECT_EQ(driven.scenario->capture->escape->brake_rate_degps, 0.1);
  EXPECT_EQ(driven.scenario->capture->escape->braked_step_s, 0.05);
  // The joint period itself (1 ms) and the whole control period are braked steps too.
  for (const char* step : {"0.001", "0.1"})
    EXPECT_TRUE(load_scenario_file(kCapture, {fmt::format("capture.escape={{braked_step_s: {}}}", step)}).scenario) << step;
}

struct BadCapture {
  const char* label;
  std::vector<std::string> overrides;
  const char* key_path;
  const char* fragment;
};

std::vector<BadCapture> bad_captures() {
  return {
      {"law", {"capture.law=pid"}, "capture.law", "must be one of compliance, hinf (got 'pid')"},
      {"before_the_capture_point", {"capture.start_s=2600"}, "capture.start_s",
       "must be at or after the end of the transfer to the capture point, 2700 s"},
      {"after_the_end", {"capture.start_s=3300"}, "capture.start_s", "must be before duration_s 3250 (got 3300)"},
      {"joint_rate_not_whole_ns", {"capture.joint_rate_hz=3"}, "capture.joint_rate_hz",
       "must divide 1e9 ns into whole nanoseconds (got 3)"},
      {"joint_rate_not_per_period", {"capture.joint_rate_hz=16"}, "capture.joint_rate_hz",
       "must run a whole number of times per control period 0.1 s (got 16 Hz)"},
      {"platform_faster_than_the_period", {"capture.platform_rate_hz=20"}, "capture.platform_rate_hz",
       "must be at most the control rate, 1 / control_period_s = 10 Hz (got 20)"},
      {"negative_bandwidth", {"capture.tool_bandwidth_radps=-1"}, "capture.tool_bandwidth_radps", "must be in (0, 100]"},
      {"slosh", {"chaser.slosh={g_eff_mps2: 0.005, tanks: [{bottom_centre_body_m: [0.5, 0.0, -0.45], axis_body: [0, 0, 1], "
                 "radius_m: 0.45, height_m: 0.9, liquid_mass_kg: 150.0, density_kgpm3: 1004.0, damping_ratio: 0.005}]}"},
       "capture", "the multibody plant has no slosh yet"},
      {"camera_latency", {"sensors.arm_camera.latency_s=0.1"}, "sensors.arm_camera.latency_s",
       "must be in [0, period_s = 0.1) (got 0.1)"},
      {"camera_period", {"sensors.arm_camera.period_s=0.05"}, "sensors.arm_camera.period_s",
       "must be in [control_period_s = 0.1, 10] (got 0.05)"},
      {"stowed_outside_limits", {"chaser.arm.stowed_deg=[0, 130, 0, -110, 0, 20, 0]"}, "chaser.arm.stowed_deg.1",
       "must be within the joint's limits [-120, 120] deg (got 130)"},
      {"stowed_count", {"chaser.arm.stowed_deg=[0, 90, 0]"}, "chaser.arm.stowed_deg", "must be a list of 7 angles"},
      {"rigidise_saturation", {"capture.rigidise.saturation=tanh"}, "capture.rigidise.saturation",
       "must be one of linear, clip (got 'tanh')"},
      {"rigidise_linear_limit_at_m", {"capture.rigidise.linear_limit_Nm=176"}, "capture.rigidise.linear_limit_Nm",
       "must be below chaser.arm.torque_repeated_peak_Nm 176 (got 176)"},
      {"rigidise_no_damping", {"capture.rigidise.damping_Nms_per_rad=0"}, "capture.rigidise.damping_Nms_per_rad",
       "must be in (0, 10000000]"},
      {"rigidise_brake_rate", {"capture.rigidise.brake_rate_degps=-0.01"}, "capture.rigidise.brake_rate_degps",
       "must be in (0, 10]"},
      {"rigidise_law", {"capture.rigidise.law=pd"}, "capture.rigidise.law", "must be one of compliance, hinf (got 'pd')"},
      {"rigidise_hinf_bandwidth",
       {"capture.rigidise.law=hinf",
        "capture.rigidise.hinf={bandwidth_radps: 40, peak_sensitivity: 2, low_frequency_gain: 0.001, error_scale_rad: 0.01}"},
       "capture.rigidise.hinf.bandwidth_radps",
       "must be at most a tenth of chaser.arm.torque_loop_bandwidth_radps, 30 rad/s (got 40)"},
      {"stabilise_duration", {"capture.stabilise.duration_s=0"}, "capture.stabilise.duration_s", "must be in [1, 100000]"},
      {"stabilise_bandwidth", {"capture.stabilise.bandwidth_radps=20"}, "capture.stabilise.bandwidth_radps",
       "must be in [0.001, 10]"},
      {"stabilise_without_rigidise",
       {"capture={start_s: 2760, law: compliance, path_duration_s: 60, standoff_m: 0.15, joint_rate_hz: 1000, "
        "platform_rate_hz: 10, hub_bandwidth_radps: 1, tool_bandwidth_radps: 4, joint_bandwidth_radps: 1, "
        "damping_ratio: 1, stabilise: {duration_s: 300}}"},
       "capture.stabilise", "needs capture.rigidise"},
      {"escape_before_the_arm_wakes", {"capture.escape={command_s: 2700}"}, "capture.escape.command_s",
       "must be at or after capture.start_s 2760 (the arm awake; got 2700)"},
      {"escape_safe_distance_inside_the_axis_point", {"capture.escape={safe_distance_m: 10}"},
       "capture.escape.safe_distance_m",
       "must be beyond the point the escape withdraws to, 12 m from the target's centre "
       "(guidance.synchronised.approach.axis_distance_m; got 10)"},
      {"escape_duration", {"capture.escape={retreat_duration_s: 0}"}, "capture.escape.retreat_duration_s",
       "must be in [1, 10000]"},
      {"escape_trigger", {"capture.escape={on_failed_grasp: maybe}"}, "capture.escape.on_failed_grasp", "must be"},
      {"escape_unknown_key", {"capture.escape={safe_distance: 30}"}, "capture.escape.safe_distance", ""},
      {"escape_brake_rate", {"capture.escape={brake_rate_degps: 0}"}, "capture.escape.brake_rate_degps",
       "must be in (0, 10]"},
      {"escape_brakes", {"capture.escape={brake_when_stowed: 1.5}"}, "capture.escape.brake_when_stowed", "must be"},
      {"escape_braked_step_range", {"capture.escape={braked_step_s: 0}"}, "capture.escape.braked_step_s",
       "must be in (0, 1]"},
      {"escape_braked_step_between_joint_steps", {"capture.escape={braked_step_s: 0.0015}"}, "capture.escape.braked_step_s",
       "must be a whole number of joint periods (1 / capture.joint_rate_hz = 0.001 s) and divide control_period_s "
       "0.1 s into whole steps (got 0.0015)"},
      {"escape_braked_step_across_periods", {"capture.escape={braked_step_s: 0.03}"}, "capture.escape.braked_step_s",
       "must be a whole number of joint periods"},
      {"escape_braked_step_past_the_period", {"capture.escape={braked_step_s: 0.2}"}, "capture.escape.braked_step_s",
       "must be a whole number of joint periods"},
      {"brake_holding_torque", {"chaser.arm.brake_holding_torque_Nm=0"}, "chaser.arm.brake_holding_torque_Nm",
       "must be in (0, 100000]"},
  };
}

class BadCaptureCase : public ::testing::TestWithParam<BadCapture> {};

TEST_P(BadCaptureCase, ReportsOneErrorAtItsKeyPath) {
  const BadCapture& c = GetParam();
  const LoadResult r = load_scenario_file(kCapture, c.overrides);
  EXPECT_FALSE(r.scenario.has_value());
  EXPECT_TRUE(has_error(r, c.key_path, c.fragment)) << format_errors(r.errors);
  EXPECT_EQ(r.errors.size(), 1u) << format_errors(r.errors);
}

INSTANTIATE_TEST_SUITE_P(Rules, BadCaptureCase, ::testing::ValuesIn(bad_captures()),
                         [](const ::testing::TestParamInfo<BadCapture>& info) { return std::string(info.param.label); });

// ASSIST's berthing (scenarios/comrade_berth.yaml): each rule of capture.berthing names its key.
std::vector<BadCapture> bad_berthings() {
  return {
      {"latch_radius", {"capture.berthing.latch_radius_m=0.2"}, "capture.berthing.latch_radius_m", "must be in (0, 0.05]"},
      {"mouth_inside_the_throat", {"capture.berthing.drogue_mouth_radius_m=0.02"},
       "capture.berthing.drogue_mouth_radius_m",
       "must be wider than the throat, probe_tip_radius_m + socket_clearance_m = 0.023 m (got 0.02)"},
      {"standoff_inside_the_drogue", {"capture.standoff_m=0.1"}, "capture.standoff_m",
       "must put the probe's tip outside the drogue's mouth: beyond capture.berthing.drogue_depth_m + "
       "probe_tip_radius_m = 0.17 m (got 0.1)"},
      {"with_escape", {"capture.escape={retract_duration_s: 30}"}, "capture.escape", "not for capture.berthing"},
      {"socket_on_the_surface", {"target.body.grasp_point_target_m=[0, -1.0, 0]"}, "target.body.grasp_point_target_m",
       "with capture.berthing must lie capture.berthing.drogue_depth_m = 0.15 m inside the target's surface"},
      {"camera_bias", {"sensors.arm_camera.position_bias_m=[0, 0.6, 0]"}, "sensors.arm_camera.position_bias_m.1",
       "must be in [-0.5, 0.5] (got 0.6)"},
      {"retraction_duration", {"capture.berthing.retraction_duration_s=0"}, "capture.berthing.retraction_duration_s",
       "must be in [1, 10000]"},
      {"friction", {"capture.berthing.friction=-0.1"}, "capture.berthing.friction", "must be in [0, 2]"},
      {"unknown_key", {"capture.berthing.latch_m=0.01"}, "capture.berthing.latch_m", ""},
  };
}

class BadBerthingCase : public ::testing::TestWithParam<BadCapture> {};

TEST_P(BadBerthingCase, ReportsOneErrorAtItsKeyPath) {
  const BadCapture& c = GetParam();
  const LoadResult r = load_scenario_file("scenarios/comrade_berth.yaml", c.overrides);
  EXPECT_FALSE(r.scenario.has_value());
  EXPECT_TRUE(has_error(r, c.key_path, c.fragment)) << format_errors(r.errors);
  EXPECT_EQ(r.errors.size(), 1u) << format_errors(r.errors);
}

INSTANTIATE_TEST_SUITE_P(Rules, BadBerthingCase, ::testing::ValuesIn(bad_berthings()),
                         [](const ::testing::TestParamInfo<BadCapture>& info) { return std::string(info.param.label); });

// Every key of capture.berthing reaches its field: each set away from model/capture.hpp's default
// (so a key the reader ignored would leave the default and fail here), and the camera's bias.
TEST(CaptureSection, EveryBerthingKeyIsRead) {
  const LoadResult r = load_scenario_file(
      "scenarios/comrade_berth.yaml",
      {"capture.berthing={probe_tip_radius_m: 0.025, drogue_mouth_radius_m: 0.13, drogue_depth_m: 0.16, "
       "socket_clearance_m: 0.004, friction: 0.4, insertion_overtravel_m: 0.02, latch_radius_m: 0.006, "
       "soft_dock_timeconst_s: 0.3, retraction_m: 0.08, retraction_duration_s: 25, pin_position_tol_m: 0.004, "
       "pin_attitude_tol_deg: 1.5, contact_force_limit_N: 60}",
       "target.body.grasp_point_target_m=[0, -0.84, 0]", "sensors.arm_camera.position_bias_m=[0.001, -0.002, 0.003]"});
  ASSERT_TRUE(r.scenario) << format_errors(r.errors);
  ASSERT_TRUE(r.scenario->capture && r.scenario->capture->berthing);
  const model::BerthingParams& b = *r.scenario->capture->berthing;
  EXPECT_EQ(b.probe_tip_radius_m, 0.025);
  EXPECT_EQ(b.drogue_mouth_radius_m, 0.13);
  EXPECT_EQ(b.drogue_depth_m, 0.16);
  EXPECT_EQ(b.socket_clearance_m, 0.004);
  EXPECT_EQ(b.friction, 0.4);
  EXPECT_EQ(b.insertion_overtravel_m, 0.02);
  EXPECT_EQ(b.latch_radius_m, 0.006);
  EXPECT_EQ(b.soft_dock_timeconst_s, 0.3);
  EXPECT_EQ(b.retraction_m, 0.08);
  EXPECT_EQ(b.retraction_duration_s, 25.0);
  EXPECT_EQ(b.pin_position_tol_m, 0.004);
  EXPECT_EQ(b.pin_attitude_tol_deg, 1.5);
  EXPECT_EQ(b.contact_force_limit_N, 60.0);
  EXPECT_EQ(r.scenario->sensors.arm_camera->position_bias_m, Vec3(0.001, -0.002, 0.003));
}

TEST(CaptureSection, NeedsAnArm) {
  const LoadResult r = load_scenario_file(
      "scenarios/comrade_sync.yaml",
      {"capture={start_s: 2760, law: compliance, path_duration_s: 60, standoff_m: 0.15, joint_rate_hz: 1000, "
       "platform_rate_hz: 10, "
       "hub_bandwidth_radps: 1, tool_bandwidth_radps: 4, joint_bandwidth_radps: 1, damping_ratio: 1}"});
  EXPECT_TRUE(has_error(r, "capture", "needs chaser.arm")) << format_errors(r.errors);
}

TEST(CaptureSection, TheArmCameraNeedsAnArm) {
  const LoadResult r = load_scenario_file("scenarios/comrade_sync.yaml", {"sensors.arm_camera={period_s: 0.1, "
                                          "position_noise_m: 0.001, attitude_noise_deg: 0.2, latency_s: 0.05, "
                                          "fov_half_angle_deg: 40, range_max_m: 3}"});
  EXPECT_TRUE(has_error(r, "sensors.arm_camera", "needs chaser.arm")) << format_errors(r.errors);
}

}  // namespace capture_section_test
}  // namespace chaser::io
