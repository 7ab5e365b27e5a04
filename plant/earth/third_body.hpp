#pragma once
// A third body's pull on a satellite in an Earth-centred frame: the Moon or the Sun at s
// (from the Earth's centre) accelerates the satellite at r and the Earth alike, and only the
// difference perturbs the orbit (Montenbruck & Gill 2000, eq. 3.37):
//   a = mu3 [(s - r) / |s - r|^3 - s / |s|^3].
// Written so, it subtracts two nearly equal accelerations: for the Sun, 6e-3 m/s^2 each, their
// difference 5e-7 m/s^2 in LEO, a loss of 4 digits. Battin's form (Battin 1999, sec. 8.4) has no
// such subtraction: with d = s - r and q = r.(r - 2 s) / |s|^2, |d|^2 = |s|^2 (1 + q) and
//   a = -mu3 / |d|^3 [r + f(q) s],  f(q) = (1 + q)^(3/2) - 1 (core/battin.hpp).
// What a chaser metres from its target feels is the difference of a over the separation dr, the
// tidal field mu3 / |d|^3 (3 d^ d^T - I) dr to first order (~1e-13 m/s^2 per metre from the Moon,
// half that from the Sun). Exactly, with e = d - dr and q = (|e|^2 - |d|^2) / |d|^2:
//   a(r + dr) - a(r) = mu3 [e / |e|^3 - d / |d|^3] = -mu3 / |e|^3 [dr + f(q) d],
// the same identity again, so no 1e-6 m/s^2 accelerations are subtracted to find 1e-13 m/s^2.
#include "core/types.hpp"

namespace chaser::plant::earth {

// [m^3/s^2] GM of the Sun, JPL DE405 (Standish 1998), as the IERS Conventions (2010) list it for
// TDB. Here rather than in sun.hpp, which gives only where the Sun is; the Moon's is in moon.hpp.
inline constexpr double kSunGravitationalParameterM3ps2 = 1.32712440018e20;

// a above [m/s^2], ECI: the satellite at r_eci_m, the body at body_eci_m, both from the Earth's
// centre, mu3 the body's GM [m^3/s^2].
Vec3 third_body_acceleration_eci(double mu3_m3ps2, const Vec3& r_eci_m, const Vec3& body_eci_m);

// a(r + dr) - a(r) [m/s^2], ECI, for the target at r_target_eci_m and the chaser at
// r_target_eci_m + dr_eci_m, to full relative precision for any dr.
Vec3 differential_third_body_eci(double mu3_m3ps2, const Vec3& r_target_eci_m, const Vec3& dr_eci_m,
                                 const Vec3& body_eci_m);

}  // namespace chaser::plant::earth
