// The synchronisation's steps before the transfer (flight/sync_approach.hpp) against closed forms:
// the fly-around's great circle (speed R theta s'/D, centripetal and tangential acceleration, body
// +x on the target, the pointing's rate), the axis turning with the orbit when it is not the orbit
// normal (the reference then moves along the inertial axis only), the rotation's synchronisation
// ending on the target's attitude and rate, and the whole profile's continuity period by period.
// Tolerances: the central differences' error budget (header: ~1e-8 m/s^2 and below) plus rounding.
#include "flight/sync_approach.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/rotation.hpp"

namespace chaser::flight {
namespace {

constexpr double kMu = 3.986004418e14, kRadius = 6378137.0 + 765e3;

SyncApproachPlan envisat_like_plan() {
  SyncApproachPlan plan;
  plan.line.approach_axis_lvlh = Vec3(0.0, -1.0, 0.0);
  plan.line.start_distance_m = 100.0;
  plan.line.capture_distance_m = 30.0;
  plan.line.approach_duration_s = 1100.0;
  plan.line.blend_time_s = 120.0;
  plan.approach = model::SyncApproachParams{.fly_around_start_s = 1200.0,
                                            .fly_around_duration_s = 600.0,
                                            .axis_distance_m = 12.0,
                                            .axis_approach_duration_s = 400.0,
                                            .rotation_sync_duration_s = 200.0};
  plan.transfer.capture_target_m = Vec3(7.4, 0.0, 0.6);
  plan.transfer.start_s = 2400.0;
  plan.transfer.duration_s = 300.0;
  plan.transfer.q_target_from_body = Quat(0.0, 0.0, 0.0, 1.0);
  plan.target_inertia_kgm2 = Vec3(17000.0, 125000.0, 129000.0).asDiagonal();
  return plan;
}

// A torque-free target spinning at w about a principal axis (inertial `axis`), as a perfect
// estimator would report it at t.
TargetEstimate spinning_target(const Quat& q0, const Vec3& omega_target_radps, double t_s) {
  TargetEstimate e;
  e.t_s = t_s;
  e.q_inertial_from_target = (q0 * quat_from_rotation_vector(omega_target_radps * t_s)).normalized();
  e.omega_target_radps = omega_target_radps;
  return e;
}

// Calls the reference every period from 0 to t_end (as the flight software does, fixing the axis
// and the start point on the way) and returns the reference at t_end.
GuidanceRef fly_to(const SyncApproachPlan& plan, SyncApproachLatch& latch, const Quat& q0, const Vec3& omega,
                   const model::TargetOrbit& orbit, double t_end_s) {
  GuidanceRef ref;
  for (long k = 0; k * 0.1 <= t_end_s + 1e-9; ++k) {
    const double t = k * 0.1;
    ref = sync_approach_reference(plan, latch, spinning_target(q0, omega, t), orbit, t);
  }
  return ref;
}

// S1: the target spins about target +z, which is the inertial (and LVLH) z, the orbit normal; the
// axis stays along LVLH +z and the fly-around is the quarter circle from -V-bar to it.
TEST(SyncApproach, FlyAroundIsTheGreatCircleToTheAxis) {
  const SyncApproachPlan plan = envisat_like_plan();
  const model::TargetOrbit orbit(kMu, kRadius);
  const double n = orbit.mean_motion_radps(), w = 2.5 * std::numbers::pi / 180.0;
  SyncApproachLatch latch;
  const double R = 30.0, theta = std::numbers::pi / 2.0, D = 600.0;
  for (const double tau : {0.1, 0.37, 0.5, 0.81}) {
    const double t = 1200.0 + tau * D;
    const GuidanceRef ref = fly_to(plan, latch, Quat::Identity(), Vec3(0, 0, w), orbit, t);
    ASSERT_TRUE(latch.axis_inertial);
    EXPECT_LE((*latch.axis_inertial - Vec3::UnitZ()).norm(), 1e-15);
    const Eigen::Vector3d s = rest_to_rest_quintic(tau);
    const double angle = theta * s[0], rate = theta * s[1] / D, accel = theta * s[2] / (D * D);
    EXPECT_LE((ref.r_lvlh_m - R * Vec3(0.0, -std::cos(angle), std::sin(angle))).norm(), 1e-12) << tau;
    const Vec3 tangent(0.0, std::sin(angle), std::cos(angle)), inward = -ref.r_lvlh_m / R;
    // The central difference's h^2/6 r''': R theta s''' / D^3 h^2 / 6 <= 5e-9 m/s (s''' <= 60).
    EXPECT_LE((ref.v_lvlh_mps - R * rate * tangent).norm(), 1e-8) << tau;
    EXPECT_LE((ref.a_lvlh_mps2 - (R * accel * tangent + R * rate * rate * inward)).norm(), 1e-9) << tau;
    // Body +x on the target, and the body turning about the circle's axis -x (LVLH) plus LVLH's n.
    const Quat q_lvlh_from_body = orbit.q_inertial_from_lvlh(t).conjugate() * ref.q_inertial_from_body;
    EXPECT_LE((q_lvlh_from_body * Vec3::UnitX() - inward).norm(), 1e-12) << tau;
    const Vec3 omega_lvlh = q_lvlh_from_body * ref.omega_body_radps;
    EXPECT_LE((omega_lvlh - (rate * Vec3(-1, 0, 0) + n * Vec3::UnitZ())).norm(), 1e-9) << tau;
  }
}

// S3-like: the angular momentum at 45 deg between the orbit normal and the radial direction of
// t = 0. In LVLH the axis turns about the orbit normal at -n; seen from inertial space the approach
// along it is a straight line towards the target: the inertial velocity is along the axis.
TEST(SyncApproach, ApproachAlongTheAxisIsStraightInInertialSpace) {
  const SyncApproachPlan plan = envisat_like_plan();
  const model::TargetOrbit orbit(kMu, kRadius);
  const Vec3 axis_inertial = Vec3(1.0, 0.0, 1.0).normalized();
  // Target z along the axis: q0 turns z onto it; spin about target z.
  const Quat q0 = Quat::FromTwoVectors(Vec3::UnitZ(), axis_inertial);
  const Vec3 omega(0.0, 0.0, 2.5 * std::numbers::pi / 180.0);
  SyncApproachLatch latch;
  for (const double t : {1850.0, 2000.0, 2150.0}) {
    const GuidanceRef ref = fly_to(plan, latch, q0, omega, orbit, t);
    ASSERT_TRUE(latch.axis_inertial);
    EXPECT_LE((*latch.axis_inertial - axis_inertial).norm(), 1e-12);
    const model::LvlhFrame lvlh = orbit.lvlh_at(t);
    const Vec3 r_inertial = lvlh.q_inertial_from_lvlh * ref.r_lvlh_m;
    EXPECT_LE(r_inertial.normalized().cross(axis_inertial).norm(), 1e-12) << t;
    const Vec3 v_inertial = lvlh.q_inertial_from_lvlh * (ref.v_lvlh_mps + lvlh.omega_lvlh_radps.cross(ref.r_lvlh_m));
    EXPECT_LE(v_inertial.cross(axis_inertial).norm(), 1e-9) << t;
    EXPECT_LT(v_inertial.dot(axis_inertial), 0.0) << t;  // closing
    const Quat q_lvlh_from_body = lvlh.q_inertial_from_lvlh.conjugate() * ref.q_inertial_from_body;
    EXPECT_LE((q_lvlh_from_body * Vec3::UnitX() + ref.r_lvlh_m.normalized()).norm(), 1e-12) << t;  // on the target
  }
}

// At the end of the rotation's synchronisation the chaser turns with the target (attitude
// q_target q_0, q_0 the transfer's first attitude, flight/sync_guidance.hpp's transfer_attitude at
// s = 0, and its rate), at its start it points at the target without turning; the position is the
// axis point, which for a principal-axis spin is fixed in the target too. Throughout, body +x stays
// on the target (the LIDAR's view).
TEST(SyncApproach, RotationSynchronisationEndsTurningWithTheTarget) {
  const SyncApproachPlan plan = envisat_like_plan();
  const model::TargetOrbit orbit(kMu, kRadius);
  const Vec3 omega(0.0, 0.0, 2.5 * std::numbers::pi / 180.0);
  SyncApproachLatch latch;
  const GuidanceRef at_start = fly_to(plan, latch, Quat::Identity(), omega, orbit, 2200.0);
  // The pointing's rate: LVLH's, the axis being the orbit normal (fixed in LVLH).
  const model::LvlhFrame lvlh = orbit.lvlh_at(2200.0);
  EXPECT_LE((at_start.q_inertial_from_body * at_start.omega_body_radps -
             lvlh.q_inertial_from_lvlh * lvlh.omega_lvlh_radps).norm(), 2e-8);
  ASSERT_TRUE(latch.start_target_m);
  EXPECT_LE((*latch.start_target_m - Vec3(0.0, 0.0, 12.0)).norm(), 1e-9);
  const GuidanceRef before_end = fly_to(plan, latch, Quat::Identity(), omega, orbit, 2399.9);
  const TargetEstimate target = spinning_target(Quat::Identity(), omega, 2399.9);
  const Quat q_0 = transfer_attitude(plan.transfer.q_target_from_body, *latch.start_target_m, 0.0);
  EXPECT_LE((q_0 * Vec3::UnitX() + latch.start_target_m->normalized()).norm(), 1e-12);  // on the target
  const Quat turning = target.q_inertial_from_target * q_0;
  EXPECT_LE(rotation_vector_from_quat(before_end.q_inertial_from_body.conjugate() * turning).norm(), 1e-7);
  // h^2/6 of the spin-up's second rate derivative (w 15 (2 + ...) / D^2 ~ 1e-4 rad/s^3): ~1e-7.
  EXPECT_LE((before_end.omega_body_radps - q_0.conjugate() * omega).norm(), 1e-6);
  for (double t = 2200.0; t <= 2400.0; t += 5.0) {
    const GuidanceRef ref = fly_to(plan, latch, Quat::Identity(), omega, orbit, t);
    const Quat q_lvlh_from_body = orbit.q_inertial_from_lvlh(t).conjugate() * ref.q_inertial_from_body;
    EXPECT_LE((q_lvlh_from_body * Vec3::UnitX() + ref.r_lvlh_m.normalized()).norm(), 1e-9) << t;
  }
  const Vec3 axis_point_lvlh = orbit.q_inertial_from_lvlh(2399.9).conjugate() * Vec3(0.0, 0.0, 12.0);
  EXPECT_LE((before_end.r_lvlh_m - axis_point_lvlh).norm(), 1e-9);
}

// Period by period from the line to the hold at the capture point: position follows the velocity
// and the velocity the acceleration (no jump anywhere, the steps' boundaries included), and the
// attitude follows the body rate. Bounds: one period's second-order remainder with the profile's
// largest jerk (and the target's w^3 r), times a margin.
TEST(SyncApproach, WholeProfileIsContinuous) {
  const SyncApproachPlan plan = envisat_like_plan();
  const model::TargetOrbit orbit(kMu, kRadius);
  const Vec3 omega(0.0, 2.5 * std::numbers::pi / 180.0, 0.0);
  const Quat q0(Eigen::AngleAxisd(-std::numbers::pi / 2.0, Vec3::UnitX()));  // target +y along the orbit normal (S1)
  SyncApproachLatch latch;
  const double T = 0.1;
  GuidanceRef prev = sync_approach_reference(plan, latch, spinning_target(q0, omega, 0.0), orbit, 0.0);
  double worst_position = 0.0, worst_velocity = 0.0, worst_attitude = 0.0;
  for (long k = 1; k <= 30000; ++k) {
    const double t = k * T;
    const GuidanceRef ref = sync_approach_reference(plan, latch, spinning_target(q0, omega, t), orbit, t);
    const Vec3 predicted_r = prev.r_lvlh_m + T * 0.5 * (prev.v_lvlh_mps + ref.v_lvlh_mps);
    const Vec3 predicted_v = prev.v_lvlh_mps + T * 0.5 * (prev.a_lvlh_mps2 + ref.a_lvlh_mps2);
    worst_position = std::max(worst_position, (ref.r_lvlh_m - predicted_r).norm());
    worst_velocity = std::max(worst_velocity, (ref.v_lvlh_mps - predicted_v).norm());
    const Vec3 turn = rotation_vector_from_quat(prev.q_inertial_from_body.conjugate() * ref.q_inertial_from_body);
    worst_attitude = std::max(worst_attitude, (turn - T * 0.5 * (prev.omega_body_radps + ref.omega_body_radps)).norm());
    prev = ref;
  }
  EXPECT_LT(worst_position, 1e-5);   // trapezoid on r: T^3/12 |r'''|, r''' <= w^3 r ~ 1e-3 m/s^3 at 12 m
  EXPECT_LT(worst_velocity, 1e-5);
  EXPECT_LT(worst_attitude, 1e-5);   // a rate jump of 1e-4 rad/s would show as 5e-6 rad
  EXPECT_LE((prev.r_lvlh_m - orbit.q_inertial_from_lvlh(3000.0).conjugate() *
                                 (spinning_target(q0, omega, 3000.0).q_inertial_from_target * Vec3(7.4, 0.0, 0.6)))
                .norm(),
            1e-9);
}

// Without a target estimate, or with a target that hardly turns, there is no axis: the line's
// reference (holding at its end) goes on.
TEST(SyncApproach, WithoutAnAxisTheLineHolds) {
  const SyncApproachPlan plan = envisat_like_plan();
  const model::TargetOrbit orbit(kMu, kRadius);
  SyncApproachLatch latch;
  const GuidanceRef line = guidance_reference(plan.line, 1500.0, orbit.lvlh_at(1500.0));
  const GuidanceRef none = sync_approach_reference(plan, latch, std::nullopt, orbit, 1500.0);
  EXPECT_EQ(none.r_lvlh_m, line.r_lvlh_m);
  TargetEstimate still;
  still.t_s = 1500.0;
  const GuidanceRef resting = sync_approach_reference(plan, latch, still, orbit, 1500.0);
  EXPECT_EQ(resting.r_lvlh_m, line.r_lvlh_m);
  EXPECT_FALSE(latch.axis_inertial);
  EXPECT_EQ(sync_step(plan, 1199.9), SyncStep::kLine);
  EXPECT_EQ(sync_step(plan, 1200.0), SyncStep::kFlyAround);
  EXPECT_EQ(sync_step(plan, 1800.0), SyncStep::kAxisApproach);
  EXPECT_EQ(sync_step(plan, 2200.0), SyncStep::kRotationSync);
  EXPECT_EQ(sync_step(plan, 2400.0), SyncStep::kTransfer);
}

}  // namespace
}  // namespace chaser::flight
