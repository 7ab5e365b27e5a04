// The tilted dipole against its potential (differenced, written here in spherical coordinates), the
// closed forms on its equator and axis, the published 2020 geomagnetic pole and the field's known
// directions; GMST against ERFA's implementation of the same IAU 1982 formula; the turn into ECI;
// and the torque m x B.
#include "plant/earth/magnetic_field.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "plant/earth/sun.hpp"

namespace chaser::plant::earth {
namespace {

constexpr double kA = kIgrfReferenceRadiusM;
const double kB0Tesla = 1e-9 * std::sqrt(kIgrf2020G10Nt * kIgrf2020G10Nt + kIgrf2020G11Nt * kIgrf2020G11Nt +
                                         kIgrf2020H11Nt * kIgrf2020H11Nt);

// GMST at J2000.0 (JD 2451545.0 UT1) is the formula's constant, 67310.54841 s = 280.460618375 deg,
// which Meeus (1998, eq. 12.4) prints as 280.46061837 deg: to 1e-8 deg. At
// Vallado 2013's Example 3-5 (1992 August 20, 12:14 UT1) and three more dates: ERFA's eraGmst82 (the
// same IAU 1982 expression, coded independently), to 1e-6 deg: a double Julian date resolves 4.7e-10
// d, 1.7e-7 deg of the Earth's turn.
TEST(Gmst, J2000AndErfaAtFourDates) {
  EXPECT_NEAR(greenwich_mean_sidereal_time_rad(2451545.0) / kDegToRad, 280.46061837, 1e-8);
  const struct {
    double jd_ut1, gmst_deg;
  } references[] = {
      {julian_date(1992, 8, 20, 12, 14), 152.5787878106},  // Vallado's Example 3-5
      {julian_date(2024, 3, 20, 3), 223.1419781625},
      {julian_date(2030, 1, 1), 100.6916693708},
      {julian_date(2010, 6, 15, 18), 173.9086789372},
  };
  for (const auto& ref : references) {
    EXPECT_NEAR(greenwich_mean_sidereal_time_rad(ref.jd_ut1) / kDegToRad, ref.gmst_deg, 1e-6) << ref.jd_ut1;
  }
}

// V = a (a / r)^2 [g10 P10(cos theta) + (g11 cos lambda + h11 sin lambda) P11(cos theta)], Schmidt
// P10 = cos theta, P11 = sin theta, written from the IGRF's definition in spherical coordinates [T m].
double degree_one_potential(const Vec3& r_ecef_m) {
  const double r = r_ecef_m.norm();
  const double colatitude = std::atan2(std::hypot(r_ecef_m.x(), r_ecef_m.y()), r_ecef_m.z());
  const double longitude = std::atan2(r_ecef_m.y(), r_ecef_m.x());
  return 1e-9 * kA * (kA / r) * (kA / r) *
         (kIgrf2020G10Nt * std::cos(colatitude) +
          (kIgrf2020G11Nt * std::cos(longitude) + kIgrf2020H11Nt * std::sin(longitude)) * std::sin(colatitude));
}

// B = -grad V by central differences with a 100 m step: truncation ~ (100 m / r)^2 ~ 3e-10 of the
// field, rounding ~ eps |V| / 100 m ~ 2e-11 of it: 1e-8 relative.
TEST(MagneticDipole, FieldIsMinusTheGradientOfTheDegreeOnePotential) {
  for (const Vec3& r :
       {Vec3(6.8e6, 0.5e6, 0.2e6), Vec3(-3.0e6, 4.0e6, 5.0e6), Vec3(1e5, -2e5, -6.9e6), Vec3(3.0e7, 2.9e7, 4e5)}) {
    Vec3 grad;
    for (int k = 0; k < 3; ++k) {
      const Vec3 step = 100.0 * Vec3::Unit(k);
      grad[k] = (degree_one_potential(r + step) - degree_one_potential(r - step)) / 200.0;
    }
    const Vec3 b = magnetic_field_ecef_T(r);
    EXPECT_LT((b + grad).norm(), 1e-8 * b.norm()) << r.transpose();
  }
}

// A dipole's field is B0 (a / r)^3 on its equator and twice that on its axis, B0 = |(g11, h11,
// g10)| = 29,806 nT; and it is (mu0 / 4 pi) [3 (m . r^) r^ - m] / r^3 of the moment, 7.7e22 A m^2.
// All closed forms: 1e-14.
TEST(MagneticDipole, EquatorAxisAndMoment) {
  const Vec3 axis = dipole_moment_direction_ecef();
  const Vec3 on_equator = axis.cross(Vec3(0.3, -0.2, 0.9)).normalized();
  for (double r : {kA, 7.0e6, 42.164e6}) {
    const double scale = std::pow(kA / r, 3);
    EXPECT_NEAR(magnetic_field_ecef_T(r * on_equator).norm() / (kB0Tesla * scale), 1.0, 1e-14) << r;
    EXPECT_NEAR(magnetic_field_ecef_T(r * axis).norm() / (2.0 * kB0Tesla * scale), 1.0, 1e-14) << r;
    EXPECT_NEAR(magnetic_field_ecef_T(-r * axis).norm() / (2.0 * kB0Tesla * scale), 1.0, 1e-14) << r;
  }
  EXPECT_NEAR(kB0Tesla, 29805.9e-9, 0.1e-9);
  const Vec3 m = dipole_moment_ecef_Am2();
  EXPECT_NEAR(m.norm(), 7.71e22, 0.01e22);
  const Vec3 r(-2.5e6, 5.5e6, 3.3e6);
  const Vec3 u = r.normalized();
  const Vec3 from_moment = 1e-7 * (3.0 * m.dot(u) * u - m) / std::pow(r.norm(), 3);
  EXPECT_LT((magnetic_field_ecef_T(r) - from_moment).norm(), 1e-14 * from_moment.norm());
}

// The boreal geomagnetic pole (where -m leaves the Earth) for IGRF-13 2020.0 is published at 80.65 N,
// 72.68 W (geodetic latitude, rounded to 0.01 deg): the dipole's geocentric 80.590 deg is 80.651 deg
// geodetic on WGS 84. Its tilt from the rotation axis is 9.41 deg. And the field's signs that any
// compass shows: at the geographic equator it points north (over 20,000 nT of it), over the north
// pole down and over the south pole up (each over 50,000 nT: 2 |g10| = 58,810 nT).
TEST(MagneticDipole, PoleTiltAndTheCompassDirections) {
  const Vec3 boreal = -dipole_moment_direction_ecef();
  const double geocentric_latitude = std::asin(boreal.z());
  const double flattening = 1.0 / 298.257223563;
  const double geodetic_latitude_deg =
      std::atan(std::tan(geocentric_latitude) / ((1 - flattening) * (1 - flattening))) / kDegToRad;
  EXPECT_NEAR(geodetic_latitude_deg, 80.65, 0.01);
  EXPECT_NEAR(std::atan2(boreal.y(), boreal.x()) / kDegToRad, -72.68, 0.01);
  EXPECT_NEAR(std::acos(boreal.z()) / kDegToRad, 9.41, 0.01);

  for (double longitude_deg : {0.0, 90.0, 200.0, 290.0}) {
    const double lon = longitude_deg * kDegToRad;
    EXPECT_GT(magnetic_field_ecef_T(kA * Vec3(std::cos(lon), std::sin(lon), 0.0)).z(), 20000e-9) << longitude_deg;
  }
  const Vec3 north_pole(0, 0, kA), south_pole(0, 0, -kA);
  EXPECT_LT(magnetic_field_ecef_T(north_pole).dot(north_pole.normalized()), -50000e-9);  // down
  EXPECT_GT(magnetic_field_ecef_T(south_pole).dot(south_pole.normalized()), 50000e-9);   // up
}

// In ECI the Greenwich meridian stands at right ascension GMST, so the boreal pole at GMST - 72.68
// deg: 500 km over it the field points straight down (a turn the wrong way would miss it by twice
// the GMST). The field at a point fixed in ECI returns after one sidereal day (360 deg over GMST's
// rate, 360.98564736629 deg a day, Meeus 1998 eq. 12.4), to 1e-8: a double Julian date resolves
// 4.7e-10 d, 3e-9 rad of the Earth's turn, and the T^2 term adds 1e-13 rad.
TEST(MagneticDipole, TurnsWithTheEarthInEci) {
  const double jd = julian_date(2024, 5, 10, 7, 30);
  const Vec3 boreal_ecef = -dipole_moment_direction_ecef();
  const double right_ascension = greenwich_mean_sidereal_time_rad(jd) + std::atan2(boreal_ecef.y(), boreal_ecef.x());
  const double declination = std::asin(boreal_ecef.z());
  const Vec3 over_pole = (kA + 500e3) * Vec3(std::cos(declination) * std::cos(right_ascension),
                                             std::cos(declination) * std::sin(right_ascension), std::sin(declination));
  const Vec3 b = magnetic_field_eci_T(over_pole, jd);
  EXPECT_LT(b.normalized().dot(over_pole.normalized()), -1.0 + 1e-12);

  const Vec3 r(5.1e6, -3.9e6, 2.7e6);
  const Vec3 now = magnetic_field_eci_T(r, jd);
  const double sidereal_day = 360.0 / 360.98564736629;
  EXPECT_LT((magnetic_field_eci_T(r, jd + sidereal_day) - now).norm(), 1e-8 * now.norm());
  EXPECT_GT((magnetic_field_eci_T(r, jd + 0.5) - now).norm(), 0.1 * now.norm());
}

// m x B: orthogonal to both, zero for m along B (to rounding), |m| |B| for m across it (1 A m^2 in
// 30 uT: 3e-5 N m, the order of a small satellite's magnetic disturbance in LEO).
TEST(MagneticTorque, IsMCrossB) {
  const Vec3 b(12e-6, -25e-6, 8e-6);
  const Vec3 m(0.4, 0.9, -0.3);
  const Vec3 torque = magnetic_torque_body_Nm(m, b);
  EXPECT_NEAR(torque.dot(m), 0.0, 1e-20);
  EXPECT_NEAR(torque.dot(b), 0.0, 1e-20);
  EXPECT_LT(magnetic_torque_body_Nm(3.0 * b / b.norm(), b).norm(), 1e-15 * 3.0 * b.norm());
  EXPECT_NEAR(magnetic_torque_body_Nm(Vec3(1.0, 0, 0), Vec3(0, 30e-6, 0)).z(), 30e-6, 1e-20);
}

}  // namespace
}  // namespace chaser::plant::earth
