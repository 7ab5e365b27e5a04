#include "flight/fdi/design/delay_discretization.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "flight/fdi/design/fdi_models.hpp"
#include "test_matrices.hpp"

namespace chaser::flight::fdi {
namespace delay_discretization_test {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using testing::random_matrix;
using testing::relative_error;

constexpr double kT = 0.1;

// eq. 22: the two pieces of the period add up to the delay-free input matrix, for every delay.
// Gamma_1 is computed as e^{A(T-delta)} int_0^delta (not as B_bar - Gamma_0), so this is a real
// check of the semigroup property; 1e-12: a few ulps of each matrix exponential.
TEST(DelayDiscretization, GammasAddUpToBBar) {
  RandomStream rng(1, "gammas");
  const MatrixXd A = random_matrix(rng, 6, 6, 3.0);
  const MatrixXd B = random_matrix(rng, 6, 3);
  const MatrixXd B_bar = discretize(A, B, kT).B_bar;
  for (int j = 0; j <= 20; ++j) {
    const double delta = kT * j / 20.0;
    EXPECT_LT(relative_error(gamma0(A, B, kT, delta) + gamma1(A, B, kT, delta), B_bar), 1e-12)
        << "delta = " << delta;
  }
  EXPECT_EQ(gamma1(A, B, kT, 0.0).norm(), 0.0);  // no delay, no previous command
  EXPECT_LT(relative_error(gamma1(A, B, kT, kT), B_bar), 1e-14);  // a whole period late
}

// Scalar x' = a x + b u: Gamma_0 = b (e^{a(T-delta)} - 1) / a, Gamma_1 = b e^{aT}(1 - e^{-a delta}) / a.
TEST(DelayDiscretization, ScalarSystemMatchesClosedForm) {
  const double a = -3.7;
  const double b = 2.5;
  const MatrixXd A = MatrixXd::Constant(1, 1, a);
  const MatrixXd B = MatrixXd::Constant(1, 1, b);
  for (const double delta : {0.0, 0.013, 0.05, 0.1}) {
    EXPECT_NEAR(gamma0(A, B, kT, delta)(0, 0), b * (std::exp(a * (kT - delta)) - 1) / a, 1e-15);
    EXPECT_NEAR(gamma1(A, B, kT, delta)(0, 0), b * (std::exp(a * kT) - std::exp(a * (kT - delta))) / a,
                1e-15);
  }
  EXPECT_NEAR(discretize(A, B, kT).A_bar(0, 0), std::exp(a * kT), 1e-15);
}

// RK4 over [0, T] for x' = A x + B u(t) with u = u_prev before delta and u_k after (eq. 19).
VectorXd integrate_delayed_step(const MatrixXd& A, const MatrixXd& B, const VectorXd& x0,
                                const VectorXd& u_prev, const VectorXd& u_k, double delta) {
  VectorXd x = x0;
  const auto piece = [&](double duration, const VectorXd& u) {
    const int steps = 2000;
    const double h = duration / steps;
    const auto f = [&](const VectorXd& s) -> VectorXd { return A * s + B * u; };
    for (int i = 0; i < steps; ++i) {
      const VectorXd k1 = f(x), k2 = f(x + 0.5 * h * k1), k3 = f(x + 0.5 * h * k2), k4 = f(x + h * k3);
      x += h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
  };
  piece(delta, u_prev);
  piece(kT - delta, u_k);
  return x;
}

// eq. 21 with the convention of eq. 19: x(k+1) = A_bar x + Gamma_0 u(k) + Gamma_1 u(k-1), checked
// against an independent RK4 integration (step 5e-5 s, error ~1e-16; tolerance 1e-11 for rounding
// over 4000 steps).
TEST(DelayDiscretization, DelayedStepMatchesIntegration) {
  RandomStream rng(2, "step");
  const MatrixXd A = random_matrix(rng, 6, 6);
  const MatrixXd B = random_matrix(rng, 6, 3);
  const VectorXd x0 = random_matrix(rng, 6, 1);
  const VectorXd u_prev = random_matrix(rng, 3, 1);
  const VectorXd u_k = random_matrix(rng, 3, 1);
  for (const double delta : {0.0, 0.017, 0.06}) {
    const VectorXd predicted = discretize(A, B, kT).A_bar * x0 + gamma0(A, B, kT, delta) * u_k +
                               gamma1(A, B, kT, delta) * u_prev;
    EXPECT_LT(relative_error(predicted, integrate_delayed_step(A, B, x0, u_prev, u_k, delta)), 1e-11);
  }
}

// For the double integrator (the attitude model at rest) the integrals are polynomials:
// B_bar = [T^2/2; T] I^-1 and Gamma_1(delta) = [T^2/2 - (T-delta)^2/2; delta] I^-1.
TEST(DelayDiscretization, DoubleIntegratorIsPolynomial) {
  const Mat3 inertia = Vec3(2000.0, 2500.0, 3000.0).asDiagonal();
  const LinearModel m = linear_attitude_model(inertia);
  const double delta = 0.03;
  MatrixXd expected(6, 3);
  expected << (kT * kT - (kT - delta) * (kT - delta)) / 2.0 * inertia.inverse(), delta * inertia.inverse();
  EXPECT_LT(relative_error(gamma1(m.A, m.B, kT, delta), expected), 1e-14);
}

}  // namespace delay_discretization_test
}  // namespace chaser::flight::fdi
