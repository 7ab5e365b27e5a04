#pragma once
// Nonlinear relative translation of the chaser about a circular target orbit (Fonod 2015, eq. 8).
//
// Frame: MSR LVLH centred on the target, x radial out (zenith), y along-track, z orbit normal; it
// turns about +z at the mean motion n = sqrt(mu / a^3) (eq. 7). With rho = (xi, eta, zeta) the
// chaser position and R = |(a + xi, eta, zeta)| its distance from the planet centre, eq. 8 reads
//   xi''   = n^2 (a + xi) + 2 n eta' - mu / R^3 (a + xi) + F_xi / m
//   eta''  = n^2 eta      - 2 n xi'  - mu / R^3 eta      + F_eta / m
//   zeta'' =                         - mu / R^3 zeta     + F_zeta / m
//
// Written as it stands, the x line subtracts two accelerations of ~2.8 m/s^2 (a ~ 3.9e6 m) to get a
// result of ~3 n^2 xi ~ 1e-4 m/s^2 (|rho| ~ 20 m): eleven of sixteen digits cancel. Battin's
// formulation (Battin 1999, sec. 8.4) removes the cancellation. With
//   q = (R^2 - a^2) / a^2 = (2 a xi + |rho|^2) / a^2          (a sum of small terms, no cancellation)
//   f(q) = (1 + q)^(3/2) - 1 = q (3 + 3 q + q^2) / (1 + (1 + q)^(3/2))   (no cancellation either)
// and n^2 = mu / a^3, the gravity-minus-centrifugal difference is exactly
//   n^2 - mu / R^3 = (mu / R^3) f(q),   mu / R^3 = n^2 / (1 + q)^(3/2),
// so eq. 8 becomes, with every term computed to full relative precision,
//   xi''   =  (mu / R^3) f(q) (a + xi) + 2 n eta' + F_xi / m
//   eta''  =  (mu / R^3) f(q) eta      - 2 n xi'  + F_eta / m
//   zeta'' = -(mu / R^3) zeta                     + F_zeta / m.
// Linearised (f ~ 3 q / 2 ~ 3 xi / a) it is the HCW system: xi'' = 3 n^2 xi + 2 n eta', ...
#include "core/battin.hpp"  // battin_f
#include "core/types.hpp"

namespace chaser::plant {

// Acceleration of the chaser relative to the target in the rotating LVLH frame due to gravity and
// frame rotation (Fonod 2015, eq. 8 without the force term), in the cancellation-free form above.
//   orbit_radius_m: a [m]; mean_motion_radps: n [rad/s], n^2 = mu / a^3;
//   r_lvlh_m [m], v_lvlh_mps [m/s]: the chaser's relative position and rotating-frame velocity.
// Returns [m/s^2], LVLH axes.
Vec3 relative_orbit_acceleration_lvlh(double orbit_radius_m, double mean_motion_radps, const Vec3& r_lvlh_m,
                                      const Vec3& v_lvlh_mps);

}  // namespace chaser::plant
