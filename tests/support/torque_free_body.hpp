#pragma once
// The tests' own torque-free rigid body, a reference independent of the product's integrators
// (flight/target_estimator.cpp, plant/orbit_propagator.cpp): classical RK4 on the quaternion and the
// rate together, the quaternion's rate written out component by component, renormalised after
// each step. ENVISAT's inertia (scenarios/comrade_envisat.yaml) is the usual case.
#include <cmath>

#include "core/types.hpp"

namespace chaser::testing {

inline Mat3 envisat_inertia_kgm2() {
  Mat3 i;
  i << 17023.3, 397.1, -2171.4, 397.1, 124825.7, 344.2, -2171.4, 344.2, 129112.2;
  return i;
}

struct TorqueFreeBody {
  Mat3 inertia_kgm2 = Mat3::Identity();
  Quat q_inertial_from_body = Quat::Identity();
  Vec3 omega_body_radps = Vec3::Zero();

  // Euler's equations without torque: omega' = -I^-1 (omega x I omega).
  Vec3 omega_dot() const { return rate_of(omega_body_radps); }

  void step(double h_s) {
    const Eigen::Vector4d q0 = q_inertial_from_body.coeffs();
    const Vec3& w0 = omega_body_radps;
    const Eigen::Vector4d a = quat_rate(q0, w0);
    const Vec3 wa = rate_of(w0);
    const Eigen::Vector4d b = quat_rate(q0 + 0.5 * h_s * a, w0 + 0.5 * h_s * wa);
    const Vec3 wb = rate_of(w0 + 0.5 * h_s * wa);
    const Eigen::Vector4d c = quat_rate(q0 + 0.5 * h_s * b, w0 + 0.5 * h_s * wb);
    const Vec3 wc = rate_of(w0 + 0.5 * h_s * wb);
    const Eigen::Vector4d d = quat_rate(q0 + h_s * c, w0 + h_s * wc);
    const Vec3 wd = rate_of(w0 + h_s * wc);
    q_inertial_from_body.coeffs() = q0 + h_s / 6 * (a + 2 * b + 2 * c + d);
    q_inertial_from_body.normalize();
    omega_body_radps = w0 + h_s / 6 * (wa + 2 * wb + 2 * wc + wd);
  }

  // Whole steps of h_s (1 ms by default) over duration_s.
  void advance(double duration_s, double h_s = 1e-3) {
    for (long k = 0, n = std::lround(duration_s / h_s); k < n; ++k) step(h_s);
  }

 private:
  Vec3 rate_of(const Vec3& w) const { return -inertia_kgm2.inverse() * w.cross(inertia_kgm2 * w); }
  // q' = 1/2 q (x) (0, w) in coeffs() order (x, y, z, w).
  static Eigen::Vector4d quat_rate(const Eigen::Vector4d& q, const Vec3& w) {
    Eigen::Vector4d dq;
    dq << 0.5 * (q.w() * w.x() + q.y() * w.z() - q.z() * w.y()), 0.5 * (q.w() * w.y() + q.z() * w.x() - q.x() * w.z()),
        0.5 * (q.w() * w.z() + q.x() * w.y() - q.y() * w.x()), -0.5 * (q.x() * w.x() + q.y() * w.y() + q.z() * w.z());
    return dq;
  }
};

}  // namespace chaser::testing
