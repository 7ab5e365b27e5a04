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

}  // namespace chaser::invsim
