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

// The paper reading's lateral return: it starts at the initial state (Table 3's y, z and rates),
// its velocity is the derivative of its position (central difference over 1 ms, 1e-9 m/s: the
// difference's error is h^2 / 6 times the third derivative, ~1e-12), it decays as t e^(-t / T)
// (critically damped) and it leaves x alone.
TEST(DesiredTrajectory, LateralReturnStartsAtTheInitialStateAndDecays) {
  const Vec3 r0(100.038, -0.0167, -0.023), v0(-0.0076, 0.131, -0.0087);
  const double T = 50.0;
  Vec6 x = Vec6::Constant(7.0);
  set_lateral_return(T, r0, v0, 0.0, x);
  EXPECT_NEAR(x(1), r0.y(), 1e-15);
  EXPECT_NEAR(x(2), r0.z(), 1e-15);
  EXPECT_NEAR(x(4), v0.y(), 1e-15);
  EXPECT_NEAR(x(5), v0.z(), 1e-15);
  EXPECT_EQ(x(0), 7.0);
  EXPECT_EQ(x(3), 7.0);
  for (double t : {10.0, 50.0, 200.0}) {
    Vec6 a = x, b = x, c = x;
    set_lateral_return(T, r0, v0, t - 1e-3, a);
    set_lateral_return(T, r0, v0, t + 1e-3, b);
    set_lateral_return(T, r0, v0, t, c);
    for (int axis : {1, 2}) {
      EXPECT_NEAR((b(axis) - a(axis)) / 2e-3, c(axis + 3), 1e-9) << t;
      const double slope = v0(axis) + r0(axis) / T;
      EXPECT_NEAR(c(axis), (r0(axis) + slope * t) * std::exp(-t / T), 1e-15) << t;
    }
  }
  Vec6 late = x;
  set_lateral_return(T, r0, v0, 1300.0, late);
  EXPECT_LT(std::abs(late(1)), 1e-9);  // (0.131 + ...) 1300 e^-26
}

// The brake before the return: a closed form to check against. From Table 3's y' = +0.131 m/s at
// a = 0.0075 m/s^2 (half a y group's 120 N on 8,000 kg) the drift stops at t = 17.47 s after
// y' t / 2 = 1.144 m, at y = -0.0167 + 1.14407 = 1.12737 m; before that the path is the uniformly decelerated one (its second
// difference over 1 ms is -a to 1e-6 m/s^2: rounding of 1e-15 m over 1e-6 s^2), after it the
// critically damped return from the stopping point at rest. Position and velocity are continuous at
// the stop (1e-12), and z (z' = -0.0087 m/s) brakes the other way (+a) and stops after 1.16 s.
TEST(DesiredTrajectory, LateralBrakeStopsTheDriftThenReturns) {
  const Vec3 r0(100.038, -0.0167, -0.023), v0(-0.0076, 0.131, -0.0087);
  const double a = 0.0075, T = 100.0;
  const auto at = [&](double t) {
    Vec6 x = Vec6::Constant(7.0);
    set_lateral_brake_then_return(a, T, r0, v0, t, x);
    return x;
  };
  EXPECT_EQ(at(0.0)(0), 7.0);  // x is the approach's
  EXPECT_EQ(at(0.0)(3), 7.0);
  EXPECT_NEAR(at(0.0)(1), r0.y(), 1e-15);
  EXPECT_NEAR(at(0.0)(4), v0.y(), 1e-15);
  const double t_stop = 0.131 / a;
  const double y_stop = r0.y() + 0.131 * t_stop / 2.0;
  for (double t : {1.0, 8.0, 17.0}) {
    const Vec6 x = at(t);
    EXPECT_NEAR(x(1), r0.y() + 0.131 * t - a * t * t / 2.0, 1e-15) << t;
    EXPECT_NEAR(x(4), 0.131 - a * t, 1e-15) << t;
    EXPECT_NEAR((at(t + 1e-3)(1) - 2.0 * x(1) + at(t - 1e-3)(1)) / 1e-6, -a, 1e-6) << t;
  }
  EXPECT_NEAR(at(t_stop)(1), 1.12737, 1e-5);  // the hand figure above, to its digits
  EXPECT_NEAR(at(t_stop - 1e-9)(1), y_stop, 1e-12);
  EXPECT_NEAR(at(t_stop + 1e-9)(1), y_stop, 1e-12);
  EXPECT_NEAR(at(t_stop + 1e-9)(4), 0.0, 1e-12);
  for (double tau : {10.0, 100.0, 400.0}) {
    const Vec6 x = at(t_stop + tau);
    EXPECT_NEAR(x(1), y_stop * (1.0 + tau / T) * std::exp(-tau / T), 1e-15) << tau;
    EXPECT_NEAR(x(4), -y_stop * tau / (T * T) * std::exp(-tau / T), 1e-15) << tau;
  }
  EXPECT_NEAR(at(0.5)(5), -0.0087 + a * 0.5, 1e-15);
  EXPECT_NEAR(at(0.0087 / a + 1e-9)(5), 0.0, 1e-12);
  // No drift: the brake has nothing to do and the path is the plain return.
  Vec6 plain = Vec6::Zero(), braked = Vec6::Zero();
  const Vec3 still(0.0, 0.0, 0.0);
  set_lateral_return(T, r0, still, 30.0, plain);
  set_lateral_brake_then_return(a, T, r0, still, 30.0, braked);
  EXPECT_EQ(plain, braked);
}

}  // namespace
}  // namespace chaser::invsim
