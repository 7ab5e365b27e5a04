#include "model/positive_span.hpp"

#include <gtest/gtest.h>

#include <Eigen/QR>
#include <cmath>
#include <limits>

#include "core/random.hpp"

namespace chaser::model {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

MatrixXd random_gaussian(RandomStream& rng, int rows, int cols) {
  MatrixXd m(rows, cols);
  for (int j = 0; j < cols; ++j)
    for (int i = 0; i < rows; ++i) m(i, j) = rng.normal();
  return m;
}

// The certificate positive_span returns is a proof either way: a lambda >= 1 with M lambda = 0 and
// rank k proves spanning; a unit d with d . m_j <= tol |m_j| for every column proves failure (no
// non-negative combination has a positive component along d). Checking it here verifies the
// answer independently of how it was found.
void expect_certificate_holds(const MatrixXd& m, const PositiveSpanResult& r) {
  const double tol = 1e-8;
  if (r.spans) {
    EXPECT_EQ(r.rank, m.rows());
    ASSERT_EQ(r.null_combination.size(), m.cols());
    EXPECT_GE(r.null_combination.minCoeff(), 1.0 - 1e-12);
    const double scale = m.colwise().norm().maxCoeff() * r.null_combination.sum();
    EXPECT_LE((m * r.null_combination).norm(), tol * scale);
  } else {
    ASSERT_EQ(r.blocked_direction.size(), m.rows());
    EXPECT_NEAR(r.blocked_direction.norm(), 1.0, 1e-12);
    for (int j = 0; j < m.cols(); ++j)
      EXPECT_LE(r.blocked_direction.dot(m.col(j)), tol * m.col(j).norm()) << "column " << j;
  }
}

// Brute force: the NNLS minimiser restricted to its support is the unconstrained least-squares
// solution on that support, so the best feasible such solution over all 2^n supports is optimal.
double brute_force_nnls_residual(const MatrixXd& a, const VectorXd& b) {
  double best = b.norm();
  const int n = static_cast<int>(a.cols());
  for (int mask = 1; mask < (1 << n); ++mask) {
    MatrixXd sub(a.rows(), 0);
    for (int j = 0; j < n; ++j) {
      if (!(mask & (1 << j))) continue;
      sub.conservativeResize(Eigen::NoChange, sub.cols() + 1);
      sub.col(sub.cols() - 1) = a.col(j);
    }
    const VectorXd z = sub.colPivHouseholderQr().solve(b);
    if (z.minCoeff() >= 0.0) best = std::min(best, (sub * z - b).norm());
  }
  return best;
}

// NNLS agrees with exhaustive search over active sets, and satisfies its optimality (KKT)
// conditions: x >= 0, gradient w = A^T (b - A x) <= 0, w_j = 0 where x_j > 0. Tolerances are a few
// hundred ulps of the O(1) problem data.
TEST(Nnls, MatchesBruteForceAndKkt) {
  RandomStream rng(3, "nnls");
  for (int trial = 0; trial < 50; ++trial) {
    const MatrixXd a = random_gaussian(rng, 6, 5);
    const VectorXd b = random_gaussian(rng, 6, 1);
    const NnlsResult r = solve_nnls(a, b);
    ASSERT_TRUE(r.converged);
    EXPECT_GE(r.x.minCoeff(), 0.0);
    EXPECT_NEAR(r.residual_norm, brute_force_nnls_residual(a, b), 1e-10);
    const VectorXd w = a.transpose() * (b - a * r.x);
    for (int j = 0; j < 5; ++j) {
      EXPECT_LE(w(j), 1e-10);
      if (r.x(j) > 0.0) {
        EXPECT_NEAR(w(j), 0.0, 1e-10);
      }
    }
  }
}

TEST(Nnls, ZeroRightHandSideGivesZero) {
  const NnlsResult r = solve_nnls(MatrixXd::Identity(3, 3), VectorXd::Zero(3));
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.x.norm(), 0.0);
}

// +-e_x, +-e_y, +-e_z: the textbook maximal positive basis of R^3.
TEST(PositiveSpan, CoordinateCrossSpans) {
  MatrixXd m(3, 6);
  m << 1, -1, 0, 0, 0, 0, 0, 0, 1, -1, 0, 0, 0, 0, 0, 0, 1, -1;
  const PositiveSpanResult r = positive_span(m);
  EXPECT_TRUE(r.spans);
  expect_certificate_holds(m, r);
}

