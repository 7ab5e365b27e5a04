// The combined compliance controller and the computed-torque precompensation flying MuJoCo's scene
// (tests/flight/arm/closed_loop_support.hpp: every generalized force applied as the law commands
// it, held over each 1 ms step, the joints' friction off).
//
// - Regulation: from the stowed arm to a grasping pose, the law's storage function V never rises
//   by more than the sampling allows, and the errors vanish. The bound: over one 1 ms step the held
//   torque's work differs from the continuous law's by O(h^2 |tau'| |v|), allowed 1e-6 V(0) per
//   step; measured: a largest rise of 3.1e-8 J from V(0) = 96 J, V(40 s) = 1.3e-5 J.
// - Tracking: the capture's reference (a tool path in a frame tumbling at 4.6 deg/s, the hub
//   starting at rest): the errors decay as the tasks' bandwidths say, feedforward doing the rest
//   (no lag is left while the frame turns).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "flight/arm/compliance_control.hpp"
#include "flight/arm/computed_torque.hpp"
#include "tests/flight/arm/closed_loop_support.hpp"

namespace chaser::flight::arm {
namespace {

using testing::Loop;
using testing::Measured;
using testing::at_rest;

ComplianceOutput compliance_step(Loop& loop, const TaskReference& reference, const ComplianceGains& gains) {
  const Measured m = loop.measured();
  const ComplianceOutput out =
      compliance_control(loop.params, arm_kinematics(loop.params, m.r_hub_world_m, m.q_world_from_hub, m.joint_angles_rad),
                         m.joint_angles_rad, m.velocity, reference, gains);
  loop.step(out.generalized_force);
  return out;
}

TEST(ComplianceControl, RegulatesToAGraspingPoseWithANonIncreasingStorage) {
  Loop loop;
  const ArmKinematics start = loop.kinematics();
  TaskReference reference;
  reference.hub = at_rest(start.r_hub_world_m, Quat(start.world_from_hub));
  // The grasping pose: the tool 3.2 m ahead of the hub's CoM and 0.3 m aside, pointing along the hub's +x.
  reference.tool = at_rest(Vec3(3.2, 0.3, -0.2), Quat::Identity());
  reference.joint_rad = 0.0;
  const ComplianceGains gains = compliance_gains(loop.params, start, ComplianceBandwidths{});
  ASSERT_TRUE(validate(gains).empty());

  double storage = compliance_step(loop, reference, gains).storage_J;
  const double storage_start = storage;
  double worst_rise_J = 0.0;
  ComplianceOutput out;
  for (int n = 1; n < 40'000; ++n) {
    out = compliance_step(loop, reference, gains);
    worst_rise_J = std::max(worst_rise_J, out.storage_J - storage);
    storage = out.storage_J;
  }
  EXPECT_GT(storage_start, 50.0);
  EXPECT_LT(worst_rise_J, 1e-6 * storage_start);
  EXPECT_LT(out.errors.pose.segment<3>(6).norm(), 1e-4);  // [m]
  EXPECT_LT(out.errors.pose.segment<3>(9).norm(), 1e-4);  // [-] eps, half the angle: 0.01 deg
  EXPECT_LT(out.errors.pose.head<3>().norm(), 1e-4);
  EXPECT_LT(out.errors.velocity.norm(), 1e-3);
  EXPECT_LT(storage, 1e-6 * storage_start);
  std::printf("storage %.3f J -> %.3e J, worst rise per step %.3e J, tool error %.3e m\n", storage_start, storage,
              worst_rise_J, out.errors.pose.segment<3>(6).norm());
}

TEST(ComplianceControl, TracksAToolPathInATumblingFrame) {
  Loop loop;
  const ArmKinematics start = loop.kinematics();
  const testing::TumblingReach reach(loop.params, start);
  const ComplianceGains gains = compliance_gains(loop.params, start, ComplianceBandwidths{});
  double worst_tool_m = 0.0, worst_tool_eps = 0.0, worst_hub_m = 0.0;
  ComplianceOutput out;
  for (int n = 0; n < 40'000; ++n) {
    const double t = n * 1e-3;
    out = compliance_step(loop, reach.at(t), gains);
    if (t < 25.0) continue;
    worst_tool_m = std::max(worst_tool_m, out.errors.pose.segment<3>(6).norm());
    worst_tool_eps = std::max(worst_tool_eps, out.errors.pose.segment<3>(9).norm());
    worst_hub_m = std::max(worst_hub_m, out.errors.pose.head<3>().norm());
  }
  // From 25 s on: the tool within 0.1 mm and 0.01 deg of its path, the hub (its task tuned to
  // 0.5 rad/s, critically damped) within 1 mm and closing; at 40 s both within 0.1 mm.
  EXPECT_LT(worst_tool_m, 1e-4);
  EXPECT_LT(worst_tool_eps, 1e-4);
  EXPECT_LT(worst_hub_m, 1e-3);
  EXPECT_LT(out.errors.pose.head<3>().norm(), 1e-4);
  EXPECT_LT(out.errors.pose.segment<3>(6).norm(), 1e-5);
  std::printf("after 25 s: tool %.3e m, eps %.3e, hub %.3e m; at 40 s: hub %.3e m, tool %.3e m\n", worst_tool_m,
              worst_tool_eps, worst_hub_m, out.errors.pose.head<3>().norm(), out.errors.pose.segment<3>(6).norm());
}

// The computed-torque precompensation makes each task's error a double integrator: under u = -k e
// - d e' (critically damped at w = 2 rad/s) a position error of the tool starting at e0 with no
// rate follows e0 (1 + w t) exp(-w t), and the tasks without an initial error keep none. The law
// held over each 1 ms step: the closed form holds to the sampling's O(w h) = 2e-3 of e0 (measured
// 3.8e-4 of it; the other tasks 5e-8).
TEST(ComputedTorque, MakesEachTasksErrorTheDesignedSecondOrderResponse) {
  Loop loop;
  const ArmKinematics start = loop.kinematics();
  const Measured m0 = loop.measured();
  TaskReference reference;
  reference.hub = at_rest(start.r_hub_world_m, Quat(start.world_from_hub));
  const Vec3 e0(0.02, -0.03, 0.01);
  reference.tool = at_rest(start.r_tool_world_m - e0, Quat(start.world_from_link[6]));
  reference.joint_rad = m0.joint_angles_rad(kRedundancyJoint);
  const double w = 2.0, k = w * w, d = 2.0 * w;
  double worst_m = 0.0, worst_others = 0.0;
  for (int n = 0; n <= 5'000; ++n) {
    const double t = n * 1e-3;
    const Measured m = loop.measured();
    const ArmKinematics kin = arm_kinematics(loop.params, m.r_hub_world_m, m.q_world_from_hub, m.joint_angles_rad);
    const TaskErrors errors = task_errors(kin, extended_jacobian(kin), m.joint_angles_rad, m.velocity, reference);
    const TaskVector u = -k * loop_errors(errors) - d * errors.velocity;
    const ComputedTorque out = computed_torque(loop.params, kin, m.joint_angles_rad, m.velocity, reference, u);
    const Vec3 expected = e0 * (1.0 + w * t) * std::exp(-w * t);
    worst_m = std::max(worst_m, (out.errors.pose.segment<3>(6) - expected).norm());
    TaskVector others = out.errors.pose;
    others.segment<3>(6).setZero();
    worst_others = std::max(worst_others, others.cwiseAbs().maxCoeff());
    loop.step(out.generalized_force);
  }
  EXPECT_LT(worst_m, 2e-3 * e0.norm());
  EXPECT_LT(worst_others, 1e-6);
  std::printf("tool error against the closed form: %.3e m (e0 %.3e m); other tasks: %.3e\n", worst_m, e0.norm(),
              worst_others);
}

}  // namespace
}  // namespace chaser::flight::arm
