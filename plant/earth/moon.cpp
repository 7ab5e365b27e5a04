#include "plant/earth/moon.hpp"

#include <cmath>

#include "core/constants.hpp"

namespace chaser::plant::earth {

namespace {

// The parallax is the angle an Earth radius subtends; Vallado's Example 5-3 takes 6378.137 km (it
// reproduces his figures to 1 m; 6378.1363 km would move them by 1.1e-7, ~35 m).
constexpr double kEarthRadiusForParallaxM = 6378137.0;

// Sine and cosine of an angle in degrees.
double sind(double deg) { return std::sin(deg * kDegToRad); }
double cosd(double deg) { return std::cos(deg * kDegToRad); }

}  // namespace

Vec3 moon_position_eci_m(double julian_date_tt) {
  // Vallado 2013, Algorithm 31 (the Astronomical Almanac's low-precision Moon); angles in degrees.
  const double t = (julian_date_tt - 2451545.0) / 36525.0;  // Julian centuries from J2000
  const double longitude = 218.32 + 481267.8813 * t + 6.29 * sind(134.9 + 477198.85 * t) -
                           1.27 * sind(259.2 - 413335.38 * t) + 0.66 * sind(235.7 + 890534.23 * t) +
                           0.21 * sind(269.9 + 954397.70 * t) - 0.19 * sind(357.5 + 35999.05 * t) -
                           0.11 * sind(186.6 + 966404.05 * t);
  const double latitude = 5.13 * sind(93.3 + 483202.03 * t) + 0.28 * sind(228.2 + 960400.87 * t) -
                          0.28 * sind(318.3 + 6003.18 * t) - 0.17 * sind(217.6 - 407332.20 * t);
  const double parallax = 0.9508 + 0.0518 * cosd(134.9 + 477198.85 * t) + 0.0095 * cosd(259.2 - 413335.38 * t) +
                          0.0078 * cosd(235.7 + 890534.23 * t) + 0.0028 * cosd(269.9 + 954397.70 * t);
  const double obliquity = 23.439291 - 0.0130042 * t;
  const double distance_m = kEarthRadiusForParallaxM / sind(parallax);
  const Vec3 ecliptic(cosd(latitude) * cosd(longitude), cosd(latitude) * sind(longitude), sind(latitude));
  return distance_m * (Eigen::AngleAxisd(obliquity * kDegToRad, Vec3::UnitX()) * ecliptic);
}

}  // namespace chaser::plant::earth
