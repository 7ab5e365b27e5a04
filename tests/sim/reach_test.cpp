// The reach and the grasp flown end to end (scenarios/comrade_capture.yaml): the synchronisation,
// then the arm woken on the multibody plant and the combined controller at 1 kHz holding the chaser
// at the capture point while the gripper goes to the pre-grasp pose, then onto the fixture, where
// the jaws close and the gripper locks. Judged by the truth (MuJoCo's gripper against the fixture
// on the target's body), never by the flight software's own errors.
#include <cmath>

#include <gtest/gtest.h>

#include "io/scenario_loader.hpp"
#include "sim/run.hpp"

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
// 4.5, 4.3 mm/s), the chaser within Table 2 at the end, the joints far below their 176 N m (17.6
// N m). The rate is not, on one axis: 0.14 deg/s about z against 0.1 (docs/servicing.md, "The reach").
TEST(Reach, TheComplianceLawPutsTheGripperInsideTable2sEnvelope) {
  const RunResult r = run_scenario(capture_scenario());
  ASSERT_FALSE(r.figures.diverged);
  ASSERT_GE(r.phases.size(), 2u);
  EXPECT_EQ(r.phases[r.phases.size() - 2].name, "reach");
  EXPECT_EQ(r.phases.back().name, "capture");
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
  EXPECT_LT(r.figures.final_position_error_m, kTable2ChaserPositionM);
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
  const RunResult r = run_scenario(capture_scenario({"capture.law=hinf"}));
  ASSERT_TRUE(r.reach.flown);
  for (int k = 0; k < 3; ++k) EXPECT_LT(r.reach.max_gripper_error_m(k), kTable2GripperErrorM[k]) << k;
  EXPECT_LT(largest(r.reach.peak_joint_torque_Nm), 30.0);
  // It grasps too; at the closure its gripper rolls at 0.78 deg/s and the chaser is 0.054 m off:
  // Table 2 is not met there (measured).
  EXPECT_STREQ(r.reach.grasp.outcome, "captured");
  EXPECT_FALSE(grasp_meets_table2(r.reach.grasp));
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
