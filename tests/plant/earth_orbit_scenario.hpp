#pragma once
// A scenario on COMRADE's 765 km sun-synchronous orbit with the perturbed Earth-orbit plant
// (orbit.earth), shared by the plant tests that build one.
#include "core/constants.hpp"
#include "model/arm.hpp"
#include "model/scenario.hpp"
#include "plant/hub_mass_properties.hpp"

namespace chaser::plant::testing {

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

}  // namespace chaser::plant::testing
