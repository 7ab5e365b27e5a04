#include "invsim/relative_dynamics.hpp"

#include <gtest/gtest.h>

#include "invsim/cw_transition.hpp"

namespace chaser::invsim {
namespace {

RvdConstants leo() {
  return make_rvd_constants(3.986004418e14, 6.778137e6, 8000.0, Vec3(6000.0, 28000.0, 28000.0).asDiagonal());
}

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
  s.omega_body_radps = Vec3(0.0, -c.mean_motion_radps, 0.0);
  for (int i = 0; i < 400; ++i) propagate_piece(c, force, Vec3::Zero(), 0.25, s);
  const Vec6 expected = cw_state_transition(c.mean_motion_radps, 100.0) * x0 +
                        cw_held_input_transition(c.mean_motion_radps, 100.0) * force / c.mass_kg;
  EXPECT_LT((s.r_hill_m - expected.head<3>()).norm(), 1e-4);
  EXPECT_LT((s.v_hill_mps - expected.tail<3>()).norm(), 1e-6);
}

// A body rotating with the Hill frame (omega = (0, -n, 0)) keeps its attitude in that frame: the
// Hill frame is an equilibrium of eqs. 10-11 without torque (principal-axis spin).
TEST(RelativeDynamics, HillPointingIsAnEquilibrium) {
  const RvdConstants c = leo();
  RvdState s;
  s.omega_body_radps = Vec3(0.0, -c.mean_motion_radps, 0.0);
  for (int i = 0; i < 4000; ++i) propagate_piece(c, Vec3::Zero(), Vec3::Zero(), 0.25, s);
  EXPECT_LT(s.q_hill_from_body.angularDistance(Quat::Identity()), 1e-12);
  EXPECT_LT(relative_rate_body(c, s).norm(), 1e-15);
}

// Torque-free tumbling conserves rotational kinetic energy and the inertial angular momentum
// magnitude (eq. 10): over 1000 s of 0.25 s RK4 steps both hold to 1e-9 relative.
TEST(RelativeDynamics, TorqueFreeInvariants) {
  const RvdConstants c = leo();
  RvdState s;
  s.omega_body_radps = Vec3(0.02, -0.01, 0.015);
  const auto energy = [&](const Vec3& w) { return 0.5 * w.dot(c.inertia_kgm2 * w); };
  const double e0 = energy(s.omega_body_radps);
  const double h0 = (c.inertia_kgm2 * s.omega_body_radps).norm();
  for (int i = 0; i < 4000; ++i) propagate_piece(c, Vec3::Zero(), Vec3::Zero(), 0.25, s);
  EXPECT_NEAR(energy(s.omega_body_radps), e0, 1e-9 * e0);
  EXPECT_NEAR((c.inertia_kgm2 * s.omega_body_radps).norm(), h0, 1e-9 * h0);
}

}  // namespace
}  // namespace chaser::invsim
