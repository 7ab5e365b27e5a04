#include "flight/guidance.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "core/rotation.hpp"

namespace chaser::flight {
namespace guidance_test {

const model::TargetOrbit kOrbit{model::OrbitParams{}};  // the MSR scenario's: Mars, 500 km
const double kN = kOrbit.mean_motion_radps();           // [rad/s]

model::GuidanceParams default_params() { return model::GuidanceParams{}; }

// The profile starts at rest at the start distance and ends at rest at the capture distance,
// exactly on the axis, and holds outside [0, D].
TEST(Guidance, EndpointsAndHolds) {
  const model::GuidanceParams p = default_params();
  const Vec3 u = p.approach_axis_lvlh.normalized();
  for (double t : {-100.0, 0.0}) {
    const GuidanceRef ref = guidance_reference(p, kOrbit, t);
    EXPECT_LT((ref.r_lvlh_m - p.start_distance_m * u).norm(), 1e-15);
    EXPECT_EQ(ref.v_lvlh_mps.norm(), 0.0);
    EXPECT_EQ(ref.a_lvlh_mps2.norm(), 0.0);
  }
  for (double t : {p.approach_duration_s, p.approach_duration_s + 500.0}) {
    const GuidanceRef ref = guidance_reference(p, kOrbit, t);
    EXPECT_LT((ref.r_lvlh_m - p.capture_distance_m * u).norm(), 1e-14);
    EXPECT_EQ(ref.v_lvlh_mps.norm(), 0.0);
    EXPECT_EQ(ref.a_lvlh_mps2.norm(), 0.0);
  }
}

// v = dr/dt, a = dv/dt and j = da/dt, checked by central differences with h = 1e-3 s at points away
// from the phase boundaries (where j jumps). Truncation error h^2/6 * |next derivative| < 1e-13 and
// round-off eps |r| / h ~ 4e-12, so 1e-9 is a safe bound that still fails on any missing factor
// (the quantities themselves are 1e-2, 5e-4 and 2.4e-5).
TEST(Guidance, VelocityAndAccelerationAreDerivatives) {
  const model::GuidanceParams p = default_params();
  const double h = 1e-3;
  for (double t = 0.37; t < p.approach_duration_s; t += 7.3) {
    const GuidanceRef ref = guidance_reference(p, kOrbit, t);
    const GuidanceRef plus = guidance_reference(p, kOrbit, t + h), minus = guidance_reference(p, kOrbit, t - h);
    EXPECT_LT(((plus.r_lvlh_m - minus.r_lvlh_m) / (2 * h) - ref.v_lvlh_mps).norm(), 1e-9) << t;
    EXPECT_LT(((plus.v_lvlh_mps - minus.v_lvlh_mps) / (2 * h) - ref.a_lvlh_mps2).norm(), 1e-9) << t;
    EXPECT_LT(((plus.a_lvlh_mps2 - minus.a_lvlh_mps2) / (2 * h) - ref.j_lvlh_mps3).norm(), 1e-9) << t;
  }
}

// Position, velocity and acceleration are continuous at the four phase boundaries (rest/blend,
// blend/cruise, cruise/blend, blend/rest): a jump there would kick the controller. Across a window
// of 2e-9 s each quantity may move by 2e-9 times its derivative (speed 0.017 m/s, acceleration
// 4.6e-4 m/s^2, jerk 2.4e-5 m/s^3), i.e. < 4e-11, 1e-12 and 1e-13; a jump would be ~1e-2 to 1e-4.
TEST(Guidance, ContinuousAtPhaseBoundaries) {
  const model::GuidanceParams p = default_params();
  const double D = p.approach_duration_s, tb = p.blend_time_s, e = 1e-9;
  for (double tc : {0.0, tb, D - tb, D}) {
    const ApproachProfile lo = approach_profile(p, tc - e), hi = approach_profile(p, tc + e);
    EXPECT_NEAR(lo.distance_m, hi.distance_m, 1e-10) << tc;
    EXPECT_NEAR(lo.rate_mps, hi.rate_mps, 1e-11) << tc;
    EXPECT_NEAR(lo.accel_mps2, hi.accel_mps2, 1e-12) << tc;
  }
}

// In the cruise the speed is (d0 - d1) / (D - tb): the two half-blends together lose exactly one
// blend time of cruise. Peak acceleration is pi/2 * speed / tb.
TEST(Guidance, CruiseSpeedAndPeakAcceleration) {
  const model::GuidanceParams p = default_params();
  const double speed = (p.start_distance_m - p.capture_distance_m) / (p.approach_duration_s - p.blend_time_s);
  EXPECT_NEAR(approach_profile(p, 0.5 * p.approach_duration_s).rate_mps, -speed, 1e-15);
  EXPECT_NEAR(approach_profile(p, 0.5 * p.blend_time_s).accel_mps2, -0.5 * kPi * speed / p.blend_time_s, 1e-15);
}

// A duration shorter than two blends degrades to a pure cosine profile that still reaches the
// capture point at D with zero speed.
TEST(Guidance, ShortDurationStillArrivesAtRest) {
  model::GuidanceParams p = default_params();
  p.approach_duration_s = 50.0;
  p.blend_time_s = 60.0;
  const ApproachProfile end = approach_profile(p, 50.0 - 1e-9);
  EXPECT_NEAR(end.distance_m, p.capture_distance_m, 1e-12);
  EXPECT_NEAR(end.rate_mps, 0.0, 1e-9);
  const ApproachProfile mid = approach_profile(p, 25.0);
  EXPECT_NEAR(mid.distance_m, 0.5 * (p.start_distance_m + p.capture_distance_m), 1e-12);
}

// Target pointing: body +x is along -axis (from the chaser towards the target); the default V-bar
// approach gives a +90 deg turn about LVLH z (body x = LVLH +y, body y = LVLH -x, body z = LVLH z).
TEST(Guidance, TargetPointingAttitude) {
  const Quat q_default = target_pointing_q_lvlh_from_body(Vec3(0.0, -1.0, 0.0));
  EXPECT_TRUE(q_default.isApprox(Quat(Eigen::AngleAxisd(0.5 * kPi, Vec3::UnitZ())), 1e-15));
  for (const Vec3& axis : {Vec3(1, 0, 0), Vec3(0.3, -1.0, 0.2), Vec3(0.1, 0.0, 1.0), Vec3(0, 0, -1)}) {
    const Quat q = target_pointing_q_lvlh_from_body(axis);
    EXPECT_NEAR(q.norm(), 1.0, 1e-15);
    EXPECT_LT((q * Vec3::UnitX() + axis.normalized()).norm(), 1e-15) << axis.transpose();
  }
}

// The reference attitude is fixed in LVLH, which turns at n about z, so (i) at any time body +x
// points from the reference position to the target, and (ii) the reference rate equals the
// finite-difference rate of the reference quaternion (1e-12 rad/s: second-order difference error
// on a uniform rotation is zero, leaving round-off ~ eps / h).
TEST(Guidance, AttitudeTurnsWithLvlhAtOrbitRate) {
  const model::GuidanceParams p = default_params();
  for (double t : {0.0, 300.0, 2000.0}) {
    const GuidanceRef ref = guidance_reference(p, kOrbit, t);
    const Vec3 to_target_inertial = kOrbit.q_inertial_from_lvlh(t) * (-ref.r_lvlh_m.normalized());
    EXPECT_LT((ref.q_inertial_from_body * Vec3::UnitX() - to_target_inertial).norm(), 1e-14);
    const double h = 0.01;
    const Quat q_next = guidance_reference(p, kOrbit, t + h).q_inertial_from_body;
    const Vec3 omega_fd = rotation_vector_from_quat(ref.q_inertial_from_body.conjugate() * q_next) / h;
    EXPECT_LT((omega_fd - ref.omega_body_radps).norm(), 1e-12);
    EXPECT_NEAR(ref.omega_body_radps.norm(), kN, 1e-18);
  }
}

}  // namespace guidance_test
}  // namespace chaser::flight
