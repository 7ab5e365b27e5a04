// The reach and the grasp flown end to end (scenarios/comrade_capture.yaml): the synchronisation,
// then the arm woken on the multibody plant and the combined controller at 1 kHz holding the chaser
// at the capture point while the gripper goes to the pre-grasp pose, then onto the fixture, where
// the jaws close and the gripper locks. Judged by the truth (MuJoCo's gripper against the fixture
// on the target's body), never by the flight software's own errors.
#include <cmath>

#include <gtest/gtest.h>

#include "io/scenario_loader.hpp"
#include "sim/run.hpp"
#include "sim/telemetry.hpp"

namespace chaser::sim {
namespace {

model::Scenario capture_scenario(std::vector<std::string> overrides = {}) {
  const io::LoadResult loaded = io::load_scenario_file("scenarios/comrade_capture.yaml", overrides);
  EXPECT_TRUE(loaded.scenario) << io::format_errors(loaded.errors);
  return *loaded.scenario;
}

double largest(const std::array<double, model::kArmJoints>& v) { return *std::max_element(v.begin(), v.end()); }

// With the arm camera (COMRADE 2018's Fig. 11): the gripper's position, attitude and velocity
// inside Table 2 over the whole hold (measured: 8.9, 6.1, 3.2 mm; 0.35, 0.34, 0.16 deg; 4.0,
// 4.5, 4.3 mm/s), the chaser within Table 2 at the end, the joints far below their 176 N m (6.4
// N m up to the capture). The rate is not, on one axis: 0.14 deg/s about z against 0.1
// (docs/servicing.md, "The reach"). Then the grasp and the rigidisation (the test below it).
TEST(Reach, TheComplianceLawPutsTheGripperInsideTable2sEnvelope) {
  TelemetryRows telemetry;
  RunOptions options;
  options.telemetry_channels = {"t_s", "ton_real_*"};
  options.telemetry_rows = &telemetry;
  const RunResult r = run_scenario(capture_scenario(), options);
  ASSERT_FALSE(r.figures.diverged);
  ASSERT_GE(r.phases.size(), 4u);
  const std::size_t n = r.phases.size();
  EXPECT_EQ(r.phases[n - 4].name, "reach");
  EXPECT_EQ(r.phases[n - 3].name, "capture");
  EXPECT_EQ(r.phases[n - 3].end_reason, "captured");
  EXPECT_EQ(r.phases[n - 2].name, "rigidisation");
  EXPECT_EQ(r.phases[n - 2].end_reason, "brakes engaged");
  EXPECT_EQ(r.phases.back().name, "stabilisation");
  const ReachResult& reach = r.reach;
  ASSERT_TRUE(reach.flown);
  EXPECT_GT(reach.hold_periods, 100);
  EXPECT_GT(reach.camera_samples, 300);
  for (int k = 0; k < 3; ++k) {
    EXPECT_LT(reach.max_gripper_error_m(k), kTable2GripperErrorM[k]) << k;
    EXPECT_LT(reach.max_gripper_attitude_rad(k), kTable2GripperAttitudeDeg * model::kArmDegToRad) << k;
    EXPECT_LT(reach.max_gripper_velocity_mps(k), kTable2GripperVelocityMps) << k;
  }
  EXPECT_LT(largest(reach.peak_joint_torque_Nm), 30.0);
  // The tool stays clear of the target's keep-out volume on its way: its least clearance is the
  // hold's, the 0.15 m standoff less the approach error (measured 0.141 m at 2,844.7 s).
  EXPECT_GT(reach.min_tool_clearance_m, 0.1);
  EXPECT_LT(reach.min_tool_clearance_m, 0.16);
  EXPECT_GE(reach.min_tool_clearance_at_s, reach.hold_from_s);
  // At the run's end, after the stabilisation, the chaser is where the braked arm holds it: within
  // Table 1's 0.1 m of the capture point (measured 0.068 m: 0.026 at the brakes, then the braked
  // joints creep under the thrusters' pulses, the wrist by 0.42 deg; docs/servicing.md).
  EXPECT_LT(r.figures.final_position_error_m, 0.1);
  EXPECT_LT(r.figures.final_attitude_error_rad, kTable2ChaserAttitudeDeg * model::kArmDegToRad);
  // The grasp: the jaws close on the third camera sample inside the envelope after the approach
  // (2,880.2 s), both fingers hold the lip 0.2 s later and the gripper locks. At the closure the
  // gripper is inside every figure of Table 2 (measured 6.9, 0.6, 0.2 mm; 0.5, 1.1, 0.02 mm/s;
  // 0.05 deg/s at most) and so is the chaser (0.038 m, 1.9 mm/s, 0.47 deg, 0.02 deg/s).
  const GraspResult& grasp = reach.grasp;
  EXPECT_TRUE(grasp.attempted);
  EXPECT_STREQ(grasp.outcome, "captured");
  EXPECT_GE(grasp.closure_s, capture_scenario().capture->approach_start_s() + 30.0);
  EXPECT_LT(grasp.captured_s, grasp.closure_s + 1.0);
  EXPECT_GE(grasp.captured_s, grasp.lock_s);
  EXPECT_TRUE(grasp.judged);
  EXPECT_TRUE(grasp_meets_table2(grasp));

  // The rigidisation (flight/rigidise.hpp) from the joint step the gripper reported itself locked:
  // from the next control period (the phase's start) to the brakes no thruster fires; the arm alone brings every joint below 0.01
  // deg/s, which it holds for the dwell, and the brakes engage (measured 11.5 s after the capture);
  // its torques stay far below the drives' 176 N m (measured 10.0 N m) and the joints end within a
  // degree of where it held them (0.57 deg: the arm now carries the chaser's centripetal load);
  // braked, a joint creeps at most at the brakes' 1e-3 deg/s (arm_joints_test.cpp).
  const RigidiseResult& rigidise = reach.rigidise;
  ASSERT_TRUE(rigidise.flown);
  EXPECT_NEAR(rigidise.start_s, grasp.captured_s, 1e-3 + 1e-9);
  EXPECT_NEAR(r.phases[n - 2].start_s, rigidise.start_s, 0.1 + 1e-9);  // the next control period
  EXPECT_GT(rigidise.brakes_s, rigidise.start_s + 1.0);
  EXPECT_LT(rigidise.brakes_s, rigidise.start_s + 20.0);
  EXPECT_LT(largest(rigidise.peak_torque_Nm), 30.0);
  for (int j = 0; j < model::kArmJoints; ++j) {
    const auto i = static_cast<std::size_t>(j);
    EXPECT_LT(std::abs(rigidise.final_angle_error_rad[i]), 1.0 * model::kArmDegToRad) << j;
    EXPECT_LT(std::abs(rigidise.final_rate_radps[i]), 1e-3 * model::kArmDegToRad) << j;
  }
  const std::size_t channels = telemetry.channels.size();
  int periods_after = 0;
  int periods_firing_after = 0;
  for (std::size_t row = 0; row < telemetry.rows(); ++row) {
    const double t_s = telemetry.values[row * channels];
    if (t_s < r.phases[n - 2].start_s - 1e-9) continue;
    bool firing = false;
    for (std::size_t c = 1; c < channels; ++c) firing = firing || telemetry.values[row * channels + c] != 0.0;
    if (t_s < r.phases.back().start_s - 1e-9) {
      ++periods_after;
      EXPECT_FALSE(firing) << t_s;
    } else {
      periods_firing_after += firing;
    }
  }
  EXPECT_GT(periods_after, 100);

  // The stabilisation (flight/stabilise.hpp) from the brakes' period: the thrusters detumble the
  // composite from 2.74 deg/s (ENVISAT's 2.5 and the chaser's share) along the momentum's linear
  // reference over 300 s, so below Table 3's 0.5 deg/s after ~82 % of it (measured 241.6 s) and
  // at the end 0.002-0.004 deg/s per axis (Table 8's H-infinity: 0.023, 0.006, 0.013). The braked
  // joints' loads peak where the thrusters' full-thrust pulses reach them (measured 91.9 N m, the
  // period's mean couple ~30 N m; the brakes' engagement 84 N m), within the 176 N m repeated peak;
  // 3.05 kg of propellant.
  const StabiliseResult& stabilise = reach.stabilise;
  ASSERT_TRUE(stabilise.flown);
  EXPECT_NEAR(stabilise.start_s, r.phases.back().start_s, 1e-9);
  EXPECT_NEAR(stabilise.start_s, rigidise.brakes_s, 0.1 + 1e-9);
  EXPECT_GT(periods_firing_after, 1000);
  EXPECT_NEAR(stabilise.initial_rate_degps, 2.74, 0.05);
  EXPECT_GT(stabilise.below_goal_s, stabilise.start_s + 200.0);
  EXPECT_LT(stabilise.below_goal_s, stabilise.start_s + 260.0);
  EXPECT_LT(stabilise.final_rate_target_degps.cwiseAbs().maxCoeff(), 0.02);
  EXPECT_GT(largest(rigidise.peak_brake_load_Nm), 20.0);
  EXPECT_LT(largest(rigidise.peak_brake_load_Nm), 176.0);
  EXPECT_GT(stabilise.propellant_kg, 2.0);
  EXPECT_LT(stabilise.propellant_kg, 4.0);
}

// Without the camera (Fig. 12: the fixture where the target estimator puts it) the gripper misses
// the envelope sideways by the estimate's error, ~0.4 deg at 4-7 m from the target's centre:
// measured 34 and 28 mm against 22. The camera is what makes the reach.
// Nor does the gripper close blind: with no camera sample inside the envelope, the grasp is
// abandoned grasp_timeout_s after the approach, the jaws never commanded.
TEST(Reach, WithoutTheArmCameraTheTargetsEstimateLeavesTheGripperOutside) {
  model::Scenario s = capture_scenario();
  s.sensors.arm_camera.reset();
  s.duration_s = s.capture->approach_start_s() + s.capture->approach_duration_s + s.capture->grasp_timeout_s + 1.0;
  const RunResult r = run_scenario(s);
  ASSERT_TRUE(r.reach.flown);
  EXPECT_EQ(r.reach.camera_samples, 0);
  EXPECT_GT(std::max(r.reach.max_gripper_error_m.y(), r.reach.max_gripper_error_m.z()), kTable2GripperErrorM[1]);
  EXPECT_STREQ(r.reach.grasp.outcome, "abandoned");
  EXPECT_FALSE(r.reach.grasp.judged);
  EXPECT_TRUE(std::isnan(r.reach.grasp.closure_s));
}

// The H-infinity law flies the same reach: the gripper inside the position envelope (measured 6.0,
// 7.1, 6.7 mm), the joints below their limit (21.9 N m); its loops' near-integral action hunts
// against the joints' friction (a roll rate of 2.9 deg/s, docs/servicing.md).
TEST(Reach, TheHinfLawFliesTheSameReach) {
  // H-infinity throughout: the reach, the rigidisation and the stabilisation, whose reference is cut
  // to 100 s (300 in the scenario) and the run to 3,100 s: its loops detumble along a reference
  // three times as steep, in a third of the time.
  const RunResult r = run_scenario(capture_scenario({"capture.law=hinf", "capture.rigidise.law=hinf",
                                                     "capture.stabilise.law=hinf", "capture.stabilise.duration_s=100",
                                                     "duration_s=3100"}));
  ASSERT_TRUE(r.reach.flown);
  for (int k = 0; k < 3; ++k) EXPECT_LT(r.reach.max_gripper_error_m(k), kTable2GripperErrorM[k]) << k;
  EXPECT_LT(largest(r.reach.peak_joint_torque_Nm), 30.0);
  // It grasps too; at the closure its gripper rolls at 0.78 deg/s and the chaser is 0.054 m off:
  // Table 2 is not met there (measured).
  EXPECT_STREQ(r.reach.grasp.outcome, "captured");
  EXPECT_FALSE(grasp_meets_table2(r.reach.grasp));
  // Its wrist's roll at the capture is the rigidisation's hardest start: the H-infinity
  // rigidisation's loops (flight/rigidise.hpp) brake all the same (measured 63 s after the capture,
  // the torques at most 12.8 N m; the saturated PD brakes in 10.5 s at 27.8 N m from there).
  EXPECT_LT(r.reach.rigidise.brakes_s, r.reach.rigidise.start_s + 90.0);
  EXPECT_LT(largest(r.reach.rigidise.peak_torque_Nm), 30.0);
  // And COMRADE's H-infinity stabilisation (capture.stabilise.law hinf) from there detumbles the
  // composite as the momentum law does (measured below).
  EXPECT_FALSE(std::isnan(r.reach.stabilise.below_goal_s));
  EXPECT_LT(r.reach.stabilise.final_rate_target_degps.cwiseAbs().maxCoeff(), 0.02);
  EXPECT_LT(largest(r.reach.rigidise.peak_brake_load_Nm), 176.0);
}

// The same scenario and seed give the same bits: MuJoCo's pipeline, the joint loop and the camera.
TEST(Reach, TheSameSeedGivesTheSameBits) {
  model::Scenario s = capture_scenario();
  s.duration_s = s.capture->start_s + 5.0;
  const RunResult a = run_scenario(s), b = run_scenario(s);
  EXPECT_EQ(a.reach.final_gripper.r_m, b.reach.final_gripper.r_m);
  EXPECT_EQ(a.reach.final_gripper.omega_radps, b.reach.final_gripper.omega_radps);
  EXPECT_EQ(a.figures.final_position_error_m, b.figures.final_position_error_m);
}

}  // namespace
}  // namespace chaser::sim
