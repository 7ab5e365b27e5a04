#include "core/discretize.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace chaser {
namespace {

// Largest entry-wise difference scaled by max(1, |expected|): a relative error for big entries and
// an absolute one for small ones.
double scaled_max_error(const Eigen::MatrixXd& actual, const Eigen::MatrixXd& expected) {
  return ((actual - expected).array().abs() / expected.array().abs().max(1.0)).maxCoeff();
}

// HCW in the MSR LVLH frame (x radial out, y along-track, z orbit normal), state [r; v], input a:
//   x'' = 3n^2 x + 2n y',  y'' = -2n x',  z'' = -n^2 z.
Eigen::MatrixXd hcw_a(double n) {
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(6, 6);
  a.topRightCorner(3, 3).setIdentity();
  a(3, 0) = 3.0 * n * n;
  a(3, 4) = 2.0 * n;
  a(4, 3) = -2.0 * n;
  a(5, 2) = -n * n;
  return a;
}

Eigen::MatrixXd hcw_b() {
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(6, 3);
  b.bottomRows(3).setIdentity();
  return b;
}

// Clohessy-Wiltshire closed-form transition matrix Phi(t) for the same frame (Clohessy and
// Wiltshire 1960, rewritten for x radial, y along-track).
Eigen::MatrixXd hcw_phi(double n, double t) {
  const double c = std::cos(n * t), s = std::sin(n * t);
  Eigen::MatrixXd p(6, 6);
  p << 4 - 3 * c, 0, 0, s / n, 2 * (1 - c) / n, 0,  //
      6 * (s - n * t), 1, 0, -2 * (1 - c) / n, (4 * s - 3 * n * t) / n, 0,  //
      0, 0, c, 0, 0, s / n,  //
      3 * n * s, 0, 0, c, 2 * s, 0,  //
      -6 * n * (1 - c), 0, 0, -2 * s, 4 * c - 3, 0,  //
      0, 0, -n * s, 0, 0, c;
  return p;
}

// x - sin(x) by its alternating Taylor series (x^3/3! - x^5/5! + ...), which avoids the
// cancellation of the direct difference at small x; 12 terms reach 1e-17 relative for |x| <= 1.5.
double x_minus_sin(double x) {
  if (std::abs(x) > 1.5) return x - std::sin(x);
  double term = x * x * x / 6.0, sum = 0.0;
  for (int k = 1; k <= 12; ++k) {
    sum += term;
    term *= -x * x / ((2.0 * k + 2.0) * (2.0 * k + 3.0));
  }
  return sum;
}

// Bd = int_0^T Phi(s) ds [0; I], integrated column by column in closed form. 1 - cos is written
// 2 sin^2(nT/2), and T - sin(nT)/n through x_minus_sin, to avoid the cancellations that would cost
// up to 8 digits at nT ~ 1e-4.
Eigen::MatrixXd hcw_bd(double n, double t) {
  const double s = std::sin(n * t);
  const double one_minus_c = 2.0 * std::pow(std::sin(0.5 * n * t), 2);
  const double t_minus_s = x_minus_sin(n * t) / n;
  Eigen::MatrixXd b(6, 3);
  b << one_minus_c / (n * n), 2 * t_minus_s / n, 0,  //
      -2 * t_minus_s / n, 4 * one_minus_c / (n * n) - 1.5 * t * t, 0,  //
      0, 0, one_minus_c / (n * n),  //
      s / n, 2 * one_minus_c / n, 0,  //
      -2 * one_minus_c / n, 4 * s / n - 3 * t, 0,  //
      0, 0, s / n;
  return b;
}

// A double integrator held-input step is exact: position gains v T + a T^2 / 2, velocity a T.
// Padé exponentials of a nilpotent matrix are exact up to round-off, hence 1e-15.
TEST(Discretize, DoubleIntegratorMatchesClosedForm) {
  const double T = 0.1;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2, 2);
  A(0, 1) = 1.0;
  const Eigen::MatrixXd B = Eigen::Vector2d(0.0, 1.0);
  const DiscreteModel d = discretize_zoh(A, B, T);
  Eigen::Matrix2d ad_expected;
  ad_expected << 1.0, T, 0.0, 1.0;
  EXPECT_LT(scaled_max_error(d.Ad, ad_expected), 1e-15);
  EXPECT_LT(scaled_max_error(d.Bd, Eigen::Vector2d(0.5 * T * T, T)), 1e-15);
}

// Scalar first-order lag: Ad = e^{-aT}, Bd = (1 - e^{-aT}) / a.
TEST(Discretize, FirstOrderLagMatchesClosedForm) {
  const double a = 2.5, T = 0.3;
  const DiscreteModel d =
      discretize_zoh(Eigen::MatrixXd::Constant(1, 1, -a), Eigen::MatrixXd::Constant(1, 1, 1.0), T);
  EXPECT_NEAR(d.Ad(0, 0), std::exp(-a * T), 1e-15);
  EXPECT_NEAR(d.Bd(0, 0), -std::expm1(-a * T) / a, 1e-15);
}

// Ad must equal the Clohessy-Wiltshire transition matrix and Bd its integral, for the MSR control
// period at Mars (nT ~ 1e-4) and for long steps (nT up to ~1.2 rad) where every term matters.
// 1e-12 scaled error: the Padé exponential is accurate to ~1e-15 of ||block||, and the closed form
// itself loses at most ~1e-13 in (4 sin - 3 nt)/n at small nt.
TEST(Discretize, HcwMatchesClohessyWiltshireTransition) {
  struct Case { double n, T; };
  for (const Case c : {Case{8.5e-4, 0.1}, Case{8.5e-4, 10.0}, Case{1.1e-3, 600.0}, Case{8.5e-4, 1400.0}}) {
    const DiscreteModel d = discretize_zoh(hcw_a(c.n), hcw_b(), c.T);
    EXPECT_LT(scaled_max_error(d.Ad, hcw_phi(c.n, c.T)), 1e-12) << "n=" << c.n << " T=" << c.T;
    EXPECT_LT(scaled_max_error(d.Bd, hcw_bd(c.n, c.T)), 1e-12) << "n=" << c.n << " T=" << c.T;
  }
}

// Two half steps compose to one full step (semigroup property of the held-input solution).
TEST(Discretize, HalfStepsComposeToFullStep) {
  const double n = 8.5e-4, T = 50.0;
  const DiscreteModel full = discretize_zoh(hcw_a(n), hcw_b(), T);
  const DiscreteModel half = discretize_zoh(hcw_a(n), hcw_b(), 0.5 * T);
  EXPECT_LT(scaled_max_error(half.Ad * half.Ad, full.Ad), 1e-13);
  EXPECT_LT(scaled_max_error(half.Ad * half.Bd + half.Bd, full.Bd), 1e-13);
}

}  // namespace
}  // namespace chaser
