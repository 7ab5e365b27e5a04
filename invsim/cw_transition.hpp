#pragma once
// Clohessy-Wiltshire relative motion in the manual-RVD Hill frame (Zhou 2018, eq. 2): x along the
// target's velocity, y opposite the orbit normal, z towards the Earth; state [x y z x' y' z'].
//   x'' - 2 n z'        = u_x
//   y'' + n^2 y         = u_y
//   z'' + 2 n x' - 3 n^2 z = u_z
// The closed-form transition matrices below are derived here from the classic HCW solution mapped
// through zhou_from_msr (the extracted text of eqs. 4-7 is damaged: signs of the z terms and the
// -3 tau^2/2 term of the held-input matrix are lost). Tested against Van Loan and RK4.
#include "core/linear_models.hpp"
#include "core/types.hpp"

namespace chaser::invsim {


// Continuous model x' = A x + B u of eq. 2.
Mat6 cw_state_matrix(double mean_motion_radps);
Mat63 cw_input_matrix();

// Phi(t, t0) of eq. 3-4: x(t0 + tau) = Phi x(t0) with no input.
Mat6 cw_state_transition(double mean_motion_radps, double tau_s);

// Phi_u(t, tau) of eq. 5: the response at t0 + tau to a unit velocity impulse at t0 (the last
// three columns of Phi).
Mat63 cw_impulse_transition(double mean_motion_radps, double tau_s);

// Phi_u(t, t0) of eqs. 6-7: the response at t0 + tau to an acceleration held over [t0, t0 + tau],
// int_0^tau Phi(s) ds B.
Mat63 cw_held_input_transition(double mean_motion_radps, double tau_s);

}  // namespace chaser::invsim
