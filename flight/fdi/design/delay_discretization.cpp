#include "flight/fdi/design/delay_discretization.hpp"

#include <unsupported/Eigen/MatrixFunctions>

namespace chaser::flight::fdi {

using Eigen::MatrixXd;

ExpIntegral exp_and_integral(const MatrixXd& A, const MatrixXd& B, double t) {
  const Eigen::Index n = A.rows();
  const Eigen::Index m = B.cols();
  MatrixXd block = MatrixXd::Zero(n + m, n + m);
  block.topLeftCorner(n, n) = A * t;
  block.topRightCorner(n, m) = B * t;
  const MatrixXd e = block.exp();
  return {e.topLeftCorner(n, n), e.topRightCorner(n, m)};
}

DelayFreeDiscretization discretize(const MatrixXd& A, const MatrixXd& B, double period_s) {
  ExpIntegral e = exp_and_integral(A, B, period_s);
  return {std::move(e.exp_At), std::move(e.integral_B)};
}

MatrixXd gamma0(const MatrixXd& A, const MatrixXd& B, double period_s, double delta_s) {
  return exp_and_integral(A, B, period_s - delta_s).integral_B;
}

MatrixXd gamma1(const MatrixXd& A, const MatrixXd& B, double period_s, double delta_s) {
  const MatrixXd exp_rest = exp_and_integral(A, MatrixXd::Zero(A.rows(), 0), period_s - delta_s).exp_At;
  return exp_rest * exp_and_integral(A, B, delta_s).integral_B;
}

}  // namespace chaser::flight::fdi
