#include "flight/fdi/design/cayley_hamilton_polytope.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <unsupported/Eigen/MatrixFunctions>

#include "flight/fdi/design/delay_discretization.hpp"
#include "flight/fdi/design/fdi_models.hpp"
#include "flight/fdi/design/polytope.hpp"
#include "test_matrices.hpp"

namespace chaser::flight::fdi {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;
using testing::random_matrix;
using testing::relative_error;

constexpr double kT = 0.1;
constexpr double kN = 8.532e-4;  // [rad/s] mean motion of a 500 km Mars orbit

struct NamedSystem {
  const char* name;
  MatrixXd A;
  MatrixXd B;
};

// HCW, the double integrator, a generic random A, and a fast oscillator (40 rad/s, so that the s_i
// change sign inside [0, T] and the extremes are interior points).
std::vector<NamedSystem> systems() {
  RandomStream rng(7, "ch");
  const LinearModel hcw = hcw_position_model(kN, 2500.0);
  const LinearModel att = linear_attitude_model(Vec3(2000.0, 2500.0, 3000.0).asDiagonal());
  MatrixXd osc = MatrixXd::Zero(4, 4);
  osc(0, 1) = 40.0, osc(1, 0) = -40.0, osc(2, 3) = 25.0, osc(3, 2) = -25.0, osc(0, 2) = 3.0;
  return {{"hcw", hcw.A, hcw.B},
          {"double integrator", att.A, att.B},
          {"random", random_matrix(rng, 6, 6), random_matrix(rng, 6, 3)},
          {"oscillator", osc, random_matrix(rng, 4, 2)}};
}

MatrixXd polynomial_of(const VectorXd& c, const MatrixXd& A) {  // p(A), eq. 46
  const Index n = A.rows();
  MatrixXd p = MatrixXd::Identity(n, n);  // Horner: A^n + c_{n-1} A^{n-1} + ... + c_0 I
  for (Index k = n - 1; k >= 0; --k) p = A * p + c(k) * MatrixXd::Identity(n, n);
  return p;
}

// HCW: p(lambda) = lambda^2 (lambda^2 + n^2)^2 = lambda^6 + 2 n^2 lambda^4 + n^4 lambda^2, and every
// matrix annihilates its characteristic polynomial (Cayley-Hamilton). Tolerances: rounding on the
// scale of the largest term, ||A||^n.
TEST(CayleyHamilton, CharacteristicPolynomial) {
  const VectorXd c = characteristic_coefficients(hcw_position_model(kN, 2500.0).A);
  VectorXd expected = VectorXd::Zero(6);
  expected(2) = std::pow(kN, 4);
  expected(4) = 2 * kN * kN;
  EXPECT_LT((c - expected).norm(), 1e-20);
  EXPECT_NEAR(c(2) / expected(2), 1.0, 1e-9);
  for (const auto& s : systems()) {
    const VectorXd cs = characteristic_coefficients(s.A);
    const double scale = std::pow(s.A.norm(), s.A.rows());
    EXPECT_LT(polynomial_of(cs, s.A).norm(), 1e-12 * scale) << s.name;
  }
}

// eq. 47: e^{At} = sum_i s_i(t) A^{i-1} at sampled t, to 1e-10 relative (the s_i come from the
// companion matrix, so this is an independent check of eqs. 46-48), and the initial conditions
// s_i^{(j)}(0) = [j == i-1] via s_i(0) = [i == 1]. The unscaled companion matrix (time unit 1 s)
// is also accurate for the slow MSR models, whose ||A|| is well below one.
TEST(CayleyHamilton, FunctionsReproduceTheMatrixExponential) {
  for (const auto& s : systems()) {
    const VectorXd c = characteristic_coefficients(s.A);
    for (const double t : {0.0, 0.003, 0.05, 0.1}) {
      const VectorXd si = cayley_hamilton_functions(c, t, kT);
      MatrixXd sum = MatrixXd::Zero(s.A.rows(), s.A.cols());
      MatrixXd power = MatrixXd::Identity(s.A.rows(), s.A.cols());
      for (Index i = 0; i < si.size(); ++i) sum += si(i) * power, power = s.A * power;
      EXPECT_LT(relative_error(sum, (s.A * t).exp()), 1e-10) << s.name << " t = " << t;
    }
    EXPECT_LT((cayley_hamilton_functions(c, 0.0, kT) - VectorXd::Unit(c.size(), 0)).norm(), 1e-15);
    if (s.A.norm() < 1.5) {
      const VectorXd unscaled = cayley_hamilton_functions(c, 0.07);
      EXPECT_LT((unscaled - cayley_hamilton_functions(c, 0.07, kT)).norm(), 1e-12 * unscaled.norm()) << s.name;
    }
  }
}

// int_{t0}^{t1} s_i agrees with a Simpson rule on s_i (2000 panels: error ~1e-13 relative).
TEST(CayleyHamilton, IntegralsMatchQuadrature) {
  for (const auto& s : systems()) {
    const VectorXd c = characteristic_coefficients(s.A);
    const double t0 = 0.02, t1 = 0.1;
    const int panels = 2000;
    const double h = (t1 - t0) / panels;
    VectorXd simpson = cayley_hamilton_functions(c, t0, kT) + cayley_hamilton_functions(c, t1, kT);
    for (int j = 1; j < panels; ++j) simpson += (j % 2 ? 4.0 : 2.0) * cayley_hamilton_functions(c, t0 + j * h, kT);
    simpson *= h / 3.0;
    const VectorXd g = cayley_hamilton_integrals(c, t0, t1, kT);
    for (Index i = 0; i < c.size(); ++i)
      EXPECT_NEAR(g(i), simpson(i), 1e-10 * std::abs(simpson(i)) + 1e-22) << s.name << " i = " << i;
  }
}

// s_i^min, s_i^max are the extremes of g_i over the delay range: a brute-force scan of 4001
// delays never leaves [s_min, s_max], and comes within its own resolution of both ends
// (|g'| <= max |s_i| so a grid step of range/4000 misses an extreme by at most ~(step)^2 |s_i'|).
TEST(CayleyHamilton, ExtremesMatchBruteForce) {
  for (const auto& s : systems()) {
    const CayleyHamiltonPolytope p = cayley_hamilton_polytope(s.A, s.B, kT, 0.0, kT);
    const VectorXd& c = p.coefficients;
    VectorXd lo = VectorXd::Constant(c.size(), 1e300), hi = VectorXd::Constant(c.size(), -1e300);
    for (int j = 0; j <= 4000; ++j) {
      const VectorXd g = cayley_hamilton_integrals(c, kT - kT * j / 4000.0, kT, kT);
      lo = lo.cwiseMin(g), hi = hi.cwiseMax(g);
    }
    for (Index i = 0; i < c.size(); ++i) {
      const double tol = 1e-12 * (std::abs(p.s_max(i)) + std::abs(p.s_min(i))) + 1e-300;
      EXPECT_LE(p.s_min(i), lo(i) + tol) << s.name << " i = " << i;
      EXPECT_GE(p.s_max(i), hi(i) - tol) << s.name << " i = " << i;
      const double resolution = 1e-6 * (std::abs(hi(i)) + std::abs(lo(i)));
      EXPECT_NEAR(p.s_min(i), lo(i), resolution) << s.name << " i = " << i;
      EXPECT_NEAR(p.s_max(i), hi(i), resolution) << s.name << " i = " << i;
    }
  }
}

// Prop. 1: the polytope CONTAINS the exact Gamma_1(delta). The weights that reproduce it
// (alpha_i from g_i(delta), eq. 50) are in [0, 1] and sum to one, and sum mu_i U_i equals
// Gamma_1(delta) computed independently by Van Loan (1e-12 relative: two routes to the same
// integrals). Also for a sub-range [0.02, 0.07] of delays.
TEST(CayleyHamilton, PolytopeContainsExactGamma1) {
  for (const auto& s : systems()) {
    for (const auto& range : {std::pair{0.0, kT}, std::pair{0.02, 0.07}}) {
      const CayleyHamiltonPolytope p = cayley_hamilton_polytope(s.A, s.B, kT, range.first, range.second);
      ASSERT_EQ(p.vertices.size(), 2 * static_cast<std::size_t>(s.A.rows()));
      for (int j = 0; j <= 10; ++j) {
        const double delta = range.first + (range.second - range.first) * j / 10.0;
        const VectorXd mu = cayley_hamilton_weights(p, delta);
        EXPECT_GE(mu.minCoeff(), -1e-12) << s.name << " delta = " << delta;
        EXPECT_LE(mu.maxCoeff(), 1.0 / s.A.rows() + 1e-12);
        EXPECT_NEAR(mu.sum(), 1.0, 1e-14);
        const MatrixXd exact = gamma1(s.A, s.B, kT, delta);
        if (delta > 0.0) {
          EXPECT_LT(relative_error(convex_combination(p.vertices, mu), exact), 1e-12)
              << s.name << " delta = " << delta;
        }
      }
    }
  }
}

// App. A for HCW and the double integrator: s_i(t) ~ t^{i-1}/(i-1)! > 0 on (0, T], so each g_i
// increases with the delay: s_min = 0 and s_max = T^i / i! (up to n^2 T^2 ~ 1e-8 for HCW).
TEST(CayleyHamilton, MsrModelsHaveMonotoneIntegrals) {
  for (const auto& s : systems()) {
    if (std::string(s.name) != "hcw" && std::string(s.name) != "double integrator") continue;
    const CayleyHamiltonPolytope p = cayley_hamilton_polytope(s.A, s.B, kT, 0.0, kT);
    double factorial = 1.0;
    for (Index i = 0; i < 6; ++i) {
      factorial *= static_cast<double>(i + 1);
      EXPECT_EQ(p.s_min(i), 0.0);
      EXPECT_NEAR(p.s_max(i) * factorial / std::pow(kT, i + 1), 1.0, 1e-7) << s.name << " i = " << i;
    }
  }
}

}  // namespace
}  // namespace chaser::flight::fdi
