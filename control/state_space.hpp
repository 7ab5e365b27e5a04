#pragma once
// Continuous-time state space and the lower linear fractional transformation (LFT).
//
//   x' = a x + b u,   y = c x + d u                                            (StateSpace)
//
// Lower LFT (Skogestad & Postlethwaite, "Multivariable Feedback Control", 2nd ed., 2005, sec. 3.8;
// Zhou, Doyle, Glover, "Robust and Optimal Control", 1996, the chapter on linear fractional
// transformations): the generalised plant P has inputs [w; u] and outputs [z; y], where u
// (n_ctrl) is the control input and y (n_meas) the measurement. Partitioned conformally,
//
//   P = [ A  | B1  B2  ]      K = [ Ak | Bk ]      u = K y,
//       [ C1 | D11 D12 ]          [ Ck | Dk ]
//       [ C2 | D21 D22 ]
//
// and F_l(P, K) is the closed loop from w to z. D22 != 0 is handled: with
// R = (I - D22 Dk)^-1 (n_meas x n_meas) and R~ = (I - Dk D22)^-1 (n_ctrl x n_ctrl), the closed loop
// on the state [x; xk] is (the loop equations solved for u and y; derivation in state_space.cpp):
//
//   Acl = [ A + B2 R~ Dk C2     B2 R~ Ck            ]   Bcl = [ B1 + B2 R~ Dk D21 ]
//         [ Bk R C2             Ak + Bk R D22 Ck    ]         [ Bk R D21          ]
//   Ccl = [ C1 + D12 R~ Dk C2   D12 R~ Ck ]         Dcl = D11 + D12 R~ Dk D21
//
// The loop is well posed only if I - D22 Dk is invertible; lower_lft refuses it otherwise.
// Design-time code: dynamic sizes, allocates.
#include <Eigen/Core>
#include <string>
#include <vector>

namespace chaser::control {

struct StateSpace {
  Eigen::MatrixXd a;  // [n x n] state matrix
  Eigen::MatrixXd b;  // [n x m] input matrix
  Eigen::MatrixXd c;  // [p x n] output matrix
  Eigen::MatrixXd d;  // [p x m] feedthrough

  Eigen::Index states() const { return a.rows(); }
  Eigen::Index inputs() const { return d.cols(); }
  Eigen::Index outputs() const { return d.rows(); }
};

// Every size or finiteness problem of `sys`, one line each, prefixed by `name` (empty: consistent).
// A static gain is a StateSpace with 0 states: a 0 x 0, b 0 x m, c p x 0.
std::vector<std::string> validate(const StateSpace& sys, const std::string& name);

// A static gain d (no states).
StateSpace static_gain(const Eigen::MatrixXd& d);

// F_l(p, k): the closed loop from w (the first inputs() - n_ctrl inputs of p) to z (the first
// outputs() - n_meas outputs). k has n_meas inputs and n_ctrl outputs. Throws std::invalid_argument
// naming every size problem, or if I - D22 Dk is singular (an ill-posed loop).
StateSpace lower_lft(const StateSpace& p, int n_meas, int n_ctrl, const StateSpace& k);

}  // namespace chaser::control
