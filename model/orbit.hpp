#pragma once
// Circular target orbit about a central body (Fonod 2015, eqs. 6-7).
#include <cmath>

namespace chaser::model {

struct OrbitParams {
  double mu_m3ps2 = 4.282837e13;      // [m^3/s^2] gravitational parameter (Mars)
  double body_radius_m = 3.3895e6;    // [m] mean equatorial radius (Mars)
  double altitude_m = 500e3;          // [m] target orbit altitude

  double radius_m() const { return body_radius_m + altitude_m; }                       // a
  double mean_motion_radps() const { return std::sqrt(mu_m3ps2 / std::pow(radius_m(), 3)); }  // eq. 7
};

}  // namespace chaser::model
