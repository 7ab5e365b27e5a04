#include "flight/fdi/design/taylor_polytope.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "flight/fdi/design/delay_discretization.hpp"
#include "flight/fdi/design/fdi_models.hpp"
#include "flight/fdi/design/polytope.hpp"
#include "test_matrices.hpp"

namespace chaser::flight::fdi {
namespace taylor_polytope_test {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using testing::random_matrix;
using testing::relative_error;

constexpr double kT = 0.1;

MatrixXd random_A() {
  RandomStream rng(11, "taylor");
  return random_matrix(rng, 6, 6, 4.0);  // ||A|| T ~ 1: the remainder is far above rounding
}

MatrixXd random_B() {
  RandomStream rng(12, "taylor");
  return random_matrix(rng, 6, 3);
}

// Prop. 2 as read here (eq. 52 completed with mu_{h+1} = w_h): for sampled delays the weights are
// non-negative and sum to one, and sum mu_i U^b_i IS the order-h approximation (1e-13 relative:
// the same finite sums by two routes). Several orders h and delay ranges, including delta_min > 0
// where the printed weights need w_p to decrease with p.
TEST(TaylorPolytope, ApproximationIsAConvexCombinationOfVertices) {
  const MatrixXd A = random_A();
  const MatrixXd B = random_B();
  for (const int h : {1, 2, 3, 5})
    for (const auto& range : {std::pair{0.0, kT}, std::pair{0.02, kT}, std::pair{0.05, 0.06}}) {
      const TaylorPolytope p = taylor_polytope(A, B, kT, range.first, range.second, h);
      ASSERT_EQ(p.vertices.size(), static_cast<std::size_t>(h + 1));
      for (int j = 0; j <= 20; ++j) {
        const double delta = range.first + (range.second - range.first) * j / 20.0;
        const VectorXd mu = taylor_weights(p, delta);
        EXPECT_GE(mu.minCoeff(), -1e-15) << "h = " << h << " delta = " << delta;
        EXPECT_NEAR(mu.sum(), 1.0, 1e-15);
        const MatrixXd approx = taylor_gamma1(p, delta);
        EXPECT_LT((convex_combination(p.vertices, mu) - approx).norm(), 1e-13 * p.vertices.back().norm())
            << "h = " << h << " delta = " << delta;
      }
    }
}

// The vertices are the approximation at the range ends: U^b_1 = Gamma_1^b(delta_min) and
// U^b_{h+1} = Gamma_1^b(delta_max); with delta_min = 0, U^b_1 = 0.
TEST(TaylorPolytope, EndVerticesAreTheApproximationAtTheEnds) {
  const TaylorPolytope p = taylor_polytope(random_A(), random_B(), kT, 0.0, kT, 3);
  EXPECT_EQ(p.vertices.front().norm(), 0.0);
  EXPECT_LT(relative_error(p.vertices.back(), taylor_gamma1(p, kT)), 1e-15);
}

// Theorem 3: the series converges to the exact Gamma_1; the order-h error stays below the stated
// remainder bound and falls like delta^{h+1} (halving delta divides it by ~2^{h+1}; 10 % slack
// for the next-order term at delta = 0.0125 with ||A|| delta ~ 0.1).
TEST(TaylorPolytope, ErrorIsBelowTheRemainderBoundAndOfOrderHPlusOne) {
  const MatrixXd A = random_A();
  const MatrixXd B = random_B();
  for (const int h : {1, 2, 3}) {
    const TaylorPolytope p = taylor_polytope(A, B, kT, 0.0, kT, h);
    for (const double delta : {0.0125, 0.025, 0.05, 0.1}) {
      const MatrixXd error = gamma1(A, B, kT, delta) - taylor_gamma1(p, delta);
      const double spectral = error.jacobiSvd().singularValues()(0);
      EXPECT_LE(spectral, taylor_remainder_bound(A, B, kT, delta, h)) << "h = " << h;
    }
    const double e1 = (gamma1(A, B, kT, 0.0125) - taylor_gamma1(p, 0.0125)).norm();
    const double e2 = (gamma1(A, B, kT, 0.00625) - taylor_gamma1(p, 0.00625)).norm();
    EXPECT_NEAR(e1 / e2 / std::pow(2.0, h + 1), 1.0, 0.1) << "h = " << h;
  }
  const TaylorPolytope high = taylor_polytope(A, B, kT, 0.0, kT, 25);
  EXPECT_LT(relative_error(taylor_gamma1(high, 0.1), gamma1(A, B, kT, 0.1)), 1e-13);
}

// For the attitude model at rest A^2 = 0, so the order-2 expansion is exact: the Taylor polytope
// contains the exact Gamma_1 (1e-14 relative).
TEST(TaylorPolytope, ExactForTheDoubleIntegratorAtOrderTwo) {
  const LinearModel m = linear_attitude_model(Vec3(2000.0, 2500.0, 3000.0).asDiagonal());
  const TaylorPolytope p = taylor_polytope(m.A, m.B, kT, 0.0, kT, 2);
  for (const double delta : {0.01, 0.05, 0.1})
    EXPECT_LT(relative_error(taylor_gamma1(p, delta), gamma1(m.A, m.B, kT, delta)), 1e-14);
  EXPECT_EQ(taylor_remainder_bound(MatrixXd::Zero(6, 6), m.B, kT, 0.1, 2), 0.0);
}

}  // namespace taylor_polytope_test
}  // namespace chaser::flight::fdi
