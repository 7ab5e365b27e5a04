#include "core/rotation.hpp"

#include <cmath>

namespace chaser {

Mat3 skew(const Vec3& a) {
  Mat3 s;
  s << 0.0, -a.z(), a.y(),  //
      a.z(), 0.0, -a.x(),   //
      -a.y(), a.x(), 0.0;
  return s;
}

Quat quat_from_rotation_vector(const Vec3& rotation_vector) {
  const double angle = rotation_vector.norm();
  constexpr double kSmallAngle = 1e-8;  // below this sin(a/2)/a = 1/2 - a^2/48 to machine precision
  const double half_sinc = angle < kSmallAngle ? 0.5 - angle * angle / 48.0 : std::sin(0.5 * angle) / angle;
  const Vec3 v = half_sinc * rotation_vector;
  return Quat(std::cos(0.5 * angle), v.x(), v.y(), v.z());
}

Vec3 rotation_vector_from_quat(const Quat& q_in) {
  const Quat q = q_in.w() < 0.0 ? Quat(-q_in.coeffs()) : q_in;
  const double w = q.w(), vec_norm_sq = q.vec().squaredNorm();
  // Small angles, x = |v| / w below 1/128 (rotations below 0.9 deg: every attitude error of a
  // controlled approach): angle / |v| = (2 / w) atan(x) / x by its series 1 - x^2/3 + x^4/5 - x^6/7,
  // whose next term x^8/9 < 2e-18 is below rounding. No sqrt and no atan2: this runs several times
  // per control period (attitude control, the attitude FDI scheme).
  if (vec_norm_sq * 16384.0 < w * w) {
    const double x2 = vec_norm_sq / (w * w);
    const double atan_x_over_x = 1.0 - x2 * (1.0 / 3.0 - x2 * (1.0 / 5.0 - x2 * (1.0 / 7.0)));
    return (2.0 * atan_x_over_x / w) * q.vec();
  }
  const double vec_norm = std::sqrt(vec_norm_sq);
  const double angle = 2.0 * std::atan2(vec_norm, w);
  return (angle / vec_norm) * q.vec();
}

Quat rotation_towards(const Vec3& u, const Vec3& v, double fraction) {
  Vec3 axis = u.cross(v);
  const double angle = std::atan2(axis.norm(), u.dot(v));
  if (axis.norm() < 1e-12) {
    axis = u.cross(Vec3::UnitZ());
    if (axis.norm() < 1e-6) axis = u.cross(Vec3::UnitX());
  }
  return Quat(Eigen::AngleAxisd(fraction * angle, axis.normalized()));
}

Vec3 attitude_error_body(const Quat& q_inertial_from_desired, const Quat& q_inertial_from_body) {
  return rotation_vector_from_quat(q_inertial_from_desired.conjugate() * q_inertial_from_body);
}

Vec3 small_angle_error_body(const Quat& q_inertial_from_desired, const Quat& q_inertial_from_body) {
  const Quat q = q_inertial_from_desired.conjugate() * q_inertial_from_body;
  return (q.w() < 0.0 ? -2.0 : 2.0) * q.vec();
}


// MSR: x zenith, y along-track, z orbit normal. Zhou: x along-track, y anti-normal, z nadir.
Vec3 zhou_from_msr(const Vec3& v) { return Vec3(v.y(), -v.z(), -v.x()); }
Vec3 msr_from_zhou(const Vec3& v) { return Vec3(-v.z(), v.x(), -v.y()); }

}  // namespace chaser
