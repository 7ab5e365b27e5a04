#include "plant/earth/sun.hpp"

#include <cmath>

#include "core/constants.hpp"

namespace chaser::plant::earth {

double julian_date(int year, int month, int day, int hour, int minute, double second) {
  const int a = (7 * (year + (month + 9) / 12)) / 4;
  const int b = (275 * month) / 9;
  return 367.0 * year - a + b + day + 1721013.5 + ((second / 60.0 + minute) / 60.0 + hour) / 24.0;
}

Vec3 sun_position_eci_m(double julian_date_tt) {
  // Vallado 2013, Algorithm 29 (the Astronomical Almanac's low-precision Sun).
  const double t = (julian_date_tt - 2451545.0) / 36525.0;  // Julian centuries from J2000
  const double mean_longitude = (280.460 + 36000.771 * t) * kDegToRad;
  const double mean_anomaly = (357.5291092 + 35999.05034 * t) * kDegToRad;
  const double longitude = mean_longitude + (1.914666471 * std::sin(mean_anomaly) +
                                             0.019994643 * std::sin(2.0 * mean_anomaly)) * kDegToRad;
  const double distance_au =
      1.000140612 - 0.016708617 * std::cos(mean_anomaly) - 0.000139589 * std::cos(2.0 * mean_anomaly);
  const double obliquity = (23.439291 - 0.0130042 * t) * kDegToRad;
  const double d = distance_au * kAstronomicalUnitM;
  return Eigen::AngleAxisd(obliquity, Vec3::UnitX()) * Vec3(d * std::cos(longitude), d * std::sin(longitude), 0.0);
}

}  // namespace chaser::plant::earth
