#include "flight/fdi/design/taylor_polytope.hpp"

#include <Eigen/SVD>
#include <cmath>
#include <unsupported/Eigen/MatrixFunctions>

namespace chaser::flight::fdi {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

TaylorPolytope taylor_polytope(const MatrixXd& A, const MatrixXd& B, double period_s,
                               double delta_min_s, double delta_max_s, int order) {
  TaylorPolytope p;
  p.order = order;
  p.delta_min_s = delta_min_s;
  p.delta_max_s = delta_max_s;
  MatrixXd power = (A * period_s).exp() * B;  // A^{i-1} e^{AT} B
  double factorial = 1.0;
  for (int i = 1; i <= order; ++i) {
    factorial *= i;
    p.terms.push_back(((i % 2 == 1) ? 1.0 : -1.0) / factorial * power);  // Theorem 3
    power = A * power;
  }
  for (int j = 1; j <= order + 1; ++j) {  // Phi_j: the powers p <= j-1 at delta_max
    MatrixXd vertex = MatrixXd::Zero(B.rows(), B.cols());
    for (int pw = 1; pw <= order; ++pw)
      vertex += std::pow(pw <= j - 1 ? delta_max_s : delta_min_s, pw) * p.terms[pw - 1];
    p.vertices.push_back(vertex);
  }
  return p;
}

MatrixXd taylor_gamma1(const TaylorPolytope& p, double delta_s) {
  MatrixXd sum = MatrixXd::Zero(p.terms.front().rows(), p.terms.front().cols());
  for (int i = 1; i <= p.order; ++i) sum += std::pow(delta_s, i) * p.terms[i - 1];
  return sum;
}

VectorXd taylor_weights(const TaylorPolytope& p, double delta_s) {
  const int h = p.order;
  VectorXd w(h + 2);  // w_0 = 1, w_1 .. w_h, w_{h+1} = 0
  w(0) = 1.0;
  w(h + 1) = 0.0;
  for (int pw = 1; pw <= h; ++pw) {
    const double lo = std::pow(p.delta_min_s, pw);
    const double hi = std::pow(p.delta_max_s, pw);
    w(pw) = hi > lo ? (std::pow(delta_s, pw) - lo) / (hi - lo) : 0.5;
  }
  VectorXd mu(h + 1);
  for (int j = 0; j <= h; ++j) mu(j) = w(j) - w(j + 1);  // mu_{j+1} = w_j - w_{j+1}, eq. 52
  return mu;
}

double taylor_remainder_bound(const MatrixXd& A, const MatrixXd& B, double period_s,
                              double delta_s, int order) {
  const double a = A.jacobiSvd().singularValues()(0);
  const MatrixXd eB = (A * period_s).exp() * B;
  const double eB_norm = eB.jacobiSvd().singularValues()(0);
  double factorial = 1.0;
  for (int i = 2; i <= order + 1; ++i) factorial *= i;
  return eB_norm * std::pow(delta_s, order + 1) * std::pow(a, order) * std::exp(a * delta_s) /
         factorial;
}

}  // namespace chaser::flight::fdi
