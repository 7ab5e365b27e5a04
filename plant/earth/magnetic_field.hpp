#pragma once
// The Earth's magnetic field as a tilted dipole, and the torque it puts on a body's residual
// magnetic dipole. The dipole is IGRF-13's degree 1 for epoch 2020.0 (Alken et al. 2021):
// g10 = -29404.8 nT, g11 = -1450.9 nT, h11 = 4652.5 nT, reference radius a = 6371.2 km. Its scalar
// potential, B = -grad V, in geocentric colatitude theta and east longitude lambda (Earth-fixed):
//   V = a (a / r)^2 [g10 cos(theta) + (g11 cos(lambda) + h11 sin(lambda)) sin(theta)]
//     = a^3 (g . r) / r^3,   g = (g11, h11, g10) in ECEF,
// which is a dipole's, (mu0 / 4 pi) (m . r) / r^3, with the moment m = (4 pi / mu0) a^3 g: 7.7e22
// A m^2, pointing into the southern hemisphere (g10 < 0) 9.4 deg from the rotation axis. So
//   B(r) = a^3 [3 (g . r^) r^ - g] / r^3   (B0 = |g| = 29,806 nT on the dipole's equator at r = a).
// Accuracy: the higher degrees, left out, are ~10 % of the field at the surface, up to ~30 %
// locally (the South Atlantic Anomaly). Degree n falls as (a / r)^(n + 2), one power of a / r faster
// per degree than the dipole: in LEO (a / r ~ 0.9) hardly less, in GEO (0.15) ~2 %. The secular
// variation, tens of nT a year, is left out too. That is enough for the disturbance torque m x B of
// a residual dipole, itself known to tens of percent.
//
// The Earth-fixed frame turns by the Greenwich mean sidereal time about ECI's z (the mean equator and
// equinox of date, as sun.hpp's); polar motion (0.3") and the equation of the equinoxes (< 0.005 deg)
// are left out. GMST is a function of UT1; runs pass TT, 69 s later in 2024, which turns the dipole
// by 0.29 deg: against the 10 % above, nothing.
#include "core/types.hpp"

namespace chaser::plant::earth {

inline constexpr double kIgrf2020G10Nt = -29404.8;          // [nT] IGRF-13, epoch 2020.0
inline constexpr double kIgrf2020G11Nt = -1450.9;           // [nT]
inline constexpr double kIgrf2020H11Nt = 4652.5;            // [nT]
inline constexpr double kIgrfReferenceRadiusM = 6371200.0;  // [m] a

// Greenwich mean sidereal time [rad, 0..2 pi), IAU 1982 (Vallado 2013, Algorithm 15):
//   GMST = 67310.54841 s + (876600 h + 8640184.812866 s) T + 0.093104 s T^2 - 6.2e-6 s T^3,
// T the Julian centuries of UT1 from J2000.
double greenwich_mean_sidereal_time_rad(double julian_date_ut1);

// The Earth-fixed axes from ECI: a turn of -GMST about z (the Greenwich meridian lies at right
// ascension GMST).
Mat3 ecef_from_eci(double julian_date_ut1);

// The Earth's dipole moment m = (4 pi / mu0) a^3 (g11, h11, g10) [A m^2], ECEF; and its direction.
Vec3 dipole_moment_ecef_Am2();
Vec3 dipole_moment_direction_ecef();

// B above [T], ECEF, at r_ecef_m from the Earth's centre.
Vec3 magnetic_field_ecef_T(const Vec3& r_ecef_m);

// B [T], ECI (mean of date), at r_eci_m at the Julian date (TT taken as UT1, see above).
Vec3 magnetic_field_eci_T(const Vec3& r_eci_m, double julian_date);

// The torque m x B [N m] on a residual dipole m [A m^2] in a field B [T], both in body axes.
Vec3 magnetic_torque_body_Nm(const Vec3& residual_dipole_body_Am2, const Vec3& field_body_T);

}  // namespace chaser::plant::earth
