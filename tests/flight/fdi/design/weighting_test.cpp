#include "flight/fdi/design/weighting.hpp"

#include <gtest/gtest.h>

#include <Eigen/QR>
#include <cmath>

#include "test_matrices.hpp"

namespace chaser::flight::fdi {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using testing::random_matrix;

MatrixXd orthonormal_basis(RandomStream& rng, int n, int c) {
  const MatrixXd m = random_matrix(rng, n, c);
  return m.householderQr().householderQ() * MatrixXd::Identity(n, c);
}

// The search maximises what it is asked to: for score = |w . a|^2 over unit w in span(basis), the
// optimum is the projection of a on the span (up to sign). The final step is 1e-6 rad and the
// score is quadratic at the optimum, so the direction is found to ~1e-6.
TEST(Weighting, FindsTheBestDirection) {
  RandomStream rng(31, "weighting");
  for (const int c : {2, 3, 4}) {
    const MatrixXd basis = orthonormal_basis(rng, 5, c);
    const VectorXd a = random_matrix(rng, 5, 1);
    const auto score = [&](const MatrixXd& w) { return std::pow(w.col(0).dot(a), 2); };
    const MatrixXd chosen = choose_subspace(basis, 1, score);
    const VectorXd best = (basis * basis.transpose() * a).normalized();
    EXPECT_NEAR(std::abs(chosen.col(0).dot(best)), 1.0, 1e-9) << "c = " << c;
    EXPECT_LT((basis * basis.transpose() * chosen - chosen).norm(), 1e-14);  // inside the span
  }
}

// Choosing c - 1 directions is choosing the one left out: for a score that rewards staying away
// from a (score = -|projection of a on the chosen span|^2), the left-out direction is a's.
TEST(Weighting, FindsTheBestComplement) {
  RandomStream rng(32, "complement");
  const MatrixXd basis = orthonormal_basis(rng, 4, 3);
  const VectorXd a = basis * VectorXd(Eigen::Vector3d(0.3, -0.5, 0.8));
  const auto score = [&](const MatrixXd& w) { return -(w.transpose() * a).squaredNorm(); };
  const MatrixXd chosen = choose_subspace(basis, 2, score);
  ASSERT_EQ(chosen.cols(), 2);
  EXPECT_LT((chosen.transpose() * chosen - MatrixXd::Identity(2, 2)).norm(), 1e-14);
  EXPECT_LT((chosen.transpose() * a).norm(), 1e-5 * a.norm());
}

// Nothing to choose when p = 0 or p = c; and the search is deterministic (same answer twice).
TEST(Weighting, TrivialCasesAndDeterminism) {
  RandomStream rng(33, "trivial");
  const MatrixXd basis = orthonormal_basis(rng, 3, 3);
  const auto score = [](const MatrixXd& w) { return std::sin(7.0 * w(0, 0)) + w(1, 0); };
  EXPECT_EQ(choose_subspace(basis, 0, score).cols(), 0);
  EXPECT_EQ(choose_subspace(basis, 3, score), basis);
  EXPECT_EQ(choose_subspace(basis, 1, score), choose_subspace(basis, 1, score));
}

}  // namespace
}  // namespace chaser::flight::fdi
