#include "plant/rigid_body.hpp"

namespace chaser::plant {

Vec3 euler_angular_acceleration_body(const Mat3& inertia, const Mat3& inertia_inv, const Vec3& omega,
                                     const Vec3& torque) {
  return inertia_inv * (torque - omega.cross(inertia * omega));  // Fonod 2015, eq. 13
}

Eigen::Vector4d quat_derivative(const Quat& q, const Vec3& omega) {
  // q (x) (0, w) = (-q.vec . w, q.w w + q.vec x w)
  const Vec3 dvec = 0.5 * (q.w() * omega + q.vec().cross(omega));
  return Eigen::Vector4d(dvec.x(), dvec.y(), dvec.z(), -0.5 * q.vec().dot(omega));
}

Vec3 angular_momentum_inertial(const Mat3& inertia, const Quat& q, const Vec3& omega) {
  return q * (inertia * omega);
}

double rotational_energy(const Mat3& inertia, const Vec3& omega) { return 0.5 * omega.dot(inertia * omega); }

}  // namespace chaser::plant
