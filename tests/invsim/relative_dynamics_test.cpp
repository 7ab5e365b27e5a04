#include "invsim/relative_dynamics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "core/hill_frames.hpp"
#include "core/rotation.hpp"
#include "invsim/cw_transition.hpp"
#include "plant/propagator.hpp"

namespace chaser::invsim {
namespace {

constexpr double kMu = 3.986004418e14;  // [m^3/s^2]
constexpr double kRadius = 6.778137e6;  // [m] 400 km circular orbit
constexpr double kRunPieceS = 0.25;     // [s] the run's attitude period: one RK4 step per piece

RvdConstants leo(double max_substep_s = kRunPieceS) {
  return make_rvd_constants(kMu, kRadius, 8000.0, Vec3(6000.0, 28000.0, 28000.0).asDiagonal(), max_substep_s);
}

double mean_motion(const RvdConstants& c) { return c.dynamics.orbit.mean_motion_radps(); }

// Near the target eq. 1 reduces to the CW model (eq. 2): over 100 s from 100 m the nonlinear
// propagation (0.25 s RK4 pieces) and the closed form agree to the neglected second-order terms,
// ~ n^2 |r|^2 / R t^2 / 2 ~ 1e-5 m; 1e-4 m is the tolerance, 1e-6 of the state.
TEST(RelativeDynamics, ReducesToCwNearTheTarget) {
  const RvdConstants c = leo();
  RvdState s;
  s.r_hill_m = Vec3(100.0, -2.0, 3.0);
  s.v_hill_mps = Vec3(-0.1, 0.05, -0.02);
  Vec6 x0;
  x0 << s.r_hill_m, s.v_hill_mps;
  const Vec3 force(30.0, -20.0, 10.0);  // body = Hill (identity attitude, no torque)
  s.omega_body_radps = omega_hill_in_hill(mean_motion(c));
  for (int i = 0; i < 400; ++i) propagate_piece(c, force, Vec3::Zero(), 0.25, s);
  const Vec6 expected = cw_state_transition(mean_motion(c), 100.0) * x0 +
                        cw_held_input_transition(mean_motion(c), 100.0) * force / c.mass_kg;
  EXPECT_LT((s.r_hill_m - expected.head<3>()).norm(), 1e-4);
  EXPECT_LT((s.v_hill_mps - expected.tail<3>()).norm(), 1e-6);
}

// A body rotating with the Hill frame (omega = (0, -n, 0)) keeps its attitude in that frame: the
// Hill frame is an equilibrium of eqs. 10-11 without torque (principal-axis spin). The attitude
// passes through the inertial frame at every piece; each pass rounds at 1e-16, hence 1e-12 after
// 4000 pieces and a relative rate of rounding size.
TEST(RelativeDynamics, HillPointingIsAnEquilibrium) {
  const RvdConstants c = leo();
  RvdState s;
  s.omega_body_radps = omega_hill_in_hill(mean_motion(c));
  for (int i = 0; i < 4000; ++i) propagate_piece(c, Vec3::Zero(), Vec3::Zero(), 0.25, s);
  EXPECT_LT(s.q_hill_from_body.angularDistance(Quat::Identity()), 1e-12);
  EXPECT_LT(relative_rate_body(c, s).norm(), 1e-15);
}

// Torque-free tumbling conserves rotational kinetic energy and the inertial angular momentum
// magnitude (eq. 10): over 1000 s of 0.25 s RK4 steps both hold to 1e-9 relative.
TEST(RelativeDynamics, TorqueFreeInvariants) {
  const RvdConstants c = leo();
  const Mat3& inertia = c.dynamics.inertia_kgm2;
  RvdState s;
  s.omega_body_radps = Vec3(0.02, -0.01, 0.015);
  const auto energy = [&](const Vec3& w) { return 0.5 * w.dot(inertia * w); };
  const double e0 = energy(s.omega_body_radps);
  const double h0 = (inertia * s.omega_body_radps).norm();
  for (int i = 0; i < 4000; ++i) propagate_piece(c, Vec3::Zero(), Vec3::Zero(), 0.25, s);
  EXPECT_NEAR(energy(s.omega_body_radps), e0, 1e-9 * e0);
  EXPECT_NEAR((inertia * s.omega_body_radps).norm(), h0, 1e-9 * h0);
}

// The acceleration is eq. 1 (omega_tar' = 0) to full precision. Reference: eq. 1 as printed,
// evaluated in x87 extended precision, whose cancelling z line is then good to ~1e-18 m/s^2 (an
// ulp of mu / R^2 = 8.7 m/s^2 at 64 bits). The plant's Battin form in double is within 1e-17 m/s^2
// of it; eq. 1's literal z line in double is off by 1.2e-15 to 2.2e-15 m/s^2 at these states
// (measured; an ulp of mu / R^2), 1e-10 of the ~1e-5 m/s^2 result: the digits this change recovers.
TEST(RelativeDynamics, AccelerationIsEq1WithoutCancellation) {
  if (std::numeric_limits<long double>::digits < 64) GTEST_SKIP() << "no extended precision";
  using Ld = long double;
  const RvdConstants c = leo();
  const Ld mu = kMu, big_r = kRadius, n = std::sqrt(mu / (big_r * big_r * big_r));
  const Vec3 v(-0.0076, 0.131, -0.0087);  // [m/s] Zhou 2018, Table 3
  for (const Vec3& r : {Vec3(100.038, -0.0167, -0.023), Vec3(10.0, 0.0, -0.03), Vec3(100.0, -2.0, 3.0),
                        Vec3(300.0, 60.0, 290.0)}) {
    const Ld rz = big_r - r.z();
    const Ld mu_r3 = mu / std::pow(rz * rz + Ld(r.x()) * r.x() + Ld(r.y()) * r.y(), Ld(1.5));
    const Ld eq1[3] = {2 * n * v.z() + n * n * r.x() - mu_r3 * r.x(), -mu_r3 * r.y(),
                       -2 * n * v.x() + n * n * r.z() - mu / (big_r * big_r) + mu_r3 * rz};
    const Vec3 a = relative_gravity_accel(c, r, v);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(a(i), static_cast<double>(eq1[i]), 1e-17) << "axis " << i;
  }
}

// A tilted, turning, thrusting chaser over a run's 1300 s, in pieces of uneven length (0.03, 0.07,
// 0.15 s), force pulses every 2.5 s, torque pulses of alternating sign every 0.75 s.
struct Drive {
  double dt_s;
  Vec3 force_body_N, torque_body_Nm;
};
Drive drive(int k) {
  constexpr double kPieces[3] = {0.03, 0.07, 0.15};  // [s]
  const Vec3 force = k % 40 < 4 ? Vec3(-25.0, 18.0, 12.0) : Vec3(Vec3::Zero());
  const double sign = (k / 12) % 2 ? 1.0 : -1.0;
  const Vec3 torque = k % 12 < 2 ? Vec3(sign * Vec3(3.0, -8.0, 5.0)) : Vec3(Vec3::Zero());
  return {kPieces[k % 3], force, torque};
}
constexpr int kDrivePieces = 15600;  // 1300 s

RvdState tumbling_start() {
  RvdState s;
  s.r_hill_m = Vec3(100.038, -0.0167, -0.023);  // Zhou 2018, Table 3
  s.v_hill_mps = Vec3(-0.0076, 0.131, -0.0087);
  s.q_hill_from_body = quat_from_rotation_vector(Vec3(0.01, -0.015, 0.02));
  s.omega_body_radps = Vec3(1e-3, -2e-3, 1.5e-3);
  return s;
}

// The same drive through the previous implementation (commit d885d6e: eq. 1 as printed, one RK4
// step per piece of the 13-state Hill-frame system), final state printed to 17 digits there.
// Translation agrees to what the literal z line's error explains: a bias of ~1.5e-15 m/s^2 drifts
// the position by a t^2 / 2 ~ 1.3e-9 m and the velocity by a t ~ 2e-12 m/s over 1300 s (measured:
// 7.9e-10 m, 1.4e-12 m/s; tolerances 3e-9 m, 5e-12 m/s). The attitude agrees to 3.7e-13 rad
// (measured; tolerance 1e-12): rounding accumulated over 15,600 pieces, the size of the difference
// from the plant's own run below; RK4's truncation differs by only ~1e-15 rad over the run
// ((|omega| h)^5 / 120 ~ 1e-19 per piece at |omega| = 3e-3 rad/s). The body rate is computed by
// the same arithmetic in both (Euler's equations do not see the attitude here): equal (measured 0).
TEST(RelativeDynamics, AgreesWithThePreviousHillFrameIntegrator) {
  const RvdConstants c = leo();
  RvdState s = tumbling_start();
  for (int k = 0; k < kDrivePieces; ++k) {
    const Drive d = drive(k);
    propagate_piece(c, d.force_body_N, d.torque_body_Nm, d.dt_s, s);
  }
  const Vec3 r_old_m(62.921124255440191, 60.647352289856116, 291.18710015883391);
  const Vec3 v_old_mps(0.2773860663641175, -0.16323831040054188, 0.44887179774584574);
  const Quat q_old(0.20903952313653976, 0.64042795575354738, -0.37333745605764845, 0.63778809581285223);
  const Vec3 w_old_radps(0.001, 0.0001576811466424553, 0.0024863989447365966);
  std::printf("vs d885d6e: |dr| %.2e m |dv| %.2e m/s attitude %.2e rad |dw| %.2e rad/s\n",
              (s.r_hill_m - r_old_m).norm(), (s.v_hill_mps - v_old_mps).norm(),
              s.q_hill_from_body.angularDistance(q_old), (s.omega_body_radps - w_old_radps).norm());
  EXPECT_LT((s.r_hill_m - r_old_m).norm(), 3e-9);
  EXPECT_LT((s.v_hill_mps - v_old_mps).norm(), 5e-12);
  EXPECT_LT(s.q_hill_from_body.angularDistance(q_old), 1e-12);
  EXPECT_LT((s.omega_body_radps - w_old_radps).norm(), 1e-18);
}

// The same drive through plant::propagate_piece directly, in LVLH with the run's clock (t0 from 0
// to 1300 s, the inertial frame fixed at LVLH(0)), mapped to Hill at the end. invsim re-bases the
// inertial frame at every piece instead; the equations do not depend on that choice, so the two
// differ by rounding only: each re-basing rounds the attitude at ~1e-16 rad (four quaternion
// products, a normalisation); over 15,600 pieces this measures 2.9e-13 rad (tolerance 1e-12),
// between a random walk (3e-14) and a steady bias (7e-12). It turns the thrust (3e-3 m/s^2 on
// 10 % of the time) and moves the position by 3.2e-11 m, the velocity by 5.7e-14 m/s (tolerances
// 1e-10 m, 3e-13 m/s). The body rate: the same arithmetic, equal (measured 0).
TEST(RelativeDynamics, IsThePlantsPropagation) {
  const RvdConstants c = leo();
  RvdState s = tumbling_start();
  plant::RigidState x = plant_state(c, s);  // LVLH(0) is the inertial frame of the whole flight
  double t_s = 0.0;
  for (int k = 0; k < kDrivePieces; ++k) {
    const Drive d = drive(k);
    propagate_piece(c, d.force_body_N, d.torque_body_Nm, d.dt_s, s);
    plant::propagate_piece(c.dynamics, x, t_s, d.dt_s,
                           {.force_body_N = d.force_body_N, .torque_body_Nm = d.torque_body_Nm});
    t_s += d.dt_s;
  }
  const Quat q_hill_from_body =
      q_hill_from_lvlh() * c.dynamics.orbit.q_inertial_from_lvlh(t_s).conjugate() * x.q_inertial_from_body;
  std::printf("vs plant: |dr| %.2e m |dv| %.2e m/s attitude %.2e rad |dw| %.2e rad/s\n",
              (s.r_hill_m - hill_from_lvlh(x.r_lvlh_m)).norm(), (s.v_hill_mps - hill_from_lvlh(x.v_lvlh_mps)).norm(),
              s.q_hill_from_body.angularDistance(q_hill_from_body), (s.omega_body_radps - x.omega_body_radps).norm());
  EXPECT_LT((s.r_hill_m - hill_from_lvlh(x.r_lvlh_m)).norm(), 1e-10);
  EXPECT_LT((s.v_hill_mps - hill_from_lvlh(x.v_lvlh_mps)).norm(), 3e-13);
  EXPECT_LT(s.q_hill_from_body.angularDistance(q_hill_from_body), 1e-12);
  EXPECT_LT((s.omega_body_radps - x.omega_body_radps).norm(), 1e-18);
}

}  // namespace
}  // namespace chaser::invsim
