// The multibody plant behind the seam: handed over from the Earth-orbit plant and back it keeps the
// bodies; with the arm stowed and locked it flies the rigid Earth-orbit plant's trajectory; without
// an environment it keeps the scene's momentum; what it cannot fly it refuses naming the key.
#include "plant/multibody_motion.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "core/constants.hpp"
#include "plant/handover.hpp"
#include "plant/plant.hpp"
#include "tests/plant/earth_orbit_scenario.hpp"

namespace chaser::plant {
namespace multibody_motion_test {

// The hand-over tests' tumbling target (testing::tumbling_target_scenario) with the arm stowed; the
// chaser's mass properties are then the hub's and the stowed arm's composite.
model::Scenario capture_scenario() {
  model::Scenario s = testing::tumbling_target_scenario();
  testing::add_stowed_arm(s);
  return s;
}

RigidState start(const model::Scenario& s) {
  return testing::chaser_start(s.chaser.mass_kg);
}

// n periods of a gentle command (T1 and T3 a tenth of each period; T3 sticks open at 5 s).
void fly(Plant& plant, int n, TimeNs& t, bool thrust = true) {
  model::ThrusterCommand command;
  if (thrust) command.ton[0] = command.ton[2] = 0.1;
  for (int k = 0; k < n; ++k, t += plant.params.period_ns) {
    sense_plant(plant.params, plant.state, t, Quat::Identity());  // for its effect on the state only
    step_plant(plant.params, plant.state, command, t);
  }
}

struct Gap {
  double r_m = 0, v_mps = 0, q_rad = 0, omega_radps = 0, q_target_rad = 0, omega_target_radps = 0;
};
Gap gap(const Plant& a, const Plant& b, const model::TargetOrbit& circle, double t_s) {
  const HandoverState x = handover_state(a, circle, t_s), y = handover_state(b, circle, t_s);
  return {(x.r_lvlh_m - y.r_lvlh_m).norm(),
          (x.v_lvlh_mps - y.v_lvlh_mps).norm(),
          x.q_lvlh_from_body.angularDistance(y.q_lvlh_from_body),
          (x.omega_body_radps - y.omega_body_radps).norm(),
          x.q_lvlh_from_target.angularDistance(y.q_lvlh_from_target),
          (x.omega_target_body_radps - y.omega_target_body_radps).norm()};
}

TEST(MultibodyMotion, WhatItCannotFlyIsRefusedNamingTheKey) {
  model::Scenario s = capture_scenario();
  EXPECT_FALSE(multibody_problem(s));
  s.chaser.slosh.emplace();
  const auto slosh = multibody_problem(s);
  ASSERT_TRUE(slosh);
  EXPECT_NE(slosh->find("chaser.slosh"), std::string::npos) << *slosh;
  s = capture_scenario();
  s.chaser.arm.reset();
  ASSERT_TRUE(multibody_problem(s));
  EXPECT_NE(multibody_problem(s)->find("chaser.arm"), std::string::npos);
  // From the circle: the multibody plant needs the Earth orbit's ECI states.
  model::Scenario circle_s = capture_scenario();
  circle_s.orbit.earth.reset();
  Plant plant = make_plant(circle_s, start(circle_s), 7);
  const auto refused = hand_over_to_multibody(plant, capture_scenario());
  ASSERT_TRUE(refused);
  EXPECT_NE(refused->find("Earth-orbit plant only"), std::string::npos) << *refused;
}

// Mid-run the Earth-orbit plant hands over to the multibody plant and, ten periods of coasting
// later, back: the bodies arrive where they left, to rounding (ECI placed exactly, the hub's CoM
// offset turned out and back: 1e-12 m at 100 m), and the rigid plant flies on.
TEST(MultibodyMotion, HandedOverFromTheEarthOrbitAndBackTheBodiesStay) {
  const model::Scenario s = capture_scenario();
  model::Scenario circle_s = s;
  circle_s.orbit.earth.reset();
  const model::TargetOrbit circle(circle_s.orbit);
  Plant plant = make_plant(s, start(s), 7);
  TimeNs t = 0;
  fly(plant, 20, t);
  const double t_s = to_seconds(t);
  const HandoverState before = handover_state(plant, circle, t_s);
  ASSERT_FALSE(hand_over_to_multibody(plant, s));
  ASSERT_TRUE(std::holds_alternative<MultibodyMotionParams>(plant.params.motion));
  const HandoverState on = handover_state(plant, circle, t_s);
  EXPECT_LT((on.r_lvlh_m - before.r_lvlh_m).norm(), 1e-12);
  EXPECT_LT((on.v_lvlh_mps - before.v_lvlh_mps).norm(), 1e-14);
  EXPECT_LT(on.q_lvlh_from_body.angularDistance(before.q_lvlh_from_body), 1e-15);
  EXPECT_LT((on.omega_body_radps - before.omega_body_radps).norm(), 1e-18);
  EXPECT_LT(on.q_lvlh_from_target.angularDistance(before.q_lvlh_from_target), 1e-15);
  EXPECT_LT((on.omega_target_body_radps - before.omega_target_body_radps).norm(), 1e-18);
  EXPECT_EQ(on.mass_kg, before.mass_kg);

  fly(plant, 10, t, false);
  const double t1_s = to_seconds(t);
  const HandoverState coasted = handover_state(plant, circle, t1_s);
  ASSERT_FALSE(hand_over_to_earth_orbit(plant, s));
  ASSERT_TRUE(std::holds_alternative<EarthOrbitParams>(plant.params.motion));
  const HandoverState back = handover_state(plant, circle, t1_s);
  EXPECT_LT((back.r_lvlh_m - coasted.r_lvlh_m).norm(), 1e-12);
  EXPECT_LT((back.v_lvlh_mps - coasted.v_lvlh_mps).norm(), 1e-14);
  EXPECT_LT(back.q_lvlh_from_body.angularDistance(coasted.q_lvlh_from_body), 1e-15);
  EXPECT_LT(back.q_lvlh_from_target.angularDistance(coasted.q_lvlh_from_target), 1e-15);
  fly(plant, 5, t);
  EXPECT_TRUE(std::holds_alternative<EarthOrbitState>(plant.state.motion));
}

// The test: the arm stowed and locked, the hub flies the rigid Earth-orbit plant's
// trajectory for the same scenario: 60 s from 100 m with T1 and T3 pulsing a tenth of each period
// and T3 stuck open from 5 s (21 N and ~15 N m for most of the run: the chaser moves 5.4 m and
// spins up to 0.52 rad/s), the target tumbling, J2, drag, pressure, Sun, Moon, gravity gradient.
// Propellant is made massless here (isp 1e12 s): the rigid plant takes it from the chaser's CoM,
// the multibody plant from the hub's, which moves the whole chaser's CoM towards the arm (0.6 kg
// here: 2.5e-5 m) and is a difference of the models, not an error (docs/dynamics.md).
// The bound: the rigid plant's own RK4 at 0.1 s, (w h)^5 / 120 a step at 0.52 rad/s, 1.6e-6 rad over
// 600 steps; MuJoCo's diagonalised hub inertia, 4e-8 of ~15 rad turned, 6e-7 rad; the locks' give,
// 1.7e-7 rad moving the chaser's CoM 1.2e-8 m; the tide's second order over the chaser's 3 m,
// 2e-9 m; each of the rest (held forces at each 1 ms step's midpoint) below 1e-9. Attitude 2e-6 rad;
// position: the attitude error times the ~0.3 m/s thrust velocity change over 60 s, 4e-5 m at most,
// far less in fact, as the thrust turns with the spin. Measured: 3.1e-7 m, 1.3e-8 m/s, 1.4e-7 rad,
// 4.0e-8 rad/s; the target 1.6e-10 rad.
TEST(MultibodyMotion, StowedAndLockedItFliesTheRigidEarthOrbitTrajectory) {
  model::Scenario s = capture_scenario();
  s.chaser.isp_s = 1e12;
  model::Scenario circle_s = s;
  circle_s.orbit.earth.reset();
  const model::TargetOrbit circle(circle_s.orbit);
  Plant rigid = make_plant(s, start(s), 7);
  Plant multi = rigid;
  ASSERT_FALSE(hand_over_to_multibody(multi, s));
  TimeNs t_rigid = 0, t_multi = 0;
  Gap worst;
  for (int second = 1; second <= 60; ++second) {
    fly(rigid, 10, t_rigid);
    fly(multi, 10, t_multi);
    const Gap g = gap(rigid, multi, circle, to_seconds(t_rigid));
    worst = {std::max(worst.r_m, g.r_m), std::max(worst.v_mps, g.v_mps), std::max(worst.q_rad, g.q_rad),
             std::max(worst.omega_radps, g.omega_radps), std::max(worst.q_target_rad, g.q_target_rad),
             std::max(worst.omega_target_radps, g.omega_target_radps)};
  }
  EXPECT_GT(chaser_state(rigid).omega_body_radps.norm(), 0.5);
  EXPECT_EQ(rigid.state.propellant_used_kg, multi.state.propellant_used_kg);
  EXPECT_LT(worst.r_m, 2e-6);
  EXPECT_LT(worst.v_mps, 1e-7);
  EXPECT_LT(worst.q_rad, 2e-6);
  EXPECT_LT(worst.omega_radps, 2e-7);
  EXPECT_LT(worst.q_target_rad, 1e-9);
  const auto& params = std::get<MultibodyMotionParams>(multi.params.motion);
  const auto q = joint_angles_rad(params, std::get<MultibodyMotionState>(multi.state.motion));
  for (std::size_t j = 0; j < q.size(); ++j) EXPECT_LT(std::abs(q[j] - params.scene.arm.stowed_rad[j]), 1e-6) << j;
}

// Thrusters off and no environment (no gravity: mu = 0, so no tide, gradient or reference
// acceleration; the perturbations off), the arm unlocked and driven by 2 N m sines: the scene's
// momentum is conserved through the plant's own stepping as momentum_test.cpp shows for MuJoCo's.
TEST(MultibodyMotion, WithoutEnvironmentAndThrustTheSceneKeepsItsMomentum) {
  model::Scenario s = capture_scenario();
  s.faults.clear();
  s.environment.gravity_gradient = false;
  s.target.body->gravity_gradient = false;
  model::EarthOrbitParams& e = *s.orbit.earth;
  e.j2 = 0.0;
  e.drag = e.solar_pressure = e.sun_gravity = e.moon_gravity = e.magnetic_torque = false;
  for (auto& link : s.chaser.arm->links) link.friction_Nm = 0.0;
  Plant plant = make_plant(s, start(s), 7);
  ASSERT_FALSE(hand_over_to_multibody(plant, s));
  auto& params = std::get<MultibodyMotionParams>(plant.params.motion);
  auto& state = std::get<MultibodyMotionState>(plant.state.motion);
  params.earth.earth.dynamics.perturbations.gravity.mu_m3ps2 = 0.0;
  lock_arm(params, state, false);
  ThrustProfile quiet;
  quiet.count = 1;
  quiet.pieces[0].t_end_ns = from_seconds(0.1);
  state.world.forward();
  const multibody::Momentum p0 = state.world.momentum();
  RigidState chaser = plant.state.chaser;
  for (int k = 0; k < 10; ++k) {
    std::array<double, model::kArmJoints> torque{};
    for (int j = 0; j < model::kArmJoints; ++j) torque[static_cast<std::size_t>(j)] = 2.0 * std::sin(0.1 * k * (1.0 + 0.7 * j));
    set_joint_torques(state, torque);
    quiet.pieces[0].t_begin_ns = 0;
    begin_period(params, state, chaser, 0, from_seconds(0.1));
    advance(params, state, chaser, quiet, PeriodDisturbance{}, 0, from_seconds(0.1));
  }
  state.world.forward();
  const multibody::Momentum p1 = state.world.momentum();
  const auto w = joint_rates_radps(params, state);
  EXPECT_GT(std::abs(w[1]), 1e-3);  // the arm moved
  // Measured over 1 s at 1 ms: 4.4e-13 of 203 kg m/s, 1.1e-8 of 1.5e4 kg m^2/s (7e-13 relative).
  EXPECT_LT((p1.linear_kgmps - p0.linear_kgmps).norm(), 1e-9 * (1.0 + p0.linear_kgmps.norm()));
  EXPECT_LT((p1.angular_kgm2ps - p0.angular_kgm2ps).norm(), 1e-9 * (1.0 + p0.angular_kgm2ps.norm()));
}

}  // namespace multibody_motion_test
}  // namespace chaser::plant
