#include "core/discretize.hpp"

#include <unsupported/Eigen/MatrixFunctions>

namespace chaser {

DiscreteModel discretize_zoh(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, double period_s) {
  const Eigen::Index n = A.rows();
  const Eigen::Index m = B.cols();
  // Van Loan block matrix [[A, B], [0, 0]] T; its exponential is [[Ad, Bd], [0, I]].
  Eigen::MatrixXd block = Eigen::MatrixXd::Zero(n + m, n + m);
  block.topLeftCorner(n, n) = A * period_s;
  block.topRightCorner(n, m) = B * period_s;
  const Eigen::MatrixXd block_exp = block.exp();
  return DiscreteModel{block_exp.topLeftCorner(n, n), block_exp.topRightCorner(n, m)};
}

}  // namespace chaser
