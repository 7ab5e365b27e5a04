#pragma once
// Discretisation of x' = A x + B u when the command of period k reaches the actuator only at
// kT + delta, delta in [0, T) (Fonod 2015, eqs. 19-23 with l = 0, m = 1). During [kT, kT + delta)
// the previous command u(k-1) still acts, so
//   x(k+1) = A_bar x(k) + Gamma_0(delta) u(k) + Gamma_1(delta) u(k-1),            eq. 21
//   A_bar = e^{AT},  Gamma_0 = int_0^{T-delta} e^{At} dt B,  Gamma_1 = int_{T-delta}^T e^{At} dt B,
//   Gamma_0 + Gamma_1 = B_bar = int_0^T e^{At} dt B.                                eq. 22
// Every integral comes from a block matrix exponential (Van Loan 1978), exact for singular A.
#include <Eigen/Core>

namespace chaser::flight::fdi {

struct ExpIntegral {
  Eigen::MatrixXd exp_At;      // e^{A t}
  Eigen::MatrixXd integral_B;  // int_0^t e^{A s} ds B
};

// exp([[A, B], [0, 0]] t) = [[e^{At}, int_0^t e^{As} ds B], [0, I]]; t >= 0 [s].
ExpIntegral exp_and_integral(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, double t);

struct DelayFreeDiscretization {
  Eigen::MatrixXd A_bar;  // e^{AT}
  Eigen::MatrixXd B_bar;  // int_0^T e^{At} dt B, eq. 22
};

DelayFreeDiscretization discretize(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                                   double period_s);

// Gamma_0(delta) = int_0^{T-delta} e^{At} dt B (eq. 21), 0 <= delta <= T [s].
Eigen::MatrixXd gamma0(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, double period_s,
                       double delta_s);

// Gamma_1(delta) = int_{T-delta}^T e^{At} dt B, computed as e^{A(T-delta)} int_0^delta e^{As} ds B
// so that it is exactly zero at delta = 0 and accurate for small delays (no cancellation).
Eigen::MatrixXd gamma1(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, double period_s,
                       double delta_s);

}  // namespace chaser::flight::fdi
