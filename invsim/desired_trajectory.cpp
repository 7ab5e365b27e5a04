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

void set_lateral_return(double time_constant_s, const Vec3& r0_m, const Vec3& v0_mps, double t_s,
                        Vec6& x_desired) {
  const double decay = std::exp(-t_s / time_constant_s);
  for (int axis : {1, 2}) {
    const double slope = v0_mps(axis) + r0_m(axis) / time_constant_s;
    x_desired(axis) = (r0_m(axis) + slope * t_s) * decay;
    x_desired(axis + 3) = (v0_mps(axis) - slope * t_s / time_constant_s) * decay;
  }
}

}  // namespace chaser::invsim
