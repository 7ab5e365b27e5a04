#pragma once
// A scenario on COMRADE's 765 km sun-synchronous orbit with the perturbed Earth-orbit plant
// (orbit.earth), shared by the plant tests that build one.
#include "core/constants.hpp"
#include "model/arm.hpp"
#include "model/scenario.hpp"
#include "model/hub_mass_properties.hpp"
#include "plant/rigid_body.hpp"

namespace chaser::plant::testing {

using model::BodyMassProperties;

inline model::Scenario leo_earth_orbit_scenario() {
  model::Scenario s;
  s.orbit.mu_m3ps2 = 3.986004418e14;
  s.orbit.body_radius_m = 6378137.0;
  s.orbit.altitude_m = 765e3;
  s.orbit.earth.emplace();
  s.orbit.earth->inclination_rad = 98.4 * kDegToRad;
  s.orbit.earth->argument_of_latitude_rad = 0.5;
  return s;
}

// A chaser 100 m from a target tumbling at 2.5 deg/s about a skew axis, on that orbit: four
// thrusters on the +x face pointing along its diagonals, T3 stuck open from 5 s. The hand-over and
// multibody tests fly it on each plant.
inline model::Scenario tumbling_target_scenario() {
  model::Scenario s = leo_earth_orbit_scenario();
  s.target.body.emplace();
  s.target.body->spin_case = model::SpinCase::given;
  s.target.q_inertial_from_target = Quat(Eigen::AngleAxisd(0.3, Vec3(1.0, 2.0, 3.0).normalized()));
  s.target.omega_inertial_radps = 2.5 * kDegToRad * Vec3(0.2, 1.0, -0.4).normalized();
  s.chaser.inertia_kgm2 = Vec3(1500.0, 1200.0, 1800.0).asDiagonal();
  s.target.body->inertia_kgm2 = Vec3(17000.0, 124000.0, 130000.0).asDiagonal();
  s.thrusters.count = 4;
  for (int i = 0; i < 4; ++i) {
    const double y = i % 2 ? 1.0 : -1.0, z = i / 2 ? 1.0 : -1.0;
    s.thrusters.thrusters[static_cast<std::size_t>(i)] = {.position_body_m = Vec3(1.0, 0.5 * y, 0.5 * z),
                                                           .direction_body = Vec3(-1.0, y, z).normalized()};
  }
  s.faults = {model::FaultParams{.kind = model::FaultKind::kStuckOpen, .thruster = 2, .onset_s = 5.0}};
  return s;
}

// The same chaser with the default arm (model::default_arm) stowed on it: a hub of hub_kg with
// principal moments hub_inertia_kgm2 and CoM hub_com_body_m, and the arm at its stowed angles make
// the rigid chaser (chaser.mass_kg, inertia_kgm2, com_body_m: the composite), as a scenario states it.
inline void add_stowed_arm(model::Scenario& s, double hub_kg = 1600.0,
                           const Vec3& hub_inertia_kgm2 = Vec3(1500.0, 1200.0, 1800.0),
                           const Vec3& hub_com_body_m = Vec3(0.02, -0.01, 0.03)) {
  s.chaser.arm = model::default_arm();
  std::array<BodyMassProperties, model::kArmJoints + 2> bodies;
  const auto arm = arm_bodies(*s.chaser.arm, s.chaser.arm->stowed_rad);
  std::copy(arm.begin(), arm.end(), bodies.begin());
  bodies.back() = {.mass_kg = hub_kg, .com_body_m = hub_com_body_m, .inertia_kgm2 = hub_inertia_kgm2.asDiagonal()};
  const BodyMassProperties chaser = composite(bodies);
  s.chaser.mass_kg = chaser.mass_kg;
  s.chaser.com_body_m = chaser.com_body_m;
  s.chaser.inertia_kgm2 = chaser.inertia_kgm2;
}

// The chaser's state at the tests' start: `r_lvlh_m` from the target, drifting at a few cm/s and
// turning slowly about a skew axis.
inline RigidState chaser_start(double mass_kg, const Vec3& r_lvlh_m = Vec3(3.0, -100.0, 2.0)) {
  RigidState x;
  x.mass_kg = mass_kg;
  x.r_lvlh_m = r_lvlh_m;
  x.v_lvlh_mps = Vec3(0.01, 0.02, -0.03);
  x.q_inertial_from_body = Quat(Eigen::AngleAxisd(1.1, Vec3(-0.3, 0.5, 0.8).normalized()));
  x.omega_body_radps = Vec3(1e-3, -2e-3, 0.5e-3);
  return x;
}

}  // namespace chaser::plant::testing
