// The Sun's position against the almanac: J2000's Julian date, the 2024 solstice's declination, the
// 2024 perihelion and aphelion distances; and solar pressure's size, direction and the shadow.
#include "plant/earth/sun.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "plant/earth/solar_radiation.hpp"

namespace chaser::plant::earth {
namespace {

TEST(Sun, JulianDateOfJ2000AndAnotherDay) {
  EXPECT_DOUBLE_EQ(julian_date(2000, 1, 1, 12), 2451545.0);
  EXPECT_DOUBLE_EQ(julian_date(2024, 6, 20, 20, 51), 2460482.0 + (20 * 60 + 51) / 1440.0 - 0.5);
}

// June solstice 2024, 20:51 UTC (US Naval Observatory): the Sun at ecliptic longitude 90 deg of
// date, so right ascension 90 deg and declination the obliquity of date, 23.4361 deg. The series is
// good to ~0.01 deg; TT - UTC (69 s) moves the Sun by 0.0008 deg.
TEST(Sun, DeclinationAtTheJuneSolsticeIsTheObliquity) {
  const Vec3 s = sun_position_eci_m(julian_date(2024, 6, 20, 20, 51));
  EXPECT_NEAR(std::asin(s.z() / s.norm()) / kDegToRad, 23.4361, 0.01);
  EXPECT_NEAR(std::atan2(s.y(), s.x()) / kDegToRad, 90.0, 0.02);
}

// 2024 perihelion (Jan 3, 00:39 UTC) 0.983307 AU and aphelion (Jul 5, 05:06 UTC) 1.016725 AU
// (USNO); the series' distance is good to ~1e-4 relative.
TEST(Sun, DistanceAtPerihelionAndAphelion) {
  EXPECT_NEAR(sun_position_eci_m(julian_date(2024, 1, 3, 0, 39)).norm() / kAstronomicalUnitM, 0.983307, 2e-4);
  EXPECT_NEAR(sun_position_eci_m(julian_date(2024, 7, 5, 5, 6)).norm() / kAstronomicalUnitM, 1.016725, 2e-4);
}

// 1 AU from the Sun: |a| = P C_R A / m, pointing away from the Sun; zero in the Earth's shadow (the
// night side, within one Earth radius of the Sun line), full just outside it.
TEST(SolarPressure, SizeDirectionAndShadow) {
  const Vec3 sun(kAstronomicalUnitM, 0, 0);
  const SolarPressureParams p{.area_to_mass_m2pkg = 0.02, .reflectivity = 1.5};
  const Vec3 day_side(7e6, 0, 0), night_side(-7e6, 0, 0), past_the_rim(-7e6, 6.4e6, 0), beside(0, 7e6, 0);
  const Vec3 a = solar_pressure_acceleration_eci(p, beside, sun);
  // Beside the Earth d^2 = AU^2 + (7e6 m)^2: (AU / d)^2 = 1 - 2.2e-9.
  EXPECT_NEAR(a.norm() / (4.56e-6 * 1.5 * 0.02), 1.0 - 2.19e-9, 1e-11);
  EXPECT_LT(a.normalized().dot((sun - beside).normalized()), -1.0 + 1e-15);
  EXPECT_FALSE(in_earth_shadow(day_side, sun, p.earth_radius_m));
  EXPECT_TRUE(in_earth_shadow(night_side, sun, p.earth_radius_m));
  EXPECT_FALSE(in_earth_shadow(past_the_rim, sun, p.earth_radius_m));
  EXPECT_EQ(solar_pressure_acceleration_eci(p, night_side, sun), Vec3::Zero());
  SolarPressureParams always = p;
  always.eclipses = false;
  EXPECT_GT(solar_pressure_acceleration_eci(always, night_side, sun).norm(), 0.0);
  // Farther out the pressure falls as 1 / d^2 (out of the plane of the shadow: d = 2 AU).
  const Vec3 far = solar_pressure_acceleration_eci(p, Vec3(kAstronomicalUnitM, 2.0 * kAstronomicalUnitM, 0), sun);
  EXPECT_NEAR(far.norm() / solar_pressure_acceleration_eci(p, Vec3(0, 1.0, 0), sun).norm(), 0.25, 1e-12);
}

}  // namespace
}  // namespace chaser::plant::earth
