#pragma once
// Zero-order-hold discretisation of a continuous linear model x' = A x + B u.
//
// With u held constant over [kT, (k+1)T], x(k+1) = Ad x(k) + Bd u(k), where Ad = exp(A T) and
// Bd = int_0^T exp(A s) ds B. Both come from one matrix exponential (Van Loan 1978):
//   exp([[A, B], [0, 0]] T) = [[Ad, Bd], [0, I]].
// Exact for singular A (double integrators, HCW), where Bd = A^-1 (Ad - I) B does not exist.
// Used at design time only (gains, filters), so dynamic sizes are fine here.
#include <Eigen/Core>

namespace chaser {

struct DiscreteModel {
  Eigen::MatrixXd Ad;  // state transition over one period
  Eigen::MatrixXd Bd;  // input matrix of the held input
};

// A is n x n, B is n x m, period_s > 0.
DiscreteModel discretize_zoh(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, double period_s);

}  // namespace chaser
