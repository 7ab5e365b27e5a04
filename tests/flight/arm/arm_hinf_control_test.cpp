// The combined H-infinity controller (flight/arm_hinf_control.hpp) flying MuJoCo's scene on the
// capture's reference (tests/flight/arm/closed_loop_support.hpp): thirteen SB10AD loops behind
// the computed torque, at 1 kHz. The loops' bandwidths are the compliance controller's (hub 0.5
// rad/s, tool 2 rad/s, joint 1 rad/s) so that the two laws are compared on the same terms.
#include <algorithm>
#include <cstdio>

#include <gtest/gtest.h>

#include "flight/arm_hinf_control.hpp"
#include "tests/flight/arm/closed_loop_support.hpp"

namespace chaser::flight {
namespace {

using arm::testing::Loop;
using arm::testing::Measured;

ArmHinfSpec spec_for_the_test() {
  ArmHinfSpec spec;
  // The hub's authority of a platform like COMRADE's (0.05 m/s^2, 0.02 rad/s^2), the tool's and the
  // joint's well above what the reach asks; delays of one step; W_d on every loop, without which
  // the S/KS optimum cancels the double integrator's shifted poles and an initial velocity error
  // drifts away for hours (docs/control.md, "Input disturbance": measured here too, the hub 0.24 m
  // off after 40 s).
  spec.hub_position = {0.05, 1e-3, 0.5, 2.0, 1e-3, 0.01, 0.01};
  spec.hub_attitude = {0.02, 1e-3, 0.5, 2.0, 1e-3, 0.01, 0.01};
  spec.tool_position = {2.0, 1e-3, 2.0, 2.0, 1e-3, 0.01, 0.01};
  spec.tool_attitude = {5.0, 1e-3, 2.0, 2.0, 1e-3, 0.01, 0.01};
  spec.joint = {5.0, 1e-3, 1.0, 2.0, 1e-3, 0.01, 0.01};
  spec.period_s = 1e-3;
  return spec;
}

TEST(ArmHinfControl, TracksAToolPathInATumblingFrame) {
  Loop loop;
  const arm::ArmKinematics start = loop.kinematics();
  const arm::testing::TumblingReach reach(loop.params, start);
  const ArmHinfParams params = make_arm_hinf_control(spec_for_the_test());
  ArmHinfState state;
  double worst_tool_m = 0.0, worst_tool_eps = 0.0, worst_hub_m = 0.0;
  arm::ComputedTorque out;
  for (int n = 0; n < 40'000; ++n) {
    const double t = n * 1e-3;
    const Measured m = loop.measured();
    out = arm_hinf_control(params, state, loop.params,
                           arm::arm_kinematics(loop.params, m.r_hub_world_m, m.q_world_from_hub, m.joint_angles_rad),
                           m.joint_angles_rad, m.velocity, reach.at(t));
    loop.step(out.generalized_force);
    if (t < 25.0) continue;
    worst_tool_m = std::max(worst_tool_m, out.errors.pose.segment<3>(6).norm());
    worst_tool_eps = std::max(worst_tool_eps, out.errors.pose.segment<3>(9).norm());
    worst_hub_m = std::max(worst_hub_m, out.errors.pose.head<3>().norm());
  }
  // The tool: the loops' near-integral action holds it on its path to 1e-8 m (measured 1.2e-8 m,
  // eps 7.7e-10). The hub: its 0.05 m/s^2 authority saturates while it catches up with a reference
  // that starts at 0.14 m/s, and it settles with an overshoot (5 mm after 25 s, 0.9 mm at 40 s).
  EXPECT_LT(worst_tool_m, 1e-6);
  EXPECT_LT(worst_tool_eps, 1e-6);
  EXPECT_LT(worst_hub_m, 1e-2);
  EXPECT_LT(out.errors.pose.head<3>().norm(), 2e-3);
  std::printf("after 25 s: tool %.3e m, eps %.3e, hub %.3e m; at 40 s: hub %.3e m, tool %.3e m\n", worst_tool_m,
              worst_tool_eps, worst_hub_m, out.errors.pose.head<3>().norm(), out.errors.pose.segment<3>(6).norm());
}

}  // namespace
}  // namespace chaser::flight
