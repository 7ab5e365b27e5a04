#pragma once
// Discrete algebraic Riccati equation (DARE), discrete LQR and steady-state Kalman gains.
//
//   P = A' P A - A' P B (R + B' P B)^-1 B' P A + Q                                   (DARE)
//
// solved by the structured doubling algorithm (SDA-1: Chu, Fan, Lin, "A structure-preserving
// doubling algorithm for discrete-time algebraic Riccati equations", Lin. Alg. Appl. 396, 2005).
// Doubling squares the closed-loop transition each iteration, so convergence is quadratic and
// takes about log2(1 / (1 - |lambda_max|)) + 5 iterations even for the slow loops here (closed-loop
// poles at 1 - 1e-3); it needs no stabilising initial gain and has no tuning, so it is
// deterministic. Requires (A, B) stabilisable, (A, Q^1/2) detectable, Q >= 0, R > 0.
// Design-time code: dynamic sizes, may allocate.
#include <Eigen/Core>

namespace chaser {

struct DareSolution {
  Eigen::MatrixXd P;       // stabilising solution, symmetric positive semi-definite
  int iterations = 0;      // doubling steps taken
  bool converged = false;  // relative change of P fell below the tolerance
};

DareSolution solve_dare(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
                        const Eigen::MatrixXd& R);

// ||A'PA - P - A'PB (R + B'PB)^-1 B'PA + Q||_F / ||P||_F: how well P satisfies the DARE.
double dare_relative_residual(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
                              const Eigen::MatrixXd& R, const Eigen::MatrixXd& P);

// Discrete LQR: u = -K x minimises sum x'Qx + u'Ru for x+ = A x + B u; K = (R + B'PB)^-1 B'PA.
struct LqrDesign {
  Eigen::MatrixXd K;       // m x n state-feedback gain
  Eigen::MatrixXd P;       // cost-to-go matrix
  bool converged = false;
};
LqrDesign dlqr(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
               const Eigen::MatrixXd& R);

// Steady-state Kalman filter for x+ = A x + w, y = C x + v, cov(w) = W, cov(v) = V: the dual DARE
// (A', C', W, V) gives the predicted covariance P; the correction x+ = x- + L (y - C x-) has
// L = P C' (C P C' + V)^-1 and corrected covariance (I - L C) P.
struct KalmanDesign {
  Eigen::MatrixXd L;               // n x p measurement-update gain
  Eigen::MatrixXd P_predicted;     // covariance before the measurement update
  Eigen::MatrixXd P_corrected;     // covariance after it
  bool converged = false;
};
KalmanDesign steady_state_kalman(const Eigen::MatrixXd& A, const Eigen::MatrixXd& C, const Eigen::MatrixXd& W,
                                 const Eigen::MatrixXd& V);

}  // namespace chaser
