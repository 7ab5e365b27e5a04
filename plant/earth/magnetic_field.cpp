#include "plant/earth/magnetic_field.hpp"

#include <cmath>

#include "core/constants.hpp"

namespace chaser::plant::earth {

namespace {

constexpr double kTeslaPerNanotesla = 1e-9;
constexpr double kFourPiOverMu0 = 1e7;  // [A/(T m)] 4 pi / mu0, mu0 = 4 pi 1e-7 (to 5e-10 since 2019)

// (g11, h11, g10) [nT]: the Earth-fixed vector of the degree-1 Gauss coefficients.
Vec3 gauss_vector_ecef_nT() { return Vec3(kIgrf2020G11Nt, kIgrf2020H11Nt, kIgrf2020G10Nt); }

}  // namespace

double greenwich_mean_sidereal_time_rad(double julian_date_ut1) {
  // Vallado 2013, Algorithm 15, in seconds of time; 86400 s of time make a turn.
  const double t = (julian_date_ut1 - 2451545.0) / 36525.0;
  const double seconds = 67310.54841 + (876600.0 * 3600.0 + 8640184.812866) * t + 0.093104 * t * t - 6.2e-6 * t * t * t;
  const double turn = std::fmod(seconds, 86400.0) / 86400.0;
  return 2.0 * kPi * (turn < 0.0 ? turn + 1.0 : turn);
}

Vec3 dipole_moment_ecef_Am2() {
  const double a = kIgrfReferenceRadiusM;
  return kFourPiOverMu0 * a * a * a * kTeslaPerNanotesla * gauss_vector_ecef_nT();
}

Vec3 dipole_moment_direction_ecef() { return gauss_vector_ecef_nT().normalized(); }

Vec3 magnetic_field_ecef_T(const Vec3& r_ecef_m) {
  const double r = r_ecef_m.norm();
  const Vec3 unit = r_ecef_m / r;
  const Vec3 g = gauss_vector_ecef_nT();
  const double ratio = kIgrfReferenceRadiusM / r;
  return kTeslaPerNanotesla * ratio * ratio * ratio * (3.0 * g.dot(unit) * unit - g);
}

Mat3 ecef_from_eci(double julian_date_ut1) {
  return Eigen::AngleAxisd(-greenwich_mean_sidereal_time_rad(julian_date_ut1), Vec3::UnitZ()).toRotationMatrix();
}

Vec3 magnetic_field_eci_T(const Vec3& r_eci_m, double julian_date) {
  const Mat3 to_ecef = ecef_from_eci(julian_date);
  return to_ecef.transpose() * magnetic_field_ecef_T(to_ecef * r_eci_m);
}

Vec3 magnetic_torque_body_Nm(const Vec3& residual_dipole_body_Am2, const Vec3& field_body_T) {
  return residual_dipole_body_Am2.cross(field_body_T);
}

}  // namespace chaser::plant::earth
