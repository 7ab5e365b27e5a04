// The reach's judgement from its periods (sim/reach_result.hpp): the largest values over the hold
// only, the least clearance over the whole reach, Table 2 met or not per axis, by hand-made periods.
#include "sim/reach_result.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace chaser::sim {
namespace {

plant::GripperTruth gripper(double error_m, double velocity_mps, double attitude_rad, double rate_radps) {
  plant::GripperTruth g;
  g.r_m = Vec3(error_m, -2.0 * error_m, 0.5 * error_m);
  g.v_mps = Vec3(0.0, velocity_mps, 0.0);
  g.attitude_rad = Vec3(0.0, 0.0, -attitude_rad);
  g.omega_radps = Vec3(rate_radps, 0.0, 0.0);
  return g;
}

TEST(ReachResult, TakesTheLargestValuesOverTheHoldAndTheLeastClearanceOverTheReach) {
  ReachResult r;
  r.hold_from_s = 10.0;
  add_reach_period(r, gripper(0.5, 0.1, 0.3, 0.2), 0.0, 0.8);   // the path: far off, not judged
  add_reach_period(r, gripper(0.004, 0.003, 0.01, 0.001), 10.0, 0.12);
  add_reach_period(r, gripper(-0.006, -0.001, 0.02, -0.0005), 10.1, 0.14);
  EXPECT_TRUE(r.flown);
  EXPECT_EQ(r.hold_periods, 2);
  EXPECT_EQ(r.max_gripper_error_m, Vec3(0.006, 0.012, 0.003));
  EXPECT_EQ(r.max_gripper_velocity_mps, Vec3(0.0, 0.003, 0.0));
  EXPECT_EQ(r.max_gripper_attitude_rad, Vec3(0.0, 0.0, 0.02));
  EXPECT_EQ(r.max_gripper_rate_radps, Vec3(0.001, 0.0, 0.0));
  EXPECT_EQ(r.final_gripper.r_m.x(), -0.006);
  EXPECT_EQ(r.min_tool_clearance_m, 0.12);
  EXPECT_EQ(r.min_tool_clearance_at_s, 10.0);
  // Inside Table 2 on every axis: 12 mm sideways (22), 20 mrad (47.8), 3 mm/s (5), 1 mrad/s (1.75).
  EXPECT_TRUE(gripper_meets_table2(r));
  // One axis of the rate past 0.1 deg/s (1.745e-3 rad/s) fails it.
  add_reach_period(r, gripper(0.0, 0.0, 0.0, 0.0018), 10.2, 0.13);
  EXPECT_FALSE(gripper_meets_table2(r));
}

TEST(ReachResult, WithoutAKeepOutVolumeThereIsNoClearanceAndWithoutAHoldNoVerdict) {
  ReachResult r;
  r.hold_from_s = 100.0;
  add_reach_period(r, gripper(0.0, 0.0, 0.0, 0.0), 1.0, std::numeric_limits<double>::quiet_NaN());
  EXPECT_TRUE(std::isnan(r.min_tool_clearance_m));
  EXPECT_EQ(r.hold_periods, 0);
  EXPECT_FALSE(gripper_meets_table2(r));  // flown, but the hold never began
}

}  // namespace
}  // namespace chaser::sim
