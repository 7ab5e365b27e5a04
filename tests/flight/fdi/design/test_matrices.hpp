#pragma once
// Small helpers shared by the FDI design tests.
#include <Eigen/Core>

#include "core/random.hpp"

namespace chaser::flight::fdi::testing {

inline Eigen::MatrixXd random_matrix(RandomStream& rng, Eigen::Index rows, Eigen::Index cols,
                                     double sigma = 1.0) {
  Eigen::MatrixXd m(rows, cols);
  for (Eigen::Index j = 0; j < cols; ++j)
    for (Eigen::Index i = 0; i < rows; ++i) m(i, j) = rng.normal(0.0, sigma);
  return m;
}

// ||a - b||_F / ||b||_F (or the absolute difference when b is zero).
inline double relative_error(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  const double scale = b.norm();
  return scale > 0.0 ? (a - b).norm() / scale : (a - b).norm();
}

}  // namespace chaser::flight::fdi::testing
