#include "plant/earth/gravity.hpp"

#include <cmath>

#include "core/battin.hpp"

namespace chaser::plant::earth {

namespace {

// A position with the powers of its radius every term below needs, formed once: a stage of the
// propagator asks for the target's and the chaser's, and square roots and divisions are what
// these few lines cost (one of each per point, 1 / r^3 = (1 / r^2)(r / r^2)).
struct Radius {
  Vec3 r;
  double r2, rn, inv_r2;
  explicit Radius(const Vec3& position)
      : r(position), r2(position.squaredNorm()), rn(std::sqrt(r2)), inv_r2(1.0 / r2) {}
  double inv_r3() const { return inv_r2 * (rn * inv_r2); }
};

// The J2 part of the acceleration alone: 1 / r^5 = (1 / r^2) / r^3.
Vec3 j2_acceleration(const GravityParams& g, const Radius& p) {
  const Vec3& r = p.r;
  const double k = -1.5 * g.j2 * g.mu_m3ps2 * g.radius_m * g.radius_m * (p.inv_r2 * p.inv_r3());
  const double z2_r2 = r.z() * r.z() * p.inv_r2;
  return k * Vec3(r.x() * (1.0 - 5.0 * z2_r2), r.y() * (1.0 - 5.0 * z2_r2), r.z() * (3.0 - 5.0 * z2_r2));
}

// The central term alone: -mu r / |r|^3.
Vec3 central_acceleration(const GravityParams& g, const Radius& p) { return (-g.mu_m3ps2 * p.inv_r3()) * p.r; }

// Central: -mu (r + d) / |r + d|^3 + mu r / |r|^3 = -mu / |r + d|^3 [d - f(q) r], since
// |r + d|^3 / |r|^3 = (1 + q)^(3/2) with q = (2 r.d + d.d) / |r|^2 (Battin 1999, sec. 8.4): a
// sum of small terms, no two nearly equal accelerations subtracted. chaser = r + d.
Vec3 central_difference(const GravityParams& g, const Radius& target, const Radius& chaser, const Vec3& dr_eci_m) {
  const double q = (2.0 * target.r.dot(dr_eci_m) + dr_eci_m.squaredNorm()) * target.inv_r2;
  return (-g.mu_m3ps2 * chaser.inv_r3()) * (dr_eci_m - battin_f(q) * target.r);
}

}  // namespace

Vec3 gravity_acceleration_eci(const GravityParams& g, const Vec3& r_eci_m) {
  const Radius p(r_eci_m);
  return central_acceleration(g, p) + j2_acceleration(g, p);
}

double gravity_potential_energy(const GravityParams& g, const Vec3& r_eci_m) {
  const double r2 = r_eci_m.squaredNorm();
  const double rn = std::sqrt(r2);
  const double p2 = 0.5 * (3.0 * r_eci_m.z() * r_eci_m.z() / r2 - 1.0);  // Legendre P2(sin(latitude))
  return -g.mu_m3ps2 / rn * (1.0 - g.j2 * g.radius_m * g.radius_m / r2 * p2);
}

Vec3 differential_gravity_eci(const GravityParams& g, const Vec3& r_eci_m, const Vec3& dr_eci_m) {
  const Radius target(r_eci_m), chaser(r_eci_m + dr_eci_m);
  return central_difference(g, target, chaser, dr_eci_m) + (j2_acceleration(g, chaser) - j2_acceleration(g, target));
}

GravityPair gravity_pair_eci(const GravityParams& g, const Vec3& r_eci_m, const Vec3& dr_eci_m) {
  const Radius target(r_eci_m), chaser(r_eci_m + dr_eci_m);
  const Vec3 j2_target = j2_acceleration(g, target);
  return {.target_eci_mps2 = central_acceleration(g, target) + j2_target,
          .relative_eci_mps2 = central_difference(g, target, chaser, dr_eci_m) + (j2_acceleration(g, chaser) - j2_target)};
}

double nodal_regression_radps(const GravityParams& g, double semi_major_axis_m, double inclination_rad) {
  const double n = std::sqrt(g.mu_m3ps2 / std::pow(semi_major_axis_m, 3));
  const double ratio = g.radius_m / semi_major_axis_m;
  return -1.5 * n * g.j2 * ratio * ratio * std::cos(inclination_rad);
}

}  // namespace chaser::plant::earth
