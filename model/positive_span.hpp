#pragma once
// Positive spanning: can a set of thrusters, each pushing only one way (on-times >= 0), produce
// force and torque in every direction? With M the 6x8 configuration matrix of a branch
// (Fonod 2015, eq. 2), the branch is fully controllable in the unilateral sense iff the columns of M
// positively span R^6, i.e. (Davis 1954) rank M = 6 and M lambda = 0 for some lambda > 0 elementwise.
//
// Test used here (equivalent and numerically robust): rank M = k and, for every column m_j, -m_j
// lies in the cone {M x : x >= 0}. The cone membership is decided by non-negative least squares
// (Lawson & Hanson 1974, ch. 23): the residual of min ||M x + m_j|| over x >= 0 is zero iff it does.
// Summing the certificates gives lambda = sum_j (e_j + x_j) >= 1 with M lambda = 0. When -m_j is
// not in the cone, the NNLS residual d satisfies M^T d <= 0 (optimality condition): a direction no
// column can push along, reported as the certificate of failure.
#include <Eigen/Core>

namespace chaser::model {

// Relative tolerance of the span test. Columns are scaled to unit length first (a positive column
// scaling changes neither the cone nor the span), so residuals and singular values are compared to
// 1: at 1e-9 a genuinely spanning thruster set (margin of order 0.1) is never rejected, and a set
// that fails only by rounding (1e-15) is never accepted as failing.
inline constexpr double kPositiveSpanTolerance = 1e-9;

struct NnlsResult {
  Eigen::VectorXd x;           // minimiser, x >= 0
  double residual_norm = 0.0;  // ||A x - b||
  bool converged = false;      // false only if the iteration limit was hit
};

// min ||A x - b||_2 subject to x >= 0 (Lawson & Hanson, algorithm NNLS). At most 3 n outer
// iterations (their recommended limit), so it always terminates.
NnlsResult solve_nnls(const Eigen::MatrixXd& a, const Eigen::VectorXd& b);

struct PositiveSpanResult {
  bool spans = false;                 // the columns positively span R^k
  int rank = 0;                       // numerical rank of the column-normalised matrix
  Eigen::VectorXd null_combination;   // if spans: lambda, min element 1, M lambda = 0 (to tolerance)
  Eigen::VectorXd blocked_direction;  // if not: unit d with d . m_j <= tolerance |m_j| for all j
};

PositiveSpanResult positive_span(const Eigen::MatrixXd& m,
                                 double tolerance = kPositiveSpanTolerance);

}  // namespace chaser::model
