#pragma once
// The generalised plant of the mixed-sensitivity problem
//
//   min_K || [ W_S S ; W_KS K S ; W_T T ] ||_inf,   S = (I + G K)^-1,  T = G K S = I - S
//
// (Skogestad & Postlethwaite, "Multivariable Feedback Control", 2nd ed., 2005: the general
// control configuration of sec. 3.8 and the mixed-sensitivity design of sec. 9.3, S/KS/T form).
//
// Signs: the reference is the exogenous input, w = r (then w_d, with W_d below); the controller sees the error e = r - y and
// outputs u = K e; y = G u. Then e = S r, u = K S r, y = T r, and with z = [W_S e; W_KS u; W_T y]
//
//   [ z1 ]   [ W_S   -W_S G  ]
//   [ z2 ] = [ 0      W_KS   ] [ r ]          (P's inputs [w; u] = [r; u],
//   [ z3 ]   [ 0      W_T G  ] [ u ]           outputs [z; v] with v = e, n_meas = n_y, n_ctrl = n_u)
//   [ v  ]   [ I     -G      ]
//
// so that F_l(P, K) = [W_S S; W_KS K S; W_T T] (S&P write W_P, W_u, W_T for W_S, W_KS, W_T).
// Any weight may be absent (its rows of z are left out). Realisation: the state is
// [x_G; x_S; x_KS; x_T], each weight driven by the signal it weighs; P's order is the sum of the
// orders. D22 = -D_G (zero for a strictly proper G).
// For hinf_synthesis (SB10AD) the problem must satisfy its assumptions: D12 = [-D_S D_G; D_KS;
// D_T D_G] of full column rank (for strictly proper G, a W_KS with full-rank feedthrough), and no
// weight pole on the imaginary axis (an integrator in W_S breaks (A3): use s + omega_B A, A small).
#include <optional>

#include "control/state_space.hpp"

namespace chaser::control {

struct MixedSensitivityWeights {
  std::optional<StateSpace> w_s;   // on e = S r: n_y inputs, any number of outputs
  std::optional<StateSpace> w_ks;  // on u = K S r: n_u inputs
  std::optional<StateSpace> w_t;   // on y = T r: n_y inputs
  // Optional input disturbance: d = W_d w_d adds to u at G's input (y = G (u + d)), a second
  // exogenous input after r. It brings G S (d -> e) and K S G (d -> u) into the problem, which an
  // S/KS design otherwise ignores: without it the optimum cancels the plant's slow poles with
  // controller zeros and leaves them in the loop, where an input disturbance excites them
  // (S&P sec. 9.3; docs/control.md, "Input disturbance"). n_u inputs, n_u outputs.
  std::optional<StateSpace> w_d;
};

struct GeneralisedPlant {
  StateSpace p;     // inputs [r; u], outputs [z; e]
  int n_meas = 0;   // = n_y: the controller's inputs (the error e)
  int n_ctrl = 0;   // = n_u: the controller's outputs
};

// S&P's performance weight w_P(s) = (s / M + omega_B) / (s + omega_B A) (sec. 2.8), SISO:
// |S| is kept below 1 / |w_P|, i.e. below A at low frequency, below M at high frequency, crossing
// 1 near omega_B.
StateSpace performance_weight(double peak_m, double bandwidth_radps, double low_freq_gain_a);

// Throws std::invalid_argument naming every problem (a weight whose inputs do not match G, no
// weight at all, inconsistent sizes).
GeneralisedPlant mixed_sensitivity_plant(const StateSpace& g, const MixedSensitivityWeights& weights);

}  // namespace chaser::control
