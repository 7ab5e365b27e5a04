#include "invsim/inverse_step.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "invsim/cw_transition.hpp"

namespace chaser::invsim {
namespace inverse_step_test {

constexpr double kN = 1.1313e-3;  // [rad/s]

// Eq. 21 (with Q on both sides) equals an independent dense solve of the weighted least-squares
// problem min |W (x_c - Phi x - Phi_u u)|, W = sqrt(Q), by column-pivoting QR on dynamic matrices.
// Both are backward stable on a 6x3 problem of condition ~10: 1e-10 relative is ample.
TEST(InverseStep, MatchesDenseWeightedLeastSquares) {
  Vec6 w;
  w << 1.0, 2.0, 0.5, 10.0, 30.0, 5.0;
  const InverseModel m = make_inverse_model(kN, 1.0, 3, w);
  Vec6 x, xc;
  x << 100.038, -0.0167, -0.023, -0.0076, 0.131, -0.0087;
  xc << 99.7, 0.0, 0.0, -0.1, 0.0, 0.0;
  const Vec3 u = inverse_step(m, x, xc);

  const Eigen::MatrixXd sqrt_q = w.cwiseSqrt().asDiagonal();
  const Eigen::MatrixXd a = sqrt_q * cw_held_input_transition(kN, 3.0);
  const Eigen::VectorXd b = sqrt_q * (xc - cw_state_transition(kN, 3.0) * x);
  const Eigen::VectorXd u_dense = a.colPivHouseholderQr().solve(b);
  EXPECT_LT((u - u_dense).norm(), 1e-10 * u_dense.norm());
}

// The solution minimises J (eq. 20): the weighted residual is orthogonal to the columns of
// Phi_u, so any perturbation of u raises J.
TEST(InverseStep, ResidualIsWeightOrthogonalToInputColumns) {
  Vec6 w = Vec6::Ones();
  const InverseModel m = make_inverse_model(kN, 1.0, 3, w);
  Vec6 x = Vec6::Zero(), xc;
  xc << 1.0, -2.0, 0.5, 0.1, 0.0, -0.2;
  const Vec3 u = inverse_step(m, x, xc);
  const Vec6 residual = xc - m.phi * x - m.phi_u * u;
  EXPECT_LT((m.phi_u.transpose() * residual).norm(), 1e-12 * xc.norm());
  const auto cost = [&](const Vec3& v) { return (xc - m.phi * x - m.phi_u * v).squaredNorm(); };
  EXPECT_LT(cost(u), cost(u + Vec3(1e-3, 0.0, 0.0)));
  EXPECT_LT(cost(u), cost(u - Vec3(0.0, 0.0, 1e-3)));
}

// A desired state that a constant input can reach exactly is reached exactly (zero residual).
TEST(InverseStep, RecoversTheInputOfAReachableState) {
  Vec6 w;
  w << 1.0, 1.0, 1.0, 4.0, 4.0, 4.0;
  const InverseModel m = make_inverse_model(kN, 1.0, 3, w);
  Vec6 x;
  x << 50.0, 1.0, -1.0, -0.1, 0.01, 0.02;
  const Vec3 u_true(3e-3, -1e-3, 2e-3);
  const Vec6 xc = m.phi * x + m.phi_u * u_true;
  EXPECT_LT((inverse_step(m, x, xc) - u_true).norm(), 1e-12);
}

}  // namespace inverse_step_test
}  // namespace chaser::invsim
