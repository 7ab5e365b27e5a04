#include "model/positive_span.hpp"

#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace chaser::model {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// Unconstrained least squares on the passive columns, the others held at zero.
VectorXd solve_on_passive(const MatrixXd& a, const VectorXd& b, const std::vector<bool>& passive) {
  std::vector<int> idx;
  for (int j = 0; j < static_cast<int>(passive.size()); ++j)
    if (passive[j]) idx.push_back(j);
  MatrixXd sub(a.rows(), static_cast<Eigen::Index>(idx.size()));
  for (std::size_t i = 0; i < idx.size(); ++i) sub.col(static_cast<Eigen::Index>(i)) = a.col(idx[i]);
  const VectorXd z_sub = sub.colPivHouseholderQr().solve(b);
  VectorXd z = VectorXd::Zero(a.cols());
  for (std::size_t i = 0; i < idx.size(); ++i) z(idx[i]) = z_sub(static_cast<Eigen::Index>(i));
  return z;
}

// Lawson-Hanson inner loop: move from x towards the passive least-squares solution, dropping
// indices that reach zero, until the passive solution is strictly positive.
void inner_loop(const MatrixXd& a, const VectorXd& b, std::vector<bool>& passive, VectorXd& x) {
  const int n = static_cast<int>(a.cols());
  for (int guard = 0; guard <= n; ++guard) {  // each pass drops at least one index
    const VectorXd z = solve_on_passive(a, b, passive);
    double alpha = std::numeric_limits<double>::infinity();
    int blocking = -1;
    for (int j = 0; j < n; ++j) {
      if (passive[j] && z(j) <= 0.0) {
        const double step = x(j) / (x(j) - z(j));
        if (step < alpha) alpha = step, blocking = j;
      }
    }
    if (blocking < 0) {
      x = z;
      return;
    }
    x += alpha * (z - x);
    x(blocking) = 0.0;
    for (int j = 0; j < n; ++j)
      if (passive[j] && x(j) <= 0.0) passive[j] = false, x(j) = 0.0;
  }
}

// Index of the largest positive entry of the gradient w among active, non-skipped indices, or -1.
int most_violating(const VectorXd& w, const std::vector<bool>& passive,
                   const std::vector<bool>& skip, double w_tol) {
  int t = -1;
  double w_max = w_tol;
  for (int j = 0; j < static_cast<int>(w.size()); ++j)
    if (!passive[j] && !skip[j] && w(j) > w_max) w_max = w(j), t = j;
  return t;
}

}  // namespace

NnlsResult solve_nnls(const MatrixXd& a, const VectorXd& b) {
  const int n = static_cast<int>(a.cols());
  const double eps = std::numeric_limits<double>::epsilon();
  const double w_tol = 10.0 * eps * std::max<double>(a.rows(), n) * a.norm() * b.norm();
  NnlsResult result;
  result.x = VectorXd::Zero(n);
  std::vector<bool> passive(n, false), skip(n, false);
  VectorXd& x = result.x;
  for (int iteration = 0; iteration < 3 * std::max(n, 1); ++iteration) {
    const VectorXd w = a.transpose() * (b - a * x);
    const int t = most_violating(w, passive, skip, w_tol);
    if (t < 0) {
      result.converged = true;
      break;
    }
    passive[t] = true;
    // Rounding can make the new variable's own least-squares value non-positive; Lawson-Hanson
    // then exclude it for this step instead of cycling on it.
    if (solve_on_passive(a, b, passive)(t) <= 0.0) {
      passive[t] = false;
      skip[t] = true;
      continue;
    }
    std::fill(skip.begin(), skip.end(), false);
    inner_loop(a, b, passive, x);
  }
  result.residual_norm = (a * x - b).norm();
  return result;
}

PositiveSpanResult positive_span(const MatrixXd& m, double tolerance) {
  const Eigen::Index k = m.rows(), n = m.cols();
  MatrixXd unit = m;
  VectorXd norms(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    norms(j) = m.col(j).norm();
    if (norms(j) > 0.0) unit.col(j) /= norms(j);
  }
  PositiveSpanResult result;
  const Eigen::JacobiSVD<MatrixXd> svd(unit, Eigen::ComputeFullU);
  const VectorXd& sv = svd.singularValues();
  const double sv_max = sv.size() > 0 ? sv(0) : 0.0;
  for (Eigen::Index i = 0; i < sv.size(); ++i) result.rank += sv_max > 0.0 && sv(i) > tolerance * sv_max;
  if (result.rank < k) {  // a left null vector: no column has any component along it
    result.blocked_direction = svd.matrixU().col(k - 1);
    return result;
  }
  VectorXd lambda = VectorXd::Ones(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    if (norms(j) == 0.0) continue;
    const NnlsResult nnls = solve_nnls(unit, -unit.col(j));
    if (nnls.residual_norm > tolerance) {
      const VectorXd residual = -unit.col(j) - unit * nnls.x;
      result.blocked_direction = residual / residual.norm();
      return result;
    }
    lambda += nnls.x;
  }
  // lambda combines the unit columns; undo the scaling so that it combines the columns of m.
  for (Eigen::Index j = 0; j < n; ++j)
    if (norms(j) > 0.0) lambda(j) /= norms(j);
  result.null_combination = lambda / lambda.minCoeff();
  result.spans = true;
  return result;
}

}  // namespace chaser::model
