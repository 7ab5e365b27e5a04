#pragma once
// A matrix polytope: the convex combination sum_i mu_i U_i of its vertices (Fonod 2015, eqs. 24-25).
#include <Eigen/Core>
#include <vector>

namespace chaser::flight::fdi {

inline Eigen::MatrixXd convex_combination(const std::vector<Eigen::MatrixXd>& vertices,
                                          const Eigen::VectorXd& mu) {
  Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(vertices.front().rows(), vertices.front().cols());
  for (std::size_t i = 0; i < vertices.size(); ++i) sum += mu(static_cast<Eigen::Index>(i)) * vertices[i];
  return sum;
}

}  // namespace chaser::flight::fdi
