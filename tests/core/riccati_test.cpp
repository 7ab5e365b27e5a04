#include "core/riccati.hpp"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <string>
#include <vector>

#include "core/discretize.hpp"
#include "core/random.hpp"

namespace chaser {
namespace {

struct System {
  std::string name;
  Eigen::MatrixXd A, B, Q, R;
};

double spectral_radius(const Eigen::MatrixXd& m) { return m.eigenvalues().cwiseAbs().maxCoeff(); }

// The second, independent method: the plain Riccati recursion from P = Q, iterated until it stops
// moving. It converges linearly (rate = squared closed-loop pole radius), so it is slow but simple.
Eigen::MatrixXd riccati_iteration(const System& s) {
  Eigen::MatrixXd P = s.Q;
  for (int k = 0; k < 2'000'000; ++k) {
    const Eigen::MatrixXd btpa = s.B.transpose() * P * s.A;
    const Eigen::MatrixXd next = s.A.transpose() * P * s.A -
                                 btpa.transpose() * (s.R + s.B.transpose() * P * s.B).ldlt().solve(btpa) + s.Q;
    const double change = (next - P).norm();
    P = 0.5 * (next + next.transpose());
    if (change <= 1e-15 * P.norm()) break;
  }
  return P;
}

// Systems of different character: a discretised double integrator (poles on the unit circle), the
// MSR HCW position model with slow weights (closed-loop poles at ~1 - 4e-3), the attitude model, an
// open-loop unstable system, and random stabilisable ones (seeded).
std::vector<System> test_systems() {
  std::vector<System> out;
  {
    Eigen::MatrixXd A(2, 2), B(2, 1);
    A << 1.0, 0.1, 0.0, 1.0;
    B << 0.005, 0.1;
    out.push_back({"double_integrator", A, B, Eigen::Vector2d(1.0, 0.5).asDiagonal().toDenseMatrix(),
                   Eigen::MatrixXd::Constant(1, 1, 2.0)});
  }
  {
    const double n = 8.5e-4, mass = 2500.0;
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(6, 6), B = Eigen::MatrixXd::Zero(6, 3);
    A.topRightCorner(3, 3).setIdentity();
    A(3, 0) = 3 * n * n, A(3, 4) = 2 * n, A(4, 3) = -2 * n, A(5, 2) = -n * n;
    B.bottomRows(3).setIdentity();
    const DiscreteModel d = discretize_zoh(A, B / mass, 0.1);
    Eigen::VectorXd q(6);
    q << 16, 16, 16, 12000, 12000, 12000;
    out.push_back({"hcw_position", d.Ad, d.Bd, q.asDiagonal().toDenseMatrix(), Eigen::MatrixXd::Identity(3, 3)});
  }
  {
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(6, 6), B = Eigen::MatrixXd::Zero(6, 3);
    A.topRightCorner(3, 3).setIdentity();
    B.bottomRows(3) = Eigen::Vector3d(2000, 2500, 3000).cwiseInverse().asDiagonal();
    const DiscreteModel d = discretize_zoh(A, B, 0.1);
    Eigen::VectorXd q(6);
    q << 3000, 3000, 3000, 1.7e5, 1.7e5, 1.7e5;
    out.push_back({"attitude", d.Ad, d.Bd, q.asDiagonal().toDenseMatrix(), Eigen::MatrixXd::Identity(3, 3)});
  }
  {
    Eigen::MatrixXd A(3, 3), B(3, 1);
    A << 1.2, 1.0, 0.0, 0.0, 0.5, 0.3, 0.1, 0.0, 1.05;
    B << 0.0, 1.0, 0.5;
    out.push_back({"unstable", A, B, Eigen::MatrixXd::Identity(3, 3), Eigen::MatrixXd::Constant(1, 1, 0.1)});
  }
  RandomStream rng(7, "tests/riccati");
  for (int i = 0; i < 3; ++i) {
    Eigen::MatrixXd A(4, 4), B(4, 2), Qh(4, 4), Rh(2, 2);
    for (Eigen::Index j = 0; j < A.size(); ++j) A.data()[j] = rng.normal(0.0, 0.6);
    for (Eigen::Index j = 0; j < B.size(); ++j) B.data()[j] = rng.normal();
    for (Eigen::Index j = 0; j < Qh.size(); ++j) Qh.data()[j] = rng.normal();
    for (Eigen::Index j = 0; j < Rh.size(); ++j) Rh.data()[j] = rng.normal();
    out.push_back({"random_" + std::to_string(i), A, B, Qh * Qh.transpose(),
                   Rh * Rh.transpose() + Eigen::MatrixXd::Identity(2, 2)});
  }
  return out;
}

// The SDA result must satisfy the DARE to round-off (1e-9 relative leaves 5 orders of margin over
// the ~1e-14 that cancellation of A'PA against P allows), and the LQR loop A - BK must be Schur
// stable: that is what makes the stabilising solution the right one among the DARE's roots.
TEST(Riccati, SolvesDareAndStabilises) {
  for (const System& s : test_systems()) {
    const LqrDesign lqr = dlqr(s.A, s.B, s.Q, s.R);
    ASSERT_TRUE(lqr.converged) << s.name;
    EXPECT_LT(dare_relative_residual(s.A, s.B, s.Q, s.R, lqr.P), 1e-9) << s.name;
    EXPECT_LT(spectral_radius(s.A - s.B * lqr.K), 1.0) << s.name;
    EXPECT_LT((lqr.P - lqr.P.transpose()).norm(), 1e-12 * lqr.P.norm()) << s.name;
    EXPECT_GE(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(lqr.P).eigenvalues().minCoeff(),
              -1e-12 * lqr.P.norm()) << s.name;
  }
}

// Doubling and plain recursion are independent routes to the same stabilising solution; they
// agree to 1e-9 relative (the recursion's own stopping error is ~1e-13 for the slowest system).
TEST(Riccati, AgreesWithPlainRiccatiIteration) {
  for (const System& s : test_systems()) {
    const DareSolution sda = solve_dare(s.A, s.B, s.Q, s.R);
    const Eigen::MatrixXd P_iter = riccati_iteration(s);
    EXPECT_LT((sda.P - P_iter).norm(), 1e-9 * P_iter.norm()) << s.name;
  }
}

// Scalar DARE p = a^2 p - a^2 b^2 p^2 / (r + b^2 p) + q reduces to the quadratic
// b^2 p^2 + (r (1 - a^2) - q b^2) p - q r = 0 whose positive root is the stabilising one.
TEST(Riccati, ScalarMatchesClosedFormRoot) {
  struct Case { double a, b, q, r; };
  for (const Case c : {Case{0.9, 1.0, 1.0, 1.0}, Case{1.0, 0.1, 2.0, 0.5}, Case{1.5, 0.3, 0.1, 3.0}}) {
    const double lin = c.r * (1 - c.a * c.a) - c.q * c.b * c.b;
    const double p = (-lin + std::sqrt(lin * lin + 4 * c.b * c.b * c.q * c.r)) / (2 * c.b * c.b);
    const auto m = [](double v) { return Eigen::MatrixXd::Constant(1, 1, v); };
    const LqrDesign lqr = dlqr(m(c.a), m(c.b), m(c.q), m(c.r));
    EXPECT_NEAR(lqr.P(0, 0), p, 1e-12 * p);
    EXPECT_NEAR(lqr.K(0, 0), c.b * p * c.a / (c.r + c.b * c.b * p), 1e-12);
  }
}

// The steady-state Kalman gain is the fixed point of the covariance recursion
// P- = A P+ A' + W, P+ = (I - L C) P-, L = P- C' (C P- C' + V)^-1 (the filter DARE's dual).
TEST(Riccati, KalmanGainIsFixedPointOfCovarianceRecursion) {
  Eigen::MatrixXd A(2, 2), C(1, 2);
  A << 1.0, 0.1, 0.0, 1.0;
  C << 1.0, 0.0;
  const Eigen::MatrixXd W = 1e-4 * Eigen::Vector2d(0.005, 0.1) * Eigen::Vector2d(0.005, 0.1).transpose() +
                            1e-12 * Eigen::MatrixXd::Identity(2, 2);
  const Eigen::MatrixXd V = Eigen::MatrixXd::Constant(1, 1, 1e-6);
  const KalmanDesign kf = steady_state_kalman(A, C, W, V);
  ASSERT_TRUE(kf.converged);
  Eigen::MatrixXd P = Eigen::MatrixXd::Identity(2, 2);
  Eigen::MatrixXd L;
  for (int k = 0; k < 1'000'000; ++k) {
    L = P * C.transpose() * (C * P * C.transpose() + V).inverse();
    const Eigen::MatrixXd Pc = (Eigen::MatrixXd::Identity(2, 2) - L * C) * P;
    const Eigen::MatrixXd next = A * Pc * A.transpose() + W;
    const double change = (next - P).norm();
    P = next;
    if (change <= 1e-15 * P.norm()) break;
  }
  EXPECT_LT((kf.P_predicted - P).norm(), 1e-8 * P.norm());
  EXPECT_LT((kf.L - L).norm(), 1e-8 * L.norm());
  EXPECT_LT(spectral_radius(A - A * kf.L * C), 1.0);  // predictor error dynamics are stable
}

}  // namespace
}  // namespace chaser
