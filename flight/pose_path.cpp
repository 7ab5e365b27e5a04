#include "flight/pose_path.hpp"

#include <algorithm>

#include <Eigen/Geometry>

namespace chaser::flight {

Blend quintic(double t_s, double duration_s) {
  if (t_s >= duration_s) return {};
  const double x = std::max(0.0, t_s / duration_s);
  return {x * x * x * (10.0 - 15.0 * x + 6.0 * x * x), 30.0 * x * x * (1.0 - x) * (1.0 - x) / duration_s,
          60.0 * x * (1.0 - x) * (1.0 - 2.0 * x) / (duration_s * duration_s)};
}

arm::FrameMotion pose_path(const Vec3& r0_m, const Quat& q0, const Vec3& r1_m, const Quat& q1, double elapsed_s,
                           double duration_s) {
  const Blend b = quintic(elapsed_s, duration_s);
  const Vec3 travel = r1_m - r0_m;
  const Eigen::AngleAxisd turn(q0.conjugate() * q1);
  const Vec3 axis = q0 * turn.axis();  // the frame's axes
  arm::FrameMotion f;
  f.r_m = r0_m + b.s * travel;
  f.v_mps = b.rate * travel;
  f.a_mps2 = b.acceleration * travel;
  f.q_world_from_frame = q0 * Quat(Eigen::AngleAxisd(b.s * turn.angle(), turn.axis()));
  f.omega_radps = b.rate * turn.angle() * axis;
  f.alpha_radps2 = b.acceleration * turn.angle() * axis;
  return f;
}

}  // namespace chaser::flight
