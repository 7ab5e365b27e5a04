#include "flight/fdi/design/unknown_input.hpp"

#include <gtest/gtest.h>

#include <Eigen/QR>
#include <Eigen/SVD>
#include <stdexcept>

#include "flight/fdi/design/cayley_hamilton_polytope.hpp"
#include "flight/fdi/design/fdi_models.hpp"
#include "flight/fdi/design/taylor_polytope.hpp"
#include "test_matrices.hpp"

namespace chaser::flight::fdi {
namespace unknown_input_test {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;
using testing::random_matrix;

constexpr double kT = 0.1;

// Singular values above 1e-9 * scale count (scale: the size of the data, so that a product that
// is zero up to rounding has rank 0).
int numerical_rank(const MatrixXd& m, double scale) {
  const VectorXd s = m.jacobiSvd().singularValues();
  int r = 0;
  while (r < s.size() && s(r) > 1e-9 * scale) ++r;
  return r;
}

// E_d of the position model (eq. 28): 2 n_x + h + 1 vertices of n_u columns each.
MatrixXd position_E_d() {
  const LinearModel m = hcw_position_model(8.532e-4, 2500.0);
  const auto ch = cayley_hamilton_polytope(m.A, m.B, kT, 0.0, kT);
  const auto ty = taylor_polytope(m.A, m.B, kT, 0.0, kT, 2);
  return unknown_input_matrix(ch.vertices, ty.vertices);
}

TEST(UnknownInput, MatrixStacksTheVerticesSideBySide) {
  const MatrixXd a = MatrixXd::Constant(2, 3, 1.0), b = MatrixXd::Constant(2, 3, 2.0);
  const MatrixXd e = unknown_input_matrix({a, b}, {b});
  ASSERT_EQ(e.cols(), 9);
  EXPECT_EQ(e.middleCols(3, 3), b);
  EXPECT_EQ(position_E_d().cols(), (12 + 3) * 3);
}

// Eq. 39 for random E_d and C (C with non-orthonormal rows, so the seen part differs from C E_d):
// rank(C E_d*) = n_y - n_r for every n_r; Q C E_d* = 0 (1e-12 relative to |C||E_d|); Q has
// orthonormal rows; the exact minimiser's error equals the analytical optimum and is never above
// the naive truncation's.
TEST(UnknownInput, ExactMinimiserMeetsTheRankConditionAndBeatsNaiveTruncation) {
  RandomStream rng(21, "lowrank");
  for (int trial = 0; trial < 10; ++trial) {
    const MatrixXd E_d = random_matrix(rng, 6, 45);
    const MatrixXd C = random_matrix(rng, 3, 6);
    for (int n_r = 1; n_r <= 3; ++n_r) {
      const LowRankChoice exact = low_rank_choice(E_d, C, n_r, LowRankMethod::kTruncateSeenPart);
      const LowRankResult r = low_rank_solution(E_d, exact, svd_order_choice(exact));
      const double scale = C.norm() * E_d.norm();
      EXPECT_EQ(numerical_rank(C * r.E_star, scale), 3 - n_r) << "n_r = " << n_r;
      EXPECT_LT((r.Q * C * r.E_star).norm(), 1e-12 * scale);
      EXPECT_LT((r.Q * r.Q.transpose() - MatrixXd::Identity(n_r, n_r)).norm(), 1e-14);
      EXPECT_NEAR(r.frobenius_error, optimal_low_rank_error(E_d, C, n_r), 1e-12 * E_d.norm());
      const LowRankChoice naive = low_rank_choice(E_d, C, n_r, LowRankMethod::kTruncateWhole);
      const LowRankResult rn = low_rank_solution(E_d, naive, svd_order_choice(naive));
      EXPECT_LE(numerical_rank(C * rn.E_star, scale), 3 - n_r);
      EXPECT_LT((rn.Q * C * rn.E_star).norm(), 1e-12 * scale);
      EXPECT_LE(r.frobenius_error, rn.frobenius_error) << "n_r = " << n_r;
    }
  }
}

// The exact minimiser keeps the part of E_d that C does not see: (I - C^+ C)(E_d - E_d*) = 0.
TEST(UnknownInput, ExactMinimiserKeepsTheUnseenPart) {
  RandomStream rng(22, "unseen");
  const MatrixXd E_d = random_matrix(rng, 6, 20);
  const MatrixXd C = random_matrix(rng, 3, 6);
  const LowRankChoice choice = low_rank_choice(E_d, C, 1, LowRankMethod::kTruncateSeenPart);
  const LowRankResult r = low_rank_solution(E_d, choice, svd_order_choice(choice));
  const MatrixXd unseen = MatrixXd::Identity(6, 6) - C.completeOrthogonalDecomposition().pseudoInverse() * C;
  EXPECT_LT((unseen * (E_d - r.E_star)).norm(), 1e-13 * E_d.norm());
}

// Position model: the three singular values of C E_d are equal to O((n T)^2) ~ 2e-9 relative (why
// Q is a choice there), the tie is detected, and every direction inside it is a minimiser to that
// order (same Frobenius error, 1e-8 relative).
TEST(UnknownInput, PositionModelSingularValuesTie) {
  const MatrixXd E_d = position_E_d();
  const MatrixXd C = hcw_position_model(8.532e-4, 2500.0).C;
  const LowRankChoice choice = low_rank_choice(E_d, C, 1, LowRankMethod::kTruncateSeenPart);
  const VectorXd& s = choice.singular_values;
  EXPECT_LT((s(0) - s(2)) / s(0), 1e-8);
  EXPECT_EQ(choice.tied.cols(), 3);
  EXPECT_EQ(choice.choose, 1);
  EXPECT_EQ(choice.forced.cols(), 0);
  const double optimum = optimal_low_rank_error(E_d, C, 1);
  for (const VectorXd& w : {VectorXd(VectorXd::Unit(3, 0)), VectorXd(Eigen::Vector3d(1, 2, -2).normalized())}) {
    const LowRankResult r = low_rank_solution(E_d, choice, choice.tied * w);
    EXPECT_NEAR(r.frobenius_error, optimum, 1e-8 * optimum);
    EXPECT_LT((r.Q * C * r.E_star).norm(), 1e-12 * E_d.norm());
  }
}

// Distinct singular values leave nothing to choose: the n_r smallest are forced.
TEST(UnknownInput, DistinctSingularValuesForceTheChoice) {
  RandomStream rng(23, "forced");
  const MatrixXd E_d = random_matrix(rng, 6, 30);
  const LowRankChoice choice = low_rank_choice(E_d, random_matrix(rng, 3, 6), 2, LowRankMethod::kTruncateSeenPart);
  EXPECT_EQ(choice.choose, 0);
  EXPECT_EQ(choice.forced.cols(), 2);
  EXPECT_THROW(low_rank_choice(E_d, random_matrix(rng, 3, 6), 4, LowRankMethod::kTruncateSeenPart),
               std::invalid_argument);
  EXPECT_THROW(low_rank_choice(E_d, MatrixXd::Zero(3, 6), 1, LowRankMethod::kTruncateSeenPart),
               std::invalid_argument);
}

// Remark 1: E = E1 E2 with E1 of full column rank equal to rank(E).
TEST(UnknownInput, FullColumnRankFactors) {
  RandomStream rng(24, "factors");
  const MatrixXd E = random_matrix(rng, 6, 2) * random_matrix(rng, 2, 40);  // rank 2
  const FullRankFactors f = full_column_rank_factors(E);
  EXPECT_EQ(f.E1.cols(), 2);
  EXPECT_EQ(numerical_rank(f.E1, E.norm()), 2);
  EXPECT_LT((f.E1 * f.E2 - E).norm(), 1e-13 * E.norm());
}

}  // namespace unknown_input_test
}  // namespace chaser::flight::fdi
