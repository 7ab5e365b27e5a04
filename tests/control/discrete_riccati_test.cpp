#include "control/discrete_riccati.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <string>
#include <vector>

// solve_dare (SLICOT's SB02OD) checked against what needs no SLICOT: the closed-form root of the
// scalar equation, the Riccati difference equation iterated to its fixed point (definite and
// indefinite R), the closed loop's eigenvalues from Eigen, and the wrapper's own input checks.

namespace chaser::control {
namespace {

using Eigen::MatrixXd;

MatrixXd riccati_step(const MatrixXd& A, const MatrixXd& B, const MatrixXd& Q, const MatrixXd& R, const MatrixXd& X) {
  const MatrixXd btxa = B.transpose() * X * A;
  const MatrixXd next = A.transpose() * X * A - btxa.transpose() * (R + B.transpose() * X * B).lu().solve(btxa) + Q;
  return 0.5 * (next + next.transpose());
}

// Iterates the difference equation from X0 until the relative change is below 1e-13; an empty
// matrix when it has not settled in 100000 steps or has left the finite numbers.
MatrixXd iterate_riccati(const MatrixXd& A, const MatrixXd& B, const MatrixXd& Q, const MatrixXd& R, MatrixXd X) {
  for (int k = 0; k < 100000; ++k) {
    const MatrixXd next = riccati_step(A, B, Q, R, X);
    if (!next.allFinite()) return {};
    const double change = (next - X).norm() / std::max(1.0, next.norm());
    X = next;
    if (change < 1e-13) return X;
  }
  return {};
}

// Sorted by real part, then imaginary part; real parts within 1e-6 count as equal, so that a
// conjugate pair (equal real parts up to rounding) sorts the same way from both sources.
std::vector<std::complex<double>> sorted(const Eigen::VectorXcd& v) {
  std::vector<std::complex<double>> s(v.data(), v.data() + v.size());
  std::sort(s.begin(), s.end(), [](const auto& a, const auto& b) {
    return std::abs(a.real() - b.real()) > 1e-6 ? a.real() < b.real() : a.imag() < b.imag();
  });
  return s;
}

TEST(DiscreteRiccati, ScalarMatchesClosedForm) {
  struct Case { double a, b, q, r; };
  for (const Case c : {Case{1.2, 1.0, 1.0, 1.0}, Case{0.5, 2.0, 3.0, 0.5}}) {
    const DareResult res = solve_dare(MatrixXd::Constant(1, 1, c.a), MatrixXd::Constant(1, 1, c.b),
                                      MatrixXd::Constant(1, 1, c.q), MatrixXd::Constant(1, 1, c.r));
    ASSERT_TRUE(res.ok) << res.message;
    // Positive root of b^2 x^2 + (r (1 - a^2) - q b^2) x - q r = 0.
    const double p = c.b * c.b, m = c.r * (1.0 - c.a * c.a) - c.q * c.b * c.b;
    const double x = (-m + std::sqrt(m * m + 4.0 * p * c.q * c.r)) / (2.0 * p);
    // 1e-12 relative: a well-conditioned 1x1 problem (rcond 1); SB02OD loses a few ulps only.
    EXPECT_NEAR(res.X(0, 0), x, 1e-12 * x) << "a=" << c.a;
    // The closed loop a - b k, k = b x a / (r + b^2 x): same 1e-12 (derived from x).
    const double cl = c.a - c.b * (c.b * x * c.a) / (c.r + c.b * c.b * x);
    EXPECT_NEAR(res.closed_loop(0).real(), cl, 1e-12);
    EXPECT_NEAR(res.closed_loop(0).imag(), 0.0, 1e-12);
  }
}

TEST(DiscreteRiccati, UnstableMimoMatchesRecursionAndClosedLoop) {
  MatrixXd A(4, 4), B(4, 2), C(2, 4);
  A << 1.0, 0.4, 0.0, -0.2,  //  eigenvalues 1.21, 0.90, 0.82 +- 0.37i
      -0.4, 1.0, 0.4, 0.1,   //
      0.2, 0.0, 1.05, 0.3,   //
      -0.1, 0.2, 0.0, 0.7;
  B << 1.0, 0.0,  //
      0.5, 0.2,   //
      0.0, 1.0,   //
      0.3, -0.4;
  C << 1.0, 0.0, 0.0, 0.5,  //
      0.0, 0.0, 1.0, 0.0;
  const MatrixXd Q = C.transpose() * C;
  MatrixXd R(2, 2);
  R << 2.0, 0.3, 0.3, 1.0;
  // Preconditions of the test itself: A unstable, (C, A) observable.
  ASSERT_GT(A.eigenvalues().cwiseAbs().maxCoeff(), 1.0);
  MatrixXd obs(8, 4);
  MatrixXd ca = C;
  for (int i = 0; i < 4; ++i, ca = ca * A) obs.middleRows(2 * i, 2) = ca;
  ASSERT_EQ(Eigen::FullPivLU<MatrixXd>(obs).rank(), 4);

  const DareResult res = solve_dare(A, B, Q, R);
  ASSERT_TRUE(res.ok) << res.message;
  const MatrixXd X = iterate_riccati(A, B, Q, R, Q);
  ASSERT_EQ(X.rows(), 4) << "recursion did not converge";
  // 1e-9 relative: the recursion stops at a 1e-13 step, so its own error is about that over
  // (1 - rho) of the closed loop (rho 0.93; measured 6e-13); SB02OD's is rounding over rcond (~0.3 here).
  EXPECT_LT((res.X - X).norm(), 1e-9 * X.norm()) << "SB02OD\n" << res.X << "\nrecursion\n" << X;
  EXPECT_LT(res.residual, 1e-12);  // the wrapper's own residual: rounding of a 4x4 equation

  const MatrixXd acl = A - B * (R + B.transpose() * res.X * B).lu().solve(B.transpose() * res.X * A);
  const Eigen::VectorXcd eig = acl.eigenvalues();
  EXPECT_LT(eig.cwiseAbs().maxCoeff(), 1.0);
  const auto want = sorted(eig), got = sorted(res.closed_loop);
  ASSERT_EQ(got.size(), want.size());
  // 1e-9: simple, well-separated eigenvalues of a 4x4 matrix formed from X (error ~1e-12).
  for (std::size_t i = 0; i < want.size(); ++i) EXPECT_LT(std::abs(got[i] - want[i]), 1e-9) << i;
}

TEST(DiscreteRiccati, IndefiniteRGameEquationMatchesRecursion) {
  // The H-infinity filter's game equation: B = [b1 b2], R = diag(r1, -g^2). A sweep put the
  // threshold between g = 4.4 (SB02OD: INFO 5, recursion unsettled) and 4.5; at g = 5 both settle,
  // and X is far (0.7 relative) from the g = infinity LQ solution, so the -g^2 term matters.
  MatrixXd A(3, 3), B(3, 2);
  A << 1.02, 0.1, 0.0,  //
      0.0, 0.95, 0.2,   //
      0.1, 0.0, 0.8;
  B << 1.0, 0.2,  //
      0.0, 0.5,   //
      0.4, 0.1;
  const MatrixXd Q = MatrixXd::Identity(3, 3);
  MatrixXd R = MatrixXd::Zero(2, 2);
  R(0, 0) = 1.0;
  R(1, 1) = -16.0;  // g = 4, below the threshold: no stabilising solution, must be refused
  const DareResult below = solve_dare(A, B, Q, R);
  EXPECT_FALSE(below.ok);
  EXPECT_FALSE(below.message.empty());
  R(1, 1) = -25.0;
  const DareResult res = solve_dare(A, B, Q, R);
  ASSERT_TRUE(res.ok) << res.message;
  const MatrixXd X = iterate_riccati(A, B, Q, R, MatrixXd::Zero(3, 3));
  ASSERT_EQ(X.rows(), 3) << "recursion did not converge";
  // 1e-8 relative: as the definite case (measured 5e-13), with a decade more for the indefinite R's
  // slower recursion near the threshold.
  EXPECT_LT((res.X - X).norm(), 1e-8 * X.norm()) << "SB02OD\n" << res.X << "\nrecursion\n" << X;
  EXPECT_LT(res.residual, 1e-10);  // the equation itself: rounding (measured ~1e-15), rcond ~0.4
  EXPECT_LT(res.closed_loop.cwiseAbs().maxCoeff(), 1.0);
}

TEST(DiscreteRiccati, NoStabilisingSolutionIsReported) {
  // a = 1 with b = 0: the mode on the unit circle cannot be moved, x = x + q has no solution.
  // SB02OD answers INFO 5 (measured): the pencil's eigenvalues lie on the unit circle.
  const DareResult res = solve_dare(MatrixXd::Ones(1, 1), MatrixXd::Zero(1, 1), MatrixXd::Ones(1, 1),
                                    MatrixXd::Ones(1, 1));
  EXPECT_FALSE(res.ok) << "X = " << res.X;
  EXPECT_FALSE(res.message.empty());
  EXPECT_NE(res.slicot_info, 0);
}

TEST(DiscreteRiccati, BadInputRefusedBeforeSlicot) {
  const MatrixXd I2 = MatrixXd::Identity(2, 2), b = MatrixXd::Ones(2, 1), r = MatrixXd::Ones(1, 1);
  MatrixXd q_asym = I2;
  q_asym(0, 1) = 0.5;
  const MatrixXd r_nan = MatrixXd::Constant(1, 1, std::numeric_limits<double>::quiet_NaN());
  struct Case { const char* name; MatrixXd A, B, Q, R; };
  const Case cases[] = {
      {"non-square A", MatrixXd::Ones(2, 3), b, I2, r},
      {"B with wrong rows", I2, MatrixXd::Ones(3, 1), I2, r},
      {"non-symmetric Q", I2, b, q_asym, r},
      {"NaN in R", I2, b, I2, r_nan},
      {"empty A", MatrixXd(0, 0), MatrixXd(0, 1), MatrixXd(0, 0), r},
  };
  for (const Case& c : cases) {
    const DareResult res = solve_dare(c.A, c.B, c.Q, c.R);
    EXPECT_FALSE(res.ok) << c.name;
    EXPECT_NE(res.message.find("solve_dare"), std::string::npos) << c.name << ": " << res.message;
    EXPECT_EQ(res.slicot_info, 0) << c.name;
  }
}

}  // namespace
}  // namespace chaser::control
