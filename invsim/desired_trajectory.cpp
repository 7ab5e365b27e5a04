#include "invsim/desired_trajectory.hpp"

#include <cmath>

namespace chaser::invsim {

double approach_velocity_mps(const model::InvSimTrajectoryParams& p, double x0) {
  return -(x0 - p.dock_x_m) / (p.damping_start_s + p.damping_time_constant_s);
}

Vec6 desired_state(const model::InvSimTrajectoryParams& p, double x0, double t) {
  const double v_a = approach_velocity_mps(p, x0);
  Vec6 x = Vec6::Zero();
  if (t <= p.damping_start_s) {
    x(0) = x0 + v_a * t;
    x(3) = v_a;
    return x;
  }
  const double x_s = x0 + v_a * p.damping_start_s;
  const double decay = std::exp(-(t - p.damping_start_s) / p.damping_time_constant_s);
  x(0) = p.dock_x_m + (x_s - p.dock_x_m) * decay;
  x(3) = -(x_s - p.dock_x_m) / p.damping_time_constant_s * decay;
  return x;
}

namespace {

// The critically damped path from (q0, q0') at t = 0: sets q and q' at t.
void critically_damped(double time_constant_s, double q0, double v0, double t_s, double& q, double& v) {
  const double decay = std::exp(-t_s / time_constant_s);
  const double slope = v0 + q0 / time_constant_s;
  q = (q0 + slope * t_s) * decay;
  v = (v0 - slope * t_s / time_constant_s) * decay;
}

}  // namespace

void set_lateral_return(double time_constant_s, const Vec3& r0_m, const Vec3& v0_mps, double t_s,
                        Vec6& x_desired) {
  for (int axis : {1, 2})
    critically_damped(time_constant_s, r0_m(axis), v0_mps(axis), t_s, x_desired(axis), x_desired(axis + 3));
}

void set_lateral_brake_then_return(double brake_mps2, double time_constant_s, const Vec3& r0_m,
                                   const Vec3& v0_mps, double t_s, Vec6& x_desired) {
  for (int axis : {1, 2}) {
    const double q0 = r0_m(axis);
    const double v0 = v0_mps(axis);
    const double t_stop = std::abs(v0) / brake_mps2;
    if (t_s <= t_stop) {
      const double a = -std::copysign(brake_mps2, v0);
      x_desired(axis) = q0 + v0 * t_s + 0.5 * a * t_s * t_s;
      x_desired(axis + 3) = v0 + a * t_s;
    } else {
      critically_damped(time_constant_s, q0 + 0.5 * v0 * t_stop, 0.0, t_s - t_stop, x_desired(axis),
                        x_desired(axis + 3));
    }
  }
}

}  // namespace chaser::invsim
