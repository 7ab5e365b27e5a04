#pragma once
// The discrete-time algebraic Riccati equation by SLICOT's SB02OD (SLICOT 5.0, Debian's
// libslicot): the method of deflating subspaces (van Dooren 1981) on the extended symplectic
// pencil, which needs neither A nor R to be positive definite or A invertible:
//
//   X = A' X A - A' X B (R + B' X B)^-1 B' X A + Q,
//
// X the stabilising solution (A - B (R + B' X B)^-1 B' X A has every eigenvalue inside the unit
// circle). R must be symmetric and nonsingular, not definite: an H-infinity filter's R is
// diag(R_noise, -gamma^2 I) (flight/fdi/design/uio_bank.hpp). Every SB02OD INFO comes back as a
// status with a message; sizes and finiteness are checked here first, because an illegal argument
// makes SLICOT call XERBLA, which STOPs the process.
//
// Design-time code: allocates; one SB02OD call per solve.
#include <Eigen/Core>
#include <string>

namespace chaser::control {

struct DareResult {
  bool ok = false;
  std::string message;        // what went wrong; "" when ok
  int slicot_info = 0;        // SB02OD's INFO (0 unless SLICOT was called and failed)
  Eigen::MatrixXd X;          // the stabilising solution, symmetrised
  Eigen::VectorXcd closed_loop;  // the N stable eigenvalues of the pencil (the closed loop's)
  double rcond = 0;           // SB02OD's estimate of the solve's reciprocal condition number
  double residual = 0;        // ||right side - X||_F / max(1, ||X||_F), computed here
};

// A n x n, B n x m, Q n x n symmetric, R m x m symmetric nonsingular.
DareResult solve_dare(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
                      const Eigen::MatrixXd& R);

}  // namespace chaser::control
