#pragma once
// A scenario on COMRADE's 765 km sun-synchronous orbit with the perturbed Earth-orbit plant
// (orbit.earth), shared by the plant tests that build one.
#include "core/constants.hpp"
#include "model/scenario.hpp"

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

}  // namespace chaser::plant::testing
