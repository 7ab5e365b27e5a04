// The Moon's and the Sun's pull on a satellite, and its difference over a chaser's separation,
// against the plain formula evaluated in quadruple precision; the tidal field's closed forms on and
// across the Earth-Moon line, and its first-order tensor.
#include "plant/earth/third_body.hpp"

#include <gtest/gtest.h>

#include <quadmath.h>

#include <cmath>
#include <string>
#include <vector>

#include "plant/earth/moon.hpp"
#include "plant/earth/sun.hpp"

namespace chaser::plant::earth {
namespace third_body_test {

// The plain formula, mu3 [(s - r) / |s - r|^3 - s / |s|^3], in __float128 (113-bit significand): even
// the Sun's 1e4 cancellation, and the 1e14 of a 1 mm difference of two accelerations, leave it at
// ~1e-20 of the result, far below the double's 1e-16.
using Quad = __float128;
struct Vec3q {
  Quad x, y, z;
};
Vec3q to_quad(const Vec3& v) { return {v.x(), v.y(), v.z()}; }
Vec3q quad_third_body(Quad mu, const Vec3q& r, const Vec3q& s) {
  const Vec3q d{s.x - r.x, s.y - r.y, s.z - r.z};
  const Quad dn = sqrtq(d.x * d.x + d.y * d.y + d.z * d.z), sn = sqrtq(s.x * s.x + s.y * s.y + s.z * s.z);
  const Quad kd = mu / (dn * dn * dn), ks = mu / (sn * sn * sn);
  return {kd * d.x - ks * s.x, kd * d.y - ks * s.y, kd * d.z - ks * s.z};
}
Vec3 to_double(const Vec3q& v) {
  return Vec3(static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z));
}

// The plain formula in double, for comparison.
Vec3 plain_third_body(double mu, const Vec3& r, const Vec3& s) {
  const Vec3 d = s - r;
  return mu / std::pow(d.norm(), 3) * d - mu / std::pow(s.norm(), 3) * s;
}

struct Body {
  const char* name;
  double mu_m3ps2;
  Vec3 r_eci_m;
};
std::vector<Body> moon_and_sun() {
  const double jd = julian_date(2024, 3, 1, 6);
  return {{"Moon", kMoonGravitationalParameterM3ps2, moon_position_eci_m(jd)},
          {"Sun", kSunGravitationalParameterM3ps2, sun_position_eci_m(jd)}};
}

// In LEO and GEO, Battin's form keeps the digits: 3e-15 relative (a dozen roundings in q, f(q) and
// r + f s, no term much larger than the result; measured at most 1.0e-15). The plain double formula
// loses the ratio of the two accelerations to their difference, ~1e4 for the Sun (measured 1.4e-13
// to 6.3e-12): required to be over 100x Battin's error.
TEST(ThirdBody, BattinsFormKeepsTheDigitsThePlainFormulaLoses) {
  for (const Body& body : moon_and_sun()) {
    for (const Vec3& r : {Vec3(6.8e6, 1.1e6, -0.4e6), Vec3(-2.9e6, 4.1e6, 4.6e6), Vec3(3.0e7, -2.9e7, 1.0e5)}) {
      const Vec3 reference = to_double(quad_third_body(body.mu_m3ps2, to_quad(r), to_quad(body.r_eci_m)));
      const double error = (third_body_acceleration_eci(body.mu_m3ps2, r, body.r_eci_m) - reference).norm();
      EXPECT_LT(error, 3e-15 * reference.norm()) << body.name << " " << r.transpose();
      if (std::string(body.name) == "Sun") {
        const double plain_error = (plain_third_body(body.mu_m3ps2, r, body.r_eci_m) - reference).norm();
        EXPECT_GT(plain_error, 100.0 * error) << r.transpose();
      }
    }
  }
}

// The chaser 1 mm to 100 m from its target in LEO: the differential form against the difference of
// two quadruple-precision accelerations, to 3e-15 relative (a dozen roundings; the result is never
// smaller than mu3 |dr| / |d|^3; measured at most 5.1e-16). The plain difference of two double
// accelerations, even Battin's, rounds at ~eps |a| ~ 1e-22 m/s^2 against a 1 mm tidal difference of
// ~4e-17 m/s^2: measured 1.3e-9 (1 m) to 1.9e-6 (1 mm) relative, required to be over 1e-10.
TEST(ThirdBody, DifferentialFormKeepsItsDigitsFrom1mmTo100m) {
  const Vec3 target(4.1e6, -3.2e6, 4.4e6);
  for (const Body& body : moon_and_sun()) {
    for (const Vec3& dr : {Vec3(0, 0, 1e-3), Vec3(0.3, -0.7, 0.2), Vec3(1.0, 0, 0), Vec3(60.0, 80.0, -20.0)}) {
      const Vec3q s = to_quad(body.r_eci_m);
      const Vec3q near = quad_third_body(body.mu_m3ps2, to_quad(target), s);
      const Vec3q far = quad_third_body(
          body.mu_m3ps2, {Quad(target.x()) + dr.x(), Quad(target.y()) + dr.y(), Quad(target.z()) + dr.z()}, s);
      const Vec3 reference = to_double({far.x - near.x, far.y - near.y, far.z - near.z});
      const Vec3 got = differential_third_body_eci(body.mu_m3ps2, target, dr, body.r_eci_m);
      EXPECT_LT((got - reference).norm(), 3e-15 * reference.norm()) << body.name << " " << dr.transpose();
      if (dr.norm() <= 1.0) {
        const Vec3 plain = third_body_acceleration_eci(body.mu_m3ps2, target + dr, body.r_eci_m) -
                           third_body_acceleration_eci(body.mu_m3ps2, target, body.r_eci_m);
        EXPECT_GT((plain - reference).norm(), 1e-10 * reference.norm()) << body.name << " " << dr.transpose();
      }
    }
  }
}

// To first order in |dr| / |d| the difference is the tidal tensor mu3 / |d|^3 (3 d^ d^T - I) dr
// (d from the target to the body); the second-order terms are ~3 |dr| / |d| of it, so 10 |dr| / |d|.
TEST(ThirdBody, DifferentialIsTheTidalTensorToFirstOrder) {
  const Vec3 target(-5.2e6, 4.0e6, 1.9e6);
  for (const Body& body : moon_and_sun()) {
    const Vec3 d = body.r_eci_m - target;
    const Mat3 tidal =
        body.mu_m3ps2 / std::pow(d.norm(), 3) * (3.0 * d.normalized() * d.normalized().transpose() - Mat3::Identity());
    for (const Vec3& dr : {Vec3(1.0, 0, 0), Vec3(-40.0, 25.0, 90.0), Vec3(1e3, 2e3, -3e3)}) {
      const Vec3 first_order = tidal * dr;
      EXPECT_LT((differential_third_body_eci(body.mu_m3ps2, target, dr, body.r_eci_m) - first_order).norm(),
                10.0 * dr.norm() / d.norm() * first_order.norm())
          << body.name << " " << dr.transpose();
    }
  }
}

// On the Earth-Moon line at rho from the Earth's centre the pull is exactly
// mu3 [1 / (s - rho)^2 - 1 / s^2] = mu3 rho (2 s - rho) / (s^2 (s - rho)^2) towards the Moon, ~2 mu3
// rho / s^3 (the tide's stretch); across it, at rho perpendicular, -mu3 rho / (s^2 + rho^2)^(3/2)
// towards the Earth (the squeeze, half as strong) plus -3/2 mu3 rho^2 / s^4 along the line (to
// x = (rho / s)^2 ~ 3e-4: 1e-3). Both closed forms are free of cancellation: 1e-14. At the mean
// distances (384,400 km, 1 AU) and the Earth's mean radius, the stretch (averaged over the near and
// the far side, which removes the +-3/2 rho / s of the second order) is the textbook 2 mu3 rho / s^3:
// 1.10e-6 m/s^2 for the Moon, and the Sun's is 0.46 of it.
TEST(ThirdBody, TidalStretchAlongTheEarthMoonLineAndSqueezeAcrossIt) {
  const double mu = kMoonGravitationalParameterM3ps2, s = 384400e3, rho = 6.8e6;
  const Vec3 moon(s, 0, 0);
  const Vec3 along = third_body_acceleration_eci(mu, Vec3(rho, 0, 0), moon);
  EXPECT_NEAR(along.x() / (mu * rho * (2 * s - rho) / (s * s * (s - rho) * (s - rho))), 1.0, 1e-14);
  EXPECT_EQ(along.y(), 0.0);
  EXPECT_NEAR(along.x() / (2 * mu * rho / (s * s * s)), 1.0, 2.0 * rho / s);
  const Vec3 across = third_body_acceleration_eci(mu, Vec3(0, rho, 0), moon);
  EXPECT_NEAR(across.y() / (-mu * rho / std::pow(s * s + rho * rho, 1.5)), 1.0, 1e-14);
  EXPECT_NEAR(across.x() / (-1.5 * mu * rho * rho / (s * s * s * s)), 1.0, 1e-3);

  const Vec3 near_side(6371e3, 0, 0), sun(kAstronomicalUnitM, 0, 0);
  const auto stretch = [&](double mu3, const Vec3& body) {
    return 0.5 *
           (third_body_acceleration_eci(mu3, near_side, body) - third_body_acceleration_eci(mu3, -near_side, body)).x();
  };
  const double moon_stretch = stretch(mu, moon), sun_stretch = stretch(kSunGravitationalParameterM3ps2, sun);
  EXPECT_NEAR(moon_stretch, 1.10e-6, 0.01e-6);
  EXPECT_NEAR(sun_stretch / moon_stretch, 0.46, 0.01);
}

}  // namespace third_body_test
}  // namespace chaser::plant::earth
