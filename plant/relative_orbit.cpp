#include "plant/relative_orbit.hpp"

#include <cmath>

namespace chaser::plant {

Vec3 relative_orbit_acceleration_lvlh(double a, double n, const Vec3& r, const Vec3& v) {
  // q = (2 a xi + |rho|^2) / a^2. This is the hot path of the simulator: one sqrt and one division
  // on the dependency chain (with p = (R / a)^3: f = q (3 + 3 q + q^2) / (1 + p) and
  // mu / R^3 = n^2 / p share the reciprocal of p (1 + p)).
  const double inv_a = 1.0 / a;
  const double q = (2.0 * r.x() + r.squaredNorm() * inv_a) * inv_a;
  const double p = (1.0 + q) * std::sqrt(1.0 + q);                  // (R / a)^3
  const double inv = n * n / (p * (1.0 + p));
  const double mu_over_r3 = (1.0 + p) * inv;                        // [1/s^2] mu / R^3 = n^2 / p
  const double radial = q * (3.0 + q * (3.0 + q)) * inv;            // [1/s^2] n^2 - mu / R^3 = (mu / R^3) f(q)
  return Vec3(radial * (a + r.x()) + 2.0 * n * v.y(),  // Fonod 2015, eq. 8 (x)
              radial * r.y() - 2.0 * n * v.x(),        // eq. 8 (y)
              -mu_over_r3 * r.z());                    // eq. 8 (z)
}

}  // namespace chaser::plant
