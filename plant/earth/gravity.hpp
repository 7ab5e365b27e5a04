#pragma once
// Earth's gravity to J2 in an Earth-centred inertial frame (ECI, z along the rotation axis), for the
// perturbed orbits of the COMRADE platform. J2 is the only zonal term: at a few metres of
// separation the higher ones change the relative acceleration by under 1e-3 of J2's share
// (docs/dynamics.md). The field is symmetric about z, so it is static in ECI and the energy
// v^2 / 2 + V(r) is conserved by a trajectory in it.
//
// Potential energy per unit mass (Vallado 2013, eq. 8-19 truncated at J2):
//   V(r) = -mu / r [1 - J2 (R / r)^2 (3 z^2 / r^2 - 1) / 2]
// and the acceleration a = -grad V:
//   a_x = -mu x / r^3 [1 + 3/2 J2 (R / r)^2 (1 - 5 z^2 / r^2)], a_y likewise with y,
//   a_z = -mu z / r^3 [1 + 3/2 J2 (R / r)^2 (3 - 5 z^2 / r^2)].
#include "core/types.hpp"

namespace chaser::plant::earth {

struct GravityParams {
  double mu_m3ps2 = 3.986004418e14;  // [m^3/s^2] GM of the Earth (IERS 2010 / WGS 84)
  double radius_m = 6378137.0;       // [m] equatorial radius (WGS 84), J2's reference radius
  double j2 = 1.08262668e-3;         // [-] EGM2008, unnormalised; 0: central gravity only
};

Vec3 gravity_acceleration_eci(const GravityParams& g, const Vec3& r_eci_m);  // [m/s^2]
double gravity_potential_energy(const GravityParams& g, const Vec3& r_eci_m);  // [J/kg] V above

// a(r + dr) - a(r) for a separation dr small against r, to full relative precision: the central
// term by Battin's f(q) (no subtraction of two nearly equal accelerations), the J2 term, a
// thousandth of it, by plain difference. What a chaser metres from its target feels.
Vec3 differential_gravity_eci(const GravityParams& g, const Vec3& r_eci_m, const Vec3& dr_eci_m);

// Both at once, the target's J2 term formed once (what the propagator asks at every RK4 stage):
// the same bits as gravity_acceleration_eci(r) and differential_gravity_eci(r, dr).
struct GravityPair {
  Vec3 target_eci_mps2;    // a(r)
  Vec3 relative_eci_mps2;  // a(r + dr) - a(r)
};
GravityPair gravity_pair_eci(const GravityParams& g, const Vec3& r_eci_m, const Vec3& dr_eci_m);

// Secular drift of the ascending node from J2 for a near-circular orbit of semi-major axis a and
// inclination i (Vallado 2013, eq. 9-41 with e = 0): -3/2 n J2 (R / a)^2 cos i [rad/s].
double nodal_regression_radps(const GravityParams& g, double semi_major_axis_m, double inclination_rad);

}  // namespace chaser::plant::earth
