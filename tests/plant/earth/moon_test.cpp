// The Moon's low-precision series against Vallado's worked example, against a more accurate series
// (Meeus's, through ERFA) at twelve dates over 1994-2049, the 2024 April 8 solar eclipse, and the
// mean distance and month over ten years.
#include "plant/earth/moon.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/constants.hpp"
#include "plant/earth/sun.hpp"

namespace chaser::plant::earth {
namespace {

double angle_deg(const Vec3& a, const Vec3& b) { return std::atan2(a.cross(b).norm(), a.dot(b)) / kDegToRad; }

// Vallado 2013, Example 5-3: 28 April 1994, 0h, r = (-134240.626, -311571.590, -126693.785) km. The
// series is the book's, so it reproduces the figures to the rounding of its printed time argument:
// 1 m. (With an Earth radius of 6378.1363 km for the parallax they would be ~35 m apart.)
TEST(Moon, ReproducesValladoExample5_3) {
  const Vec3 r = moon_position_eci_m(julian_date(1994, 4, 28));
  EXPECT_NEAR(r.x(), -134240626.0, 1.0);
  EXPECT_NEAR(r.y(), -311571590.0, 1.0);
  EXPECT_NEAR(r.z(), -126693785.0, 1.0);
}

// Reference: ERFA's eraMoon98 (Meeus 1998, ch. 47: 2.9" rms, 18" and 32 km at worst over 1950-2100
// against ELP/MPP02), turned from the GCRS to the mean equator and equinox of date by eraPmat06
// (IAU 2006 precession), at TT. The Almanac bounds the series' error by ~0.3 deg in longitude, ~0.2
// deg in latitude and ~0.003 deg in parallax (~0.32 % of distance); hence 0.4 deg and 0.4 %. Over
// 1950-2050 every 1.37 d (26,660 dates) the largest differences were 0.364 deg and 0.334 %.
struct MoonReference {
  int year, month, day, hour, minute, second;
  Vec3 r_km;
};

TEST(Moon, AgreesWithMeeusToTheAlmanacsAccuracy) {
  const MoonReference references[] = {
      {1994, 4, 28, 0, 0, 0, {-134508.0, -311413.9, -125987.6}},
      {2000, 1, 1, 12, 0, 0, {-291605.5, -266715.3, -76099.0}},
      {2006, 3, 15, 6, 0, 0, {-404245.1, 14990.4, 11400.7}},
      {2012, 9, 30, 0, 0, 0, {392220.0, 24509.3, 40718.8}},
      {2018, 12, 24, 18, 0, 0, {-183986.9, 284260.6, 125606.9}},
      {2024, 4, 8, 18, 18, 9, {339450.2, 108577.8, 49433.5}},
      {2024, 7, 1, 0, 0, 0, {297431.2, 199846.0, 102015.0}},
      {2024, 10, 17, 0, 0, 0, {340928.5, 95117.3, 47891.7}},
      {2031, 5, 20, 3, 0, 0, {277544.9, 257078.3, 120100.8}},
      {2037, 11, 2, 0, 0, 0, {-300912.8, 191657.9, 101796.5}},
      {2043, 2, 14, 9, 0, 0, {334127.3, 138065.5, 69447.1}},
      {2049, 8, 5, 0, 0, 0, {-361196.1, -124805.2, -80589.5}},
  };
  for (const MoonReference& ref : references) {
    const Vec3 r = moon_position_eci_m(julian_date(ref.year, ref.month, ref.day, ref.hour, ref.minute, ref.second));
    const Vec3 expected = 1e3 * ref.r_km;
    EXPECT_LT(angle_deg(r, expected), 0.4) << ref.year << "-" << ref.month << "-" << ref.day;
    EXPECT_NEAR(r.norm() / expected.norm(), 1.0, 4e-3) << ref.year << "-" << ref.month << "-" << ref.day;
  }
}

// Total solar eclipse of 2024 April 8, greatest at 18:17:16 UT (TT 69 s later) with gamma = 0.3431:
// the Moon's shadow axis passed 0.3431 Earth radii from the Earth's centre, so seen from there the
// Moon stood 0.3431 R / 359,805 km = 0.3485 deg from the Sun (Meeus's Moon and ERFA's Sun give
// 0.3485 deg). Tolerance: the Moon series' 0.37 deg plus the Sun's 0.01 deg; measured 0.428 deg.
TEST(Moon, StandsBeforeTheSunAtTheSolarEclipseOf2024April8) {
  const double jd_tt = julian_date(2024, 4, 8, 18, 17, 16.0 + 69.2);
  const double separation = angle_deg(moon_position_eci_m(jd_tt), sun_position_eci_m(jd_tt));
  EXPECT_NEAR(separation, 0.3485, 0.38);
}

// Ten years, 2020-2030, hourly. The distance stays within the Moon's extremes, ~356,400 and
// ~406,700 km, widened by the series' 1,300 km (measured 357,349 and 406,019 km); its time mean is
// the constant term of Meeus's distance series (1998, ch. 47), 385,000.56 km, to 0.05 % (the
// periodic terms average out to ~1e-4 over 130 months; measured 384,975 km). Right ascension
// increases through 0 once per tropical month (27.321582 d, the month against the equinox of date;
// the sidereal one is 7 s longer): measured over 133 months to 0.005 d, which single crossings,
// shifted by up to ~0.5 d by the 6.3 deg equation of the centre, allow; the anomalistic (27.555 d)
// and draconic (27.212 d) months are far outside.
TEST(Moon, DistanceAndMonthOverTenYears) {
  const double start = julian_date(2020, 1, 1), end = julian_date(2030, 1, 1), step = 1.0 / 24.0;
  double nearest = 1e12, farthest = 0.0, sum = 0.0, first_crossing = 0.0, last_crossing = 0.0;
  int samples = 0, crossings = 0;
  double previous_ra = 1.0;
  for (double jd = start; jd < end; jd += step) {
    const Vec3 r = moon_position_eci_m(jd);
    nearest = std::min(nearest, r.norm());
    farthest = std::max(farthest, r.norm());
    sum += r.norm();
    ++samples;
    const double ra = std::atan2(r.y(), r.x());
    if (previous_ra < 0.0 && previous_ra > -1.0 && ra >= 0.0) {
      const double crossing = jd - step * ra / (ra - previous_ra);
      if (crossings == 0) first_crossing = crossing;
      last_crossing = crossing;
      ++crossings;
    }
    previous_ra = ra;
  }
  EXPECT_GT(nearest, 355.0e6);
  EXPECT_LT(farthest, 408.0e6);
  EXPECT_NEAR(sum / samples / 385000.56e3, 1.0, 5e-4);
  EXPECT_NEAR((last_crossing - first_crossing) / (crossings - 1), 27.321582, 0.005);
}

}  // namespace
}  // namespace chaser::plant::earth
