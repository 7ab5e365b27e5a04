#pragma once
// The MPC-structured inverse model (Zhou 2018, section 2.2, eqs. 17-21).
//
// Over the receding horizon of n steps the input is one constant acceleration u (the inverse loop's
// outputs are constant over the horizon), so the predicted state is (eq. 18)
//   x^(t + n tau) = Phi(n tau) x(t) + Phi_u(n tau) u.
// The input minimises J = (x_c - x^)^T Q (x_c - x^) (eq. 20), the weighted least-squares solution
//   u = (Phi_u^T Q Phi_u)^-1 Phi_u^T Q (x_c - Phi x)
// (eq. 21 prints the second Q as missing; without it the solution is not the minimiser of eq. 20
// unless Q = I). The gain is computed once; one step is a 3x6 product. u is then held over the
// first step only and recomputed at the next (receding horizon).
#include "core/linear_models.hpp"
#include "core/types.hpp"

namespace chaser::invsim {


struct InverseModel {
  Mat6 phi;     // Phi(n tau)
  Mat63 phi_u;  // Phi_u(n tau), held input
  Mat36 gain;   // (Phi_u^T Q Phi_u)^-1 Phi_u^T Q
};

// n = horizon_steps, tau = step_s, Q = diag(weights) with positive entries.
InverseModel make_inverse_model(double mean_motion_radps, double step_s, int horizon_steps,
                                const Vec6& state_weights);

// u [m/s^2, Hill] that takes x (now) closest to x_desired at the end of the horizon.
Vec3 inverse_step(const InverseModel& model, const Vec6& x_hill, const Vec6& x_desired_hill);

}  // namespace chaser::invsim
