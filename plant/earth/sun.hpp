#pragma once
// Time and the Sun for Earth-orbit runs: a calendar date's Julian date, and the Sun's
// position from the Astronomical Almanac's low-precision series (Vallado 2013, Algorithm 29):
// ~0.01 deg in direction and ~1e-4 in distance over 1950-2050, far more than solar pressure and
// eclipses at metres of separation need. Frame: the Earth's mean equator and equinox of date, taken
// as ECI (the precession that separates it from J2000's, 1.4 deg per century, is below what these
// models resolve); the time argument is TT, within 70 s of UTC (0.0008 deg of the Sun's motion).
#include "core/types.hpp"

namespace chaser::plant::earth {

inline constexpr double kAstronomicalUnitM = 149597870700.0;  // [m] IAU 2012

// Julian date of a Gregorian calendar date and time of day (Vallado 2013, Algorithm 14; 1900-2100).
double julian_date(int year, int month, int day, int hour = 0, int minute = 0, double second = 0.0);

// Position of the Sun from the Earth's centre [m], ECI (mean equator and equinox of date).
Vec3 sun_position_eci_m(double julian_date_tt);

}  // namespace chaser::plant::earth
