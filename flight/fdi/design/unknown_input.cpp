#include "flight/fdi/design/unknown_input.hpp"

#include <Eigen/QR>
#include <Eigen/SVD>
#include <stdexcept>

namespace chaser::flight::fdi {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

MatrixXd unknown_input_matrix(const std::vector<MatrixXd>& vertices_a,
                              const std::vector<MatrixXd>& vertices_b) {
  Index rows = 0;
  Index cols = 0;
  for (const auto* list : {&vertices_a, &vertices_b})
    for (const MatrixXd& v : *list) rows = v.rows(), cols += v.cols();
  MatrixXd e(rows, cols);
  Index at = 0;
  for (const auto* list : {&vertices_a, &vertices_b})
    for (const MatrixXd& v : *list) e.middleCols(at, v.cols()) = v, at += v.cols();
  return e;
}

namespace {

struct OutputSvd {  // C = U_C S_C V_C^T, C of full row rank
  MatrixXd U;
  VectorXd s;
  MatrixXd V;  // [n_x x n_y]
};

OutputSvd output_svd(const MatrixXd& C) {
  Eigen::JacobiSVD<MatrixXd> svd(C, Eigen::ComputeFullU | Eigen::ComputeThinV);
  const VectorXd& s = svd.singularValues();
  if (s.size() < C.rows() || s(s.size() - 1) <= 1e-12 * s(0))
    throw std::invalid_argument("C must have full row rank");
  return {svd.matrixU(), s, svd.matrixV()};
}

// Left singular vectors and singular values of X, padded with zeros to n_y values.
void full_left_svd(const MatrixXd& X, MatrixXd& U, VectorXd& sigma) {
  Eigen::JacobiSVD<MatrixXd> svd(X, Eigen::ComputeFullU);
  U = svd.matrixU();
  sigma = VectorXd::Zero(X.rows());
  sigma.head(svd.singularValues().size()) = svd.singularValues();
}

void fix_row_signs(MatrixXd& Q) {
  for (Index i = 0; i < Q.rows(); ++i) {
    Index j = 0;
    Q.row(i).cwiseAbs().maxCoeff(&j);
    if (Q(i, j) < 0.0) Q.row(i) *= -1.0;
  }
}

LowRankChoice seen_part_choice(const MatrixXd& E_d, const MatrixXd& C, int n_r, double tie_rel_tol) {
  const OutputSvd c = output_svd(C);
  LowRankChoice choice;
  choice.output_U = c.U, choice.output_s = c.s, choice.output_V = c.V;
  full_left_svd(c.V.transpose() * E_d, choice.tied, choice.singular_values);
  const VectorXd& s = choice.singular_values;
  const Index n_y = C.rows();
  const Index k = n_y - n_r;  // kept
  const double tol = tie_rel_tol * s(0);
  Index a = k;  // first index of the cluster tied with the first discarded sigma_k
  while (a > 0 && s(a - 1) - s(k) <= tol) --a;
  Index b = k;  // last index of that cluster
  while (b + 1 < n_y && s(k) - s(b + 1) <= tol) ++b;
  if (a == k) b = k - 1;  // no tie across the boundary: everything discarded is forced
  const MatrixXd U = choice.tied;
  choice.forced = U.rightCols(n_y - 1 - b);
  choice.tied = U.middleCols(a, b - a + 1);
  choice.choose = static_cast<int>(b - k + 1);
  return choice;
}

LowRankChoice whole_choice(const MatrixXd& E_d, const MatrixXd& C, int n_r) {
  const Index k = C.rows() - n_r;
  Eigen::JacobiSVD<MatrixXd> svd(E_d, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Index r = std::min<Index>(k, svd.singularValues().size());
  LowRankChoice choice;
  choice.truncated_whole = svd.matrixU().leftCols(r) * svd.singularValues().head(r).asDiagonal() *
                           svd.matrixV().leftCols(r).transpose();
  MatrixXd U;
  full_left_svd(C * choice.truncated_whole, U, choice.singular_values);
  const double scale = std::max((C * E_d).norm(), 1e-300);
  Index null_dim = 0;
  for (Index j = 0; j < U.cols(); ++j)
    if (choice.singular_values(j) <= 1e-9 * scale) ++null_dim;
  null_dim = std::max<Index>(null_dim, n_r);
  choice.forced = MatrixXd(C.rows(), 0);
  choice.tied = U.rightCols(null_dim);
  choice.choose = n_r;
  return choice;
}

}  // namespace

LowRankChoice low_rank_choice(const MatrixXd& E_d, const MatrixXd& C, int residual_dim,
                              LowRankMethod method, double tie_rel_tol) {
  if (residual_dim < 1 || residual_dim > C.rows())
    throw std::invalid_argument("residual dimension n_r must be in 1..n_y");
  LowRankChoice choice = method == LowRankMethod::kTruncateSeenPart
                             ? seen_part_choice(E_d, C, residual_dim, tie_rel_tol)
                             : whole_choice(E_d, C, residual_dim);
  choice.method = method;
  choice.residual_dim = residual_dim;
  return choice;
}

MatrixXd svd_order_choice(const LowRankChoice& choice) { return choice.tied.rightCols(choice.choose); }

namespace {

// [chosen, forced]: the n_r directions discarded.
MatrixXd discarded(const LowRankChoice& choice, const MatrixXd& chosen) {
  MatrixXd discard(choice.tied.rows(), choice.forced.cols() + chosen.cols());
  discard << chosen, choice.forced;
  return discard;
}

}  // namespace

MatrixXd low_rank_Q(const LowRankChoice& choice, const MatrixXd& chosen) {
  const MatrixXd discard = discarded(choice, chosen);
  MatrixXd q_columns;
  if (choice.method == LowRankMethod::kTruncateSeenPart) {
    // Q^T must be orthogonal to range(C E_d*) = U_C S_C span(kept): take U_C S_C^-1 discard.
    const MatrixXd raw = choice.output_U * choice.output_s.cwiseInverse().asDiagonal() * discard;
    q_columns = raw.householderQr().householderQ() * MatrixXd::Identity(raw.rows(), raw.cols());
  } else {
    q_columns = discard;
  }
  MatrixXd Q = q_columns.transpose();
  fix_row_signs(Q);
  return Q;
}

LowRankResult low_rank_solution(const MatrixXd& E_d, const LowRankChoice& choice, const MatrixXd& chosen) {
  LowRankResult result;
  if (choice.method == LowRankMethod::kTruncateSeenPart) {
    const MatrixXd discard = discarded(choice, chosen);
    const MatrixXd& V = choice.output_V;
    result.E_star = E_d - V * (discard * (discard.transpose() * (V.transpose() * E_d)));
  } else {
    result.E_star = choice.truncated_whole;
  }
  result.Q = low_rank_Q(choice, chosen);
  result.frobenius_error = (E_d - result.E_star).norm();
  return result;
}

double optimal_low_rank_error(const MatrixXd& E_d, const MatrixXd& C, int residual_dim) {
  const OutputSvd c = output_svd(C);
  MatrixXd U;
  VectorXd s;
  full_left_svd(c.V.transpose() * E_d, U, s);
  return s.tail(residual_dim).norm();
}

FullRankFactors full_column_rank_factors(const MatrixXd& E, double rel_tol) {
  Eigen::JacobiSVD<MatrixXd> svd(E, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const VectorXd& s = svd.singularValues();
  Index r = 0;
  while (r < s.size() && s(r) > rel_tol * s(0)) ++r;
  return {svd.matrixU().leftCols(r) * s.head(r).asDiagonal(), svd.matrixV().leftCols(r).transpose()};
}

}  // namespace chaser::flight::fdi
