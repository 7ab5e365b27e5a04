// The target orbit model against the two-body problem it stands for: the target sits on LVLH's
// x axis at the orbit radius, so r_T(t) = q_inertial_from_lvlh(t) (a, 0, 0) must be a Keplerian
// circle (speed sqrt(mu / a), period 2 pi / n), and LVLH's rate must be the derivative of its
// attitude.
#include "model/target_orbit.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"

namespace chaser::model {
namespace {

const OrbitParams kMars{};  // the MSR scenario's orbit: Mars, 500 km

// After a quarter orbit the LVLH x axis (radial) points along the initial y axis (along-track), and
// after a whole one it is back: the frame turns about the orbit normal at n.
TEST(TargetOrbit, LvlhTurnsAboutTheOrbitNormalOncePerPeriod) {
  const TargetOrbit orbit(kMars);
  const double period_s = 2.0 * kPi / orbit.mean_motion_radps();
  EXPECT_LT((orbit.q_inertial_from_lvlh(0.25 * period_s) * Vec3::UnitX() - Vec3::UnitY()).norm(), 1e-12);
  EXPECT_LT((orbit.q_inertial_from_lvlh(period_s) * Vec3::UnitX() - Vec3::UnitX()).norm(), 1e-12);
  EXPECT_EQ(orbit.q_inertial_from_lvlh(0.0).coeffs(), Quat::Identity().coeffs());  // inertial = LVLH at t = 0
}

// Kepler: on a circle of radius a the speed is sqrt(mu / a) and the acceleration mu / a^2 towards
// the centre. Central differences of r_T(t) over h = 1 s (errors (n h)^2 / 6 ~ 2e-7 relative for
// the speed, the same for the acceleration) against the closed forms, to 1e-6.
TEST(TargetOrbit, TheTargetFliesAKeplerCircle) {
  const TargetOrbit orbit(kMars);
  const double a = kMars.radius_m(), h = 1.0;
  const auto r_target = [&](double t) { return Vec3(orbit.q_inertial_from_lvlh(t) * Vec3(a, 0.0, 0.0)); };
  for (double t : {0.0, 1234.5, 5000.0}) {
    const Vec3 v = (r_target(t + h) - r_target(t - h)) / (2.0 * h);
    const Vec3 acc = (r_target(t + h) - 2.0 * r_target(t) + r_target(t - h)) / (h * h);
    EXPECT_NEAR(v.norm(), std::sqrt(kMars.mu_m3ps2 / a), 1e-6 * std::sqrt(kMars.mu_m3ps2 / a)) << t;
    EXPECT_NEAR(acc.norm(), kMars.mu_m3ps2 / (a * a), 1e-6 * kMars.mu_m3ps2 / (a * a)) << t;
    EXPECT_LT(acc.normalized().dot(r_target(t).normalized()), -1.0 + 1e-9) << t;  // towards the centre
    EXPECT_NEAR(r_target(t).norm(), a, 1e-9 * a) << t;
  }
}

// The frame's rate is its attitude's derivative: q(t + h) = q(t) exp(omega_lvlh h / 2) for a
// constant rate, so the rotation vector of q(t)^-1 q(t + h) is omega h (to rounding, 1e-15 rad).
TEST(TargetOrbit, RateIsTheDerivativeOfTheFrame) {
  const TargetOrbit orbit(kMars);
  const double t = 777.7, h = 10.0;
  const LvlhFrame now = orbit.lvlh_at(t);
  const Quat step = now.q_inertial_from_lvlh.conjugate() * orbit.q_inertial_from_lvlh(t + h);
  const Eigen::AngleAxisd turn(step);
  EXPECT_LT((turn.angle() * turn.axis() - now.omega_lvlh_radps * h).norm(), 1e-13);
  EXPECT_EQ(now.omega_dot_lvlh_radps2, Vec3::Zero());
  EXPECT_EQ(now.target_radius_m, kMars.radius_m());
  EXPECT_EQ(now.q_inertial_from_lvlh.coeffs(), orbit.q_inertial_from_lvlh(t).coeffs());
}

// Eq. 7 in one place: the orbit's n is the scenario's, and n^2 a^3 = mu.
TEST(TargetOrbit, MeanMotionIsEquationSeven) {
  const TargetOrbit orbit(kMars);
  EXPECT_EQ(orbit.mean_motion_radps(), kMars.mean_motion_radps());
  EXPECT_NEAR(std::pow(orbit.mean_motion_radps(), 2) * std::pow(orbit.radius_m(), 3) / orbit.mu_m3ps2(), 1.0, 1e-15);
  EXPECT_EQ(TargetOrbit(kMars.mu_m3ps2, kMars.radius_m()).mean_motion_radps(), kMars.mean_motion_radps());
}

}  // namespace
}  // namespace chaser::model
