#include "invsim/relative_dynamics.hpp"

#include <cmath>

namespace chaser::invsim {
namespace {

// The integrated state as one vector: r, v, q (w x y z), omega.
using Vec13 = Eigen::Matrix<double, 13, 1>;

Vec13 pack(const RvdState& s) {
  Vec13 x;
  x << s.r_hill_m, s.v_hill_mps, s.q_hill_from_body.w(), s.q_hill_from_body.vec(), s.omega_body_radps;
  return x;
}

RvdState unpack(const Vec13& x) {
  RvdState s;
  s.r_hill_m = x.segment<3>(0);
  s.v_hill_mps = x.segment<3>(3);
  s.q_hill_from_body = Quat(x(6), x(7), x(8), x(9)).normalized();
  s.omega_body_radps = x.segment<3>(10);
  return s;
}

Vec13 derivative(const RvdConstants& c, const Vec13& x, const Vec3& force, const Vec3& torque) {
  const Quat q(x(6), x(7), x(8), x(9));  // renormalised only at the end of the piece
  const Mat3 r_hill_from_body = q.normalized().toRotationMatrix();
  const Vec3 omega = x.segment<3>(10);
  const Vec3 omega_rel =
      omega - r_hill_from_body.transpose() * Vec3(0.0, -c.mean_motion_radps, 0.0);
  const Quat q_dot = q * Quat(0.0, omega_rel.x(), omega_rel.y(), omega_rel.z());
  Vec13 d;
  d.segment<3>(0) = x.segment<3>(3);
  d.segment<3>(3) = relative_gravity_accel(c, x.segment<3>(0), x.segment<3>(3)) +
                    r_hill_from_body * force / c.mass_kg;
  d(6) = 0.5 * q_dot.w();
  d.segment<3>(7) = 0.5 * q_dot.vec();
  d.segment<3>(10) = c.inertia_inv * (torque - omega.cross(c.inertia_kgm2 * omega));
  return d;
}

}  // namespace

RvdConstants make_rvd_constants(double mu, double radius, double mass, const Mat3& inertia) {
  return {mu, radius, std::sqrt(mu / (radius * radius * radius)), mass, inertia, inertia.inverse()};
}

Vec3 relative_gravity_accel(const RvdConstants& c, const Vec3& r, const Vec3& v) {
  const double n = c.mean_motion_radps, big_r = c.radius_m;
  const double rz = big_r - r.z();
  const double dist = std::sqrt(rz * rz + r.x() * r.x() + r.y() * r.y());
  const double mu_r3 = c.mu_m3ps2 / (dist * dist * dist);
  return Vec3(2.0 * n * v.z() + n * n * r.x() - mu_r3 * r.x(),
              -mu_r3 * r.y(),
              -2.0 * n * v.x() + n * n * r.z() - c.mu_m3ps2 / (big_r * big_r) + mu_r3 * rz);
}

Vec3 relative_rate_body(const RvdConstants& c, const RvdState& s) {
  return s.omega_body_radps -
         s.q_hill_from_body.toRotationMatrix().transpose() * Vec3(0.0, -c.mean_motion_radps, 0.0);
}

void propagate_piece(const RvdConstants& c, const Vec3& force, const Vec3& torque, double dt,
                     RvdState& s) {
  if (dt <= 0.0) return;
  const Vec13 x = pack(s);
  const Vec13 k1 = derivative(c, x, force, torque);
  const Vec13 k2 = derivative(c, x + 0.5 * dt * k1, force, torque);
  const Vec13 k3 = derivative(c, x + 0.5 * dt * k2, force, torque);
  const Vec13 k4 = derivative(c, x + dt * k3, force, torque);
  s = unpack(x + dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4));
}

}  // namespace chaser::invsim
