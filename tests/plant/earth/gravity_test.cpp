// Earth gravity to J2 against independent references: the gradient of its own potential (central
// differences), a long-double difference for the differential form, energy conservation along an
// integrated orbit, and the closed-form nodal regression of a sun-synchronous orbit.
#include "plant/earth/gravity.hpp"

#include <gtest/gtest.h>

#include <quadmath.h>

#include <cmath>
#include <vector>

#include "core/constants.hpp"
#include "plant/earth/inertial_orbit.hpp"

namespace chaser::plant::earth {
namespace {

const GravityParams kEarth{};

// Central differences of V with a 1 m step: truncation ~ (1 m / r)^2 ~ 1e-14 of the field, rounding
// ~ eps |V| / 1 m ~ 1e-8 m/s^2 against |a| ~ 8 m/s^2: agreement to 1e-7 relative is the method's.
TEST(EarthGravity, AccelerationIsMinusTheGradientOfThePotential) {
  for (const Vec3& r : {Vec3(7.0e6, 0, 0), Vec3(3.0e6, -4.0e6, 5.0e6), Vec3(0, 1e5, 6.9e6), Vec3(-4.2e7, 1e6, 2e5)}) {
    Vec3 grad;
    for (int k = 0; k < 3; ++k) {
      const Vec3 step = Vec3::Unit(k);
      grad[k] = (gravity_potential_energy(kEarth, r + step) - gravity_potential_energy(kEarth, r - step)) / 2.0;
    }
    const Vec3 a = gravity_acceleration_eci(kEarth, r);
    EXPECT_LT((a + grad).norm(), 1e-7 * a.norm()) << r.transpose();
  }
}

// J2 flattens the field: at the equator it pulls harder than the point mass, over a pole less
// (factor 1 + 3/2 J2 (R/r)^2 and 1 - 3 J2 (R/r)^2 at the surface).
TEST(EarthGravity, J2StrengthensTheEquatorAndWeakensThePoles) {
  const double R = kEarth.radius_m, mu = kEarth.mu_m3ps2, j2 = kEarth.j2;
  EXPECT_NEAR(gravity_acceleration_eci(kEarth, Vec3(R, 0, 0)).norm() / (mu / (R * R)), 1 + 1.5 * j2, 1e-15);
  EXPECT_NEAR(gravity_acceleration_eci(kEarth, Vec3(0, 0, R)).norm() / (mu / (R * R)), 1 - 3.0 * j2, 1e-15);
}

// The differential form against the plain difference of two accelerations in quadruple precision
// (__float128, 113-bit significand: its rounding, ~1e-33 of 8 m/s^2, is negligible even for 1 mm
// of separation). The double difference loses ~eps 8 m/s^2 ~ 2e-15 m/s^2 (1e-9 of a 1 m
// separation's 1.2e-6 m/s^2). The differential form keeps the central term to ~1e-16 relative; its
// J2 term (~1e-2 m/s^2, differenced plainly) rounds to ~eps 1e-2 ~ 2e-18 m/s^2. Bound: 1e-13
// relative plus 1e-17 m/s^2, which over a 6,000 s orbit moves a chaser by under 2e-10 m.
using Quad = __float128;
struct Vec3q {
  Quad x, y, z;
};
Vec3q quad_acceleration(const Vec3q& r) {
  const Quad mu = kEarth.mu_m3ps2, R = kEarth.radius_m, j2 = kEarth.j2;
  const Quad r2 = r.x * r.x + r.y * r.y + r.z * r.z, rn = sqrtq(r2), z2 = r.z * r.z / r2;
  const Quad c = -mu / (r2 * rn), k = Quad(-1.5) * j2 * mu * R * R / (r2 * r2 * rn);
  return {c * r.x + k * r.x * (1 - 5 * z2), c * r.y + k * r.y * (1 - 5 * z2), c * r.z + k * r.z * (3 - 5 * z2)};
}

TEST(EarthGravity, DifferentialGravityKeepsItsDigits) {
  const Vec3 r(4.1e6, -3.2e6, 4.4e6);
  for (const Vec3& d : {Vec3(1.0, 0, 0), Vec3(0.3, -0.7, 0.2), Vec3(60.0, 80.0, -20.0), Vec3(0, 0, 1e-3)}) {
    const Vec3q near = quad_acceleration({r.x(), r.y(), r.z()});
    const Vec3q far = quad_acceleration({Quad(r.x()) + d.x(), Quad(r.y()) + d.y(), Quad(r.z()) + d.z()});
    const Vec3 reference(static_cast<double>(far.x - near.x), static_cast<double>(far.y - near.y),
                         static_cast<double>(far.z - near.z));
    const Vec3 got = differential_gravity_eci(kEarth, r, d);
    EXPECT_LT((got - reference).norm(), 1e-13 * reference.norm() + 1e-17) << d.transpose();
    const Vec3 plain = gravity_acceleration_eci(kEarth, r + d) - gravity_acceleration_eci(kEarth, r);
    if (d.norm() <= 1.0) {
      EXPECT_GT((plain - reference).norm(), 10 * (got - reference).norm()) << "plain is as good";
    }
  }
}

// With central gravity and J2 (a field static in ECI) v^2/2 + V is constant. RK4 at 1 s over one
// 700 km orbit: its truncation, (n h)^5 ~ 1e-15 a step, and rounding stay far below 1e-10.
TEST(EarthGravity, EnergyIsConservedOverAnOrbitWithJ2) {
  const double a = kEarth.radius_m + 700e3;
  InertialState s = circular_orbit_state(kEarth.mu_m3ps2, a, 51.6 * kDegToRad, 0.3, 0.0);
  s.v_eci_mps *= 1.01;  // slightly eccentric, so the radius varies too
  const auto energy = [](const InertialState& x) {
    return 0.5 * x.v_eci_mps.squaredNorm() + gravity_potential_energy(kEarth, x.r_eci_m);
  };
  const double e0 = energy(s);
  const auto accel = [](double, const Vec3& r, const Vec3&) { return gravity_acceleration_eci(kEarth, r); };
  const double period = 2 * kPi * std::sqrt(std::pow(a, 3) / kEarth.mu_m3ps2) * 1.04;
  double worst = 0;
  for (double t = 0; t < period; t += 1.0) {
    s = rk4_step(s, t, 1.0, accel);
    worst = std::max(worst, std::abs(energy(s) / e0 - 1.0));
  }
  EXPECT_LT(worst, 1e-10);
}

// A sun-synchronous orbit at 700 km: the inclination that the closed form (Vallado 2013, eq. 9-41)
// gives for 360 deg per tropical year, 0.9856 deg/day. Integrated for a day with J2, the node
// (averaged over the first and the last orbit, which removes its twice-per-orbit oscillation of
// ~0.04 deg) moves at that rate to 1 %.
TEST(EarthGravity, SunSynchronousNodeRegressesAsTheClosedForm) {
  const double a = kEarth.radius_m + 700e3;
  const double wanted_radps = 2 * kPi / (365.2422 * 86400.0);
  const double unit_rate = nodal_regression_radps(kEarth, a, 0.0);  // at cos i = 1
  const double inclination = std::acos(wanted_radps / unit_rate);
  EXPECT_NEAR(inclination / kDegToRad, 98.19, 0.02);  // the textbook sun-synchronous inclination at 700 km
  InertialState s = circular_orbit_state(kEarth.mu_m3ps2, a, inclination, 1.0, 0.0);
  const auto accel = [](double, const Vec3& r, const Vec3&) { return gravity_acceleration_eci(kEarth, r); };
  const double h = 10.0;
  const int steps = static_cast<int>(86400.0 / h);
  const int per_orbit = static_cast<int>(2 * kPi * std::sqrt(std::pow(a, 3) / kEarth.mu_m3ps2) / h);
  std::vector<double> raan;
  for (int k = 0; k <= steps; ++k) {
    raan.push_back(raan_rad(s));
    s = rk4_step(s, k * h, h, accel);
  }
  double first = 0, last = 0;
  for (int k = 0; k < per_orbit; ++k) first += raan[k], last += raan[raan.size() - per_orbit + k];
  const double drift = (last - first) / per_orbit;
  const double span_s = (raan.size() - per_orbit) * h;
  EXPECT_NEAR(drift / span_s / wanted_radps, 1.0, 0.01);
}

// gravity_pair_eci forms the target's J2 term once for both; it must be the two functions' bits.
TEST(EarthGravity, PairIsBothAccelerationsBitForBit) {
  const Vec3 r(6.9e6, -1.2e6, 2.3e6);
  for (const Vec3& d : {Vec3(30.0, -12.0, 4.0), Vec3(1e-3, 2e-3, -5e-4), Vec3(-800.0, 250.0, 90.0)}) {
    const GravityPair pair = gravity_pair_eci(kEarth, r, d);
    EXPECT_EQ(pair.target_eci_mps2, gravity_acceleration_eci(kEarth, r));
    EXPECT_EQ(pair.relative_eci_mps2, differential_gravity_eci(kEarth, r, d));
  }
}

}  // namespace
}  // namespace chaser::plant::earth
