#include "invsim/desired_trajectory.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace chaser::invsim {
namespace {

// The desired x and x' are continuous where the exponential phase begins, and the exponential
// ends at the docking point: x(t) - x_dock decays by e^-1 per time constant.
TEST(DesiredTrajectory, ContinuousAtDampingStartAndConvergesToDock) {
  model::InvSimTrajectoryParams p;
  p.dock_x_m = 10.0;
  p.damping_start_s = 800.0;
  p.damping_time_constant_s = 100.0;
  const double x0 = 100.038;
  const Vec6 before = desired_state(p, x0, 800.0);
  const Vec6 after = desired_state(p, x0, 800.0 + 1e-9);
  EXPECT_NEAR(before(0), after(0), 1e-9);
  EXPECT_NEAR(before(3), after(3), 1e-9);
  EXPECT_NEAR(approach_velocity_mps(p, x0), -90.038 / 900.0, 1e-15);
  const Vec6 later = desired_state(p, x0, 900.0);
  EXPECT_NEAR(later(0) - 10.0, (before(0) - 10.0) * std::exp(-1.0), 1e-12);
  EXPECT_EQ(desired_state(p, x0, 300.0).segment<2>(1), Eigen::Vector2d::Zero());
  EXPECT_NEAR(desired_state(p, x0, 0.0)(0), x0, 1e-15);
}

}  // namespace
}  // namespace chaser::invsim
