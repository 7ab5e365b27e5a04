#pragma once
// A point mass in an Earth-centred inertial frame: its state, a classical RK4 step with any
// acceleration model, and the orbital elements the checks of docs/dynamics.md read from it.
#include "core/types.hpp"

namespace chaser::plant::earth {

struct InertialState {
  Vec3 r_eci_m = Vec3::Zero();
  Vec3 v_eci_mps = Vec3::Zero();
};

// One RK4 step of length h from time t; acceleration(t, r, v) -> [m/s^2].
template <class Acceleration>
InertialState rk4_step(const InertialState& s, double t, double h, Acceleration&& acceleration) {
  const Vec3 k1v = acceleration(t, s.r_eci_m, s.v_eci_mps);
  const Vec3 k1r = s.v_eci_mps;
  const Vec3 k2v = acceleration(t + h / 2, s.r_eci_m + h / 2 * k1r, s.v_eci_mps + h / 2 * k1v);
  const Vec3 k2r = s.v_eci_mps + h / 2 * k1v;
  const Vec3 k3v = acceleration(t + h / 2, s.r_eci_m + h / 2 * k2r, s.v_eci_mps + h / 2 * k2v);
  const Vec3 k3r = s.v_eci_mps + h / 2 * k2v;
  const Vec3 k4v = acceleration(t + h, s.r_eci_m + h * k3r, s.v_eci_mps + h * k3v);
  const Vec3 k4r = s.v_eci_mps + h * k3v;
  return {s.r_eci_m + h / 6 * (k1r + 2 * k2r + 2 * k3r + k4r), s.v_eci_mps + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v)};
}

// A circular orbit of radius a, inclination i, right ascension of the ascending node raan, at
// argument of latitude u (all angles [rad]), speed sqrt(mu / a).
InertialState circular_orbit_state(double mu_m3ps2, double radius_m, double inclination_rad, double raan_rad,
                                   double argument_of_latitude_rad);

// Osculating elements of a bound orbit.
double semi_major_axis_m(double mu_m3ps2, const InertialState& s);  // from the two-body energy
double inclination_rad(const InertialState& s);
double raan_rad(const InertialState& s);  // in [0, 2 pi); needs i > 0

}  // namespace chaser::plant::earth
