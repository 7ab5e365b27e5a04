#include "core/riccati.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>

namespace chaser {
namespace {

constexpr int kMaxDoublingSteps = 200;      // 2^200 squarings: far beyond any useful pole radius
constexpr double kRelativeTolerance = 1e-14;  // a few ulps of ||P||: doubling converges quadratically

Eigen::MatrixXd symmetric_part(const Eigen::MatrixXd& m) { return 0.5 * (m + m.transpose()); }

}  // namespace

DareSolution solve_dare(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
                        const Eigen::MatrixXd& R) {
  const Eigen::Index n = A.rows();
  const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(n, n);
  Eigen::MatrixXd Ak = A;
  Eigen::MatrixXd Gk = symmetric_part(B * R.ldlt().solve(B.transpose()));
  Eigen::MatrixXd Hk = symmetric_part(Q);
  DareSolution out;
  for (int k = 1; k <= kMaxDoublingSteps; ++k) {
    const Eigen::PartialPivLU<Eigen::MatrixXd> w_lu(identity + Gk * Hk);
    const Eigen::MatrixXd w_inv_a = w_lu.solve(Ak);
    const Eigen::MatrixXd w_inv_g = w_lu.solve(Gk);
    const Eigen::MatrixXd h_next = symmetric_part(Hk + Ak.transpose() * Hk * w_inv_a);
    Gk = symmetric_part(Gk + Ak * w_inv_g * Ak.transpose());
    Ak = Ak * w_inv_a;
    const double change = (h_next - Hk).norm();
    Hk = h_next;
    out.iterations = k;
    if (change <= kRelativeTolerance * Hk.norm()) {
      out.converged = true;
      break;
    }
  }
  out.P = Hk;
  return out;
}

double dare_relative_residual(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
                              const Eigen::MatrixXd& R, const Eigen::MatrixXd& P) {
  const Eigen::MatrixXd btpa = B.transpose() * P * A;
  const Eigen::MatrixXd s = R + B.transpose() * P * B;
  const Eigen::MatrixXd residual =
      A.transpose() * P * A - P - btpa.transpose() * s.ldlt().solve(btpa) + Q;
  const double scale = P.norm();
  return scale > 0.0 ? residual.norm() / scale : residual.norm();
}

LqrDesign dlqr(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
               const Eigen::MatrixXd& R) {
  const DareSolution dare = solve_dare(A, B, Q, R);
  const Eigen::MatrixXd s = R + B.transpose() * dare.P * B;
  return LqrDesign{s.ldlt().solve(B.transpose() * dare.P * A), dare.P, dare.converged};
}

KalmanDesign steady_state_kalman(const Eigen::MatrixXd& A, const Eigen::MatrixXd& C, const Eigen::MatrixXd& W,
                                 const Eigen::MatrixXd& V) {
  const DareSolution dare = solve_dare(A.transpose(), C.transpose(), W, V);
  const Eigen::MatrixXd& P = dare.P;
  const Eigen::MatrixXd innovation_cov = C * P * C.transpose() + V;
  const Eigen::MatrixXd L = innovation_cov.ldlt().solve(C * P).transpose();  // P C' S^-1, S symmetric
  const Eigen::Index n = A.rows();
  const Eigen::MatrixXd P_corrected = symmetric_part((Eigen::MatrixXd::Identity(n, n) - L * C) * P);
  return KalmanDesign{L, P, P_corrected, dare.converged};
}

}  // namespace chaser
