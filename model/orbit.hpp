#pragma once
// Circular target orbit about a central body (Fonod 2015, eqs. 6-7): the scenario's parameters.
// The core asks the orbit through model::TargetOrbit (model/target_orbit.hpp).
#include <cmath>
#include <optional>

#include "model/earth_orbit.hpp"

namespace chaser::model {

struct OrbitParams {
  double mu_m3ps2 = 4.282837e13;      // [m^3/s^2] gravitational parameter (Mars)
  double body_radius_m = 3.3895e6;    // [m] mean equatorial radius (Mars)
  double altitude_m = 500e3;          // [m] target orbit altitude
  // A perturbed Earth orbit: present, the plant propagates both bodies in ECI with
  // these perturbations; absent, the circular orbit of eq. 8 above.
  std::optional<EarthOrbitParams> earth;

  double radius_m() const { return body_radius_m + altitude_m; }  // a
  double mean_motion_radps() const { return mean_motion_radps(mu_m3ps2, radius_m()); }
  // n = sqrt(mu / a^3), eq. 7: the one formula, for the scenario's orbit and for TargetOrbit.
  static double mean_motion_radps(double mu_m3ps2, double radius_m) { return std::sqrt(mu_m3ps2 / std::pow(radius_m, 3)); }
};

}  // namespace chaser::model