// Without -e_z nothing can push along -z: the only blocked direction is exactly -e_z.
TEST(PositiveSpan, MissingColumnIsFoundAsBlockedDirection) {
  MatrixXd m(3, 5);
  m << 1, -1, 0, 0, 0, 0, 0, 1, -1, 0, 0, 0, 0, 0, 1;
  const PositiveSpanResult r = positive_span(m);
  EXPECT_FALSE(r.spans);
  EXPECT_EQ(r.rank, 3);  // full rank, yet not positively spanning
  expect_certificate_holds(m, r);
  EXPECT_NEAR(r.blocked_direction.z(), -1.0, 1e-12);
}

// The vertices of a regular tetrahedron are a minimal positive basis of R^3 (k + 1 vectors); any
// three of them are not.
TEST(PositiveSpan, TetrahedronIsMinimalPositiveBasis) {
  MatrixXd m(3, 4);
  m << 1, 1, -1, -1, 1, -1, 1, -1, 1, -1, -1, 1;
  const PositiveSpanResult full = positive_span(m);
  EXPECT_TRUE(full.spans);
  expect_certificate_holds(m, full);
  // By symmetry all columns carry the same weight in the null combination.
  EXPECT_NEAR(full.null_combination.maxCoeff(), 1.0, 1e-9);
  const MatrixXd three = m.leftCols(3);
  const PositiveSpanResult r = positive_span(three);
  EXPECT_FALSE(r.spans);
  expect_certificate_holds(three, r);
}

// Three vectors at 120 deg in the xy-plane positively span the plane but not R^3: rank 2, and the
// blocked direction is the plane normal.
TEST(PositiveSpan, RankDeficientSetIsRejected) {
  MatrixXd m(3, 3);
  m << 1, -0.5, -0.5, 0, std::sqrt(0.75), -std::sqrt(0.75), 0, 0, 0;
  const PositiveSpanResult r = positive_span(m);
  EXPECT_FALSE(r.spans);
  EXPECT_EQ(r.rank, 2);
  EXPECT_NEAR(std::abs(r.blocked_direction.z()), 1.0, 1e-12);
  expect_certificate_holds(m, r);
}

// Positive column scaling (different thrust levels) and an invertible row scaling (different units
// for force and torque) map the cone onto itself / a linear image: the answer must not change.
TEST(PositiveSpan, InvariantUnderScaling) {
  MatrixXd m(3, 4);
  m << 1, 1, -1, -1, 1, -1, 1, -1, 1, -1, -1, 1;
  const Eigen::Vector4d col_scale(1e-3, 1.0, 1e3, 7.0);
  const Eigen::Vector3d row_scale(1.0, 100.0, 0.01);
  const MatrixXd scaled = row_scale.asDiagonal() * m * col_scale.asDiagonal();
  const PositiveSpanResult r = positive_span(scaled);
  EXPECT_TRUE(r.spans);
  expect_certificate_holds(scaled, r);
  EXPECT_FALSE(positive_span(scaled.leftCols(3)).spans);
}

// Wendel (1962): n i.i.d. symmetric random vectors in general position in R^d all lie in some
// half-space with probability 2^-(n-1) sum_{k<d} C(n-1, k); otherwise they positively span R^d.
// For n = 8, d = 6 that is 120/128, so P(span) = 1/16. With 4000 draws the count has standard
// deviation sqrt(4000 p (1-p)) = 15.3; a 5-sigma band makes a false failure negligible while a
// test that answered wrongly on even 2 % of cases would leave it. Every answer's certificate is
// also checked.
TEST(PositiveSpan, RandomSetsFollowWendelProbability) {
  RandomStream rng(11, "wendel");
  const int trials = 4000;
  int spanning = 0;
  for (int t = 0; t < trials; ++t) {
    const MatrixXd m = random_gaussian(rng, 6, 8);
    const PositiveSpanResult r = positive_span(m);
    spanning += r.spans;
    expect_certificate_holds(m, r);
  }
  const double expected = trials / 16.0;
  EXPECT_NEAR(spanning, expected, 5.0 * std::sqrt(trials * (1.0 / 16.0) * (15.0 / 16.0)));
}

}  // namespace
}  // namespace chaser::model
