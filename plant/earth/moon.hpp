#pragma once
// The Moon for Earth-orbit runs: its position from the Astronomical Almanac's
// low-precision series (Vallado 2013, Algorithm 31; the Almanac's section D): ecliptic longitude
// and latitude as a few periodic terms, the distance from the horizontal parallax. The Almanac
// gives ~0.3 deg in longitude, ~0.2 deg in latitude and ~0.003 deg in parallax over 1900-2100, the
// last ~0.3 % or ~1,300 km of distance. The Moon's pull on a chaser metres from its target matters
// only through its tidal difference (plant/earth/third_body.hpp), ~1e-13 m/s^2 per metre of
// separation, which such errors change by ~1 %. Frame and time as sun.hpp's: the Earth's mean
// equator and equinox of date, taken as ECI; the argument is TT (TDB differs by under 2 ms).
#include "core/types.hpp"

namespace chaser::plant::earth {

// [m^3/s^2] GM of the Moon, JPL DE430 (Folkner et al. 2014): 4902.800 km^3/s^2.
inline constexpr double kMoonGravitationalParameterM3ps2 = 4.9028e12;

// Position of the Moon from the Earth's centre [m], ECI (mean equator and equinox of date).
Vec3 moon_position_eci_m(double julian_date_tt);

}  // namespace chaser::plant::earth
