// The reach's pieces that need no plant: the platform command sampled at its own rate, the tool's
// path in the target's frame.
#include "flight/reach.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace chaser::flight {
namespace {

// At 3 Hz on a 0.1 s control period the law's force is taken at the first period at or after each
// tick (0, 1/3, 2/3, 1 s: the periods at 0, 0.4, 0.7, 1.0 s) and held in between; before the law
// has run there is none.
TEST(ReachPlatformCommand, IsSampledAtThePlatformsRateAndHeld) {
  ReachParams params;
  params.platform_period_s = 1.0 / 3.0;
  ReachState state;
  Vec3 force, torque;
  EXPECT_FALSE(platform_command(params, state, 0.0, force, torque));
  state.has_output = true;
  std::vector<double> sampled_at;
  for (int k = 0; k <= 10; ++k) {
    const double t = 0.1 * k;
    state.platform_force_inertial_N = Vec3(t, 0.0, 0.0);  // the law's output changes every period
    state.platform_torque_body_Nm = Vec3(0.0, 0.0, -t);
    ASSERT_TRUE(platform_command(params, state, t, force, torque));
    if (force.x() == t) sampled_at.push_back(t);
    EXPECT_EQ(torque.z(), -force.x());
  }
  ASSERT_EQ(sampled_at.size(), 4u);
  EXPECT_DOUBLE_EQ(sampled_at[0], 0.0);
  EXPECT_NEAR(sampled_at[1], 0.4, 1e-12);
  EXPECT_NEAR(sampled_at[2], 0.7, 1e-12);
  EXPECT_NEAR(sampled_at[3], 1.0, 1e-12);
}

// At the control rate every period takes the law's latest output.
TEST(ReachPlatformCommand, AtTheControlRateEveryPeriodSamples) {
  ReachParams params;
  params.platform_period_s = 0.1;
  ReachState state;
  state.has_output = true;
  Vec3 force, torque;
  for (int k = 0; k < 50; ++k) {
    state.platform_force_inertial_N = Vec3(k, 0.0, 0.0);
    ASSERT_TRUE(platform_command(params, state, 0.1 * k, force, torque));
    EXPECT_EQ(force.x(), k);
  }
}

// The tool's path: from its start to the pre-grasp pose in path_duration_s with zero rate at both
// ends, its velocity the derivative of its position (central differences).
TEST(ReachToolPath, GoesFromItsStartToThePreGraspPoseSmoothly) {
  ReachParams params;
  params.start_s = 100.0;
  params.path_duration_s = 60.0;
  params.pre_grasp_target_m = Vec3(4.05, 0.0, 0.6);
  params.q_target_from_tool = Quat(0.0, 0.0, 0.0, 1.0);
  ReachState state;
  state.tool_start_target_m = Vec3(5.0, 1.0, 0.0);
  state.q_target_from_tool_start = Quat(Eigen::AngleAxisd(2.9, Vec3(0.1, 0.2, 1.0).normalized()));
  const arm::FrameMotion start = tool_path(params, state, 100.0), end = tool_path(params, state, 160.0);
  EXPECT_LT((start.r_m - state.tool_start_target_m).norm(), 1e-15);
  EXPECT_LT((end.r_m - params.pre_grasp_target_m).norm(), 1e-12);
  EXPECT_LT(end.q_world_from_frame.angularDistance(params.q_target_from_tool), 1e-9);
  EXPECT_EQ(start.v_mps.norm(), 0.0);
  EXPECT_EQ(end.v_mps.norm(), 0.0);
  const double h = 1e-4;
  for (const double t : {105.0, 130.0, 151.0}) {
    const arm::FrameMotion now = tool_path(params, state, t);
    const arm::FrameMotion ahead = tool_path(params, state, t + h), behind = tool_path(params, state, t - h);
    EXPECT_LT((now.v_mps - (ahead.r_m - behind.r_m) / (2 * h)).norm(), 1e-8);
    EXPECT_LT((now.a_mps2 - (ahead.v_mps - behind.v_mps) / (2 * h)).norm(), 1e-8);
    const Quat q_rate((ahead.q_world_from_frame.coeffs() - behind.q_world_from_frame.coeffs()) / (2 * h));
    EXPECT_LT((now.omega_radps - 2.0 * (q_rate * now.q_world_from_frame.conjugate()).vec()).norm(), 1e-8);
  }
}

}  // namespace
}  // namespace chaser::flight
