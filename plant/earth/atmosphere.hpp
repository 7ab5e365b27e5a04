#pragma once
// Atmospheric density and drag for low Earth orbit. Density: the piecewise exponential
// model of Vallado 2013, Table 8-4 (CIRA-72 reference densities at base altitudes 0..1000 km, a
// scale height per band): rho(h) = rho_0 exp(-(h - h_0) / H) in the band h_0 <= h < h_1. A static,
// mean-activity model: at metres of separation drag acts on the difference of the two bodies'
// ballistic coefficients, so its absolute level matters less than that difference
// (docs/dynamics.md). Above 1000 km the last band continues; below 0 the sea-level value holds.
//
// Drag on a body of ballistic coefficient B = m / (C_D A) [kg/m^2] moving at v_rel through an
// atmosphere that turns with the Earth (v_rel = v - omega_E x r):
//   a = -rho |v_rel| v_rel / (2 B).
#include "core/types.hpp"

namespace chaser::plant::earth {

inline constexpr double kEarthRotationRadps = 7.292115e-5;  // [rad/s] omega_E (IERS, mean sidereal)

double exponential_density_kgpm3(double altitude_m);  // [kg/m^3]

struct DragParams {
  double ballistic_coefficient_kgpm2 = 100.0;  // [kg/m^2] B = m / (C_D A)
  double equatorial_radius_m = 6378137.0;      // [m] altitude above the sphere of this radius
  bool corotating_atmosphere = true;           // v_rel = v - omega_E x r; false: v_rel = v
};

Vec3 drag_acceleration_eci(const DragParams& p, const Vec3& r_eci_m, const Vec3& v_eci_mps);  // [m/s^2]

// Decay rate of a circular orbit of radius a in a still atmosphere of density rho (Vallado 2013,
// eq. 9-38 with e = 0): da/dt = -rho sqrt(mu a) / B [m/s].
double circular_decay_rate_mps(double mu_m3ps2, double semi_major_axis_m, double density_kgpm3,
                               double ballistic_coefficient_kgpm2);

}  // namespace chaser::plant::earth
