#include "invsim/inverse_step.hpp"

#include <Eigen/Cholesky>

#include "invsim/cw_transition.hpp"

namespace chaser::invsim {

InverseModel make_inverse_model(double n, double step_s, int horizon_steps,
                                const Vec6& state_weights) {
  const double horizon_s = step_s * horizon_steps;
  InverseModel m;
  m.phi = cw_state_transition(n, horizon_s);
  m.phi_u = cw_held_input_transition(n, horizon_s);
  const Mat63 q_phi_u = state_weights.asDiagonal() * m.phi_u;
  const Mat3 normal = m.phi_u.transpose() * q_phi_u;  // Phi_u^T Q Phi_u, SPD for Q > 0
  m.gain = normal.llt().solve(q_phi_u.transpose());
  return m;
}

Vec3 inverse_step(const InverseModel& m, const Vec6& x, const Vec6& x_desired) {
  return m.gain * (x_desired - m.phi * x);
}

}  // namespace chaser::invsim
