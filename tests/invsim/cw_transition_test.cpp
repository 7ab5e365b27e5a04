#include "invsim/cw_transition.hpp"

#include <gtest/gtest.h>

#include "core/discretize.hpp"
#include "core/rotation.hpp"

namespace chaser::invsim {
namespace {

constexpr double kN = 1.1313e-3;  // [rad/s] mean motion of a 400 km circular LEO

// Classic RK4 of eq. 2 with a held input, many small steps: an integration independent of the
// closed forms and of the matrix exponential.
Vec6 integrate_rk4(const Vec6& x0, const Vec3& u, double tau, int steps) {
  const Mat6 a = cw_state_matrix(kN);
  const Mat63 b = cw_input_matrix();
  const auto f = [&](const Vec6& x) -> Vec6 { return a * x + b * u; };
  Vec6 x = x0;
  const double h = tau / steps;
  for (int i = 0; i < steps; ++i) {
    const Vec6 k1 = f(x), k2 = f(x + 0.5 * h * k1), k3 = f(x + 0.5 * h * k2), k4 = f(x + h * k3);
    x += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  return x;
}

// Eq. 2 is the MSR-frame HCW model (core/linear_models.hpp) seen through zhou_from_msr: the same
// physics in the other Hill convention. Exact: the map is a signed permutation.
TEST(CwTransition, StateMatrixIsHcwInTheZhouFrame) {
  Mat3 p;  // zhou = p * msr
  for (int i = 0; i < 3; ++i) p.col(i) = zhou_from_msr(Vec3::Unit(i));
  Mat6 big_p = Mat6::Zero();
  big_p.topLeftCorner<3, 3>() = p;
  big_p.bottomRightCorner<3, 3>() = p;
  const Mat6 expected = big_p * hcw_state_matrix(kN) * big_p.transpose();
  EXPECT_EQ(cw_state_matrix(kN), expected);
}

// The closed forms equal the Van Loan matrix exponential (core/discretize.hpp) to 1e-9 relative
// for steps from 1 s (the IS step) to half an orbit: both are exact, so only rounding differs.
TEST(CwTransition, ClosedFormsMatchVanLoan) {
  for (const double tau : {1.0, 3.0, 100.0, 2777.0}) {
    const DiscreteModel d = discretize_zoh(cw_state_matrix(kN), cw_input_matrix(), tau);
    const Mat6 phi = cw_state_transition(kN, tau);
    const Mat63 phi_u = cw_held_input_transition(kN, tau);
    EXPECT_LT((phi - d.Ad).norm(), 1e-9 * d.Ad.norm()) << "tau " << tau;
    EXPECT_LT((phi_u - d.Bd).norm(), 1e-9 * d.Bd.norm()) << "tau " << tau;
    EXPECT_EQ(cw_impulse_transition(kN, tau), Mat63(phi.rightCols<3>()));
  }
}

// The closed forms propagate states and held inputs like a fine RK4 integration of eq. 2
// (h = 0.01 s: RK4's error ~ (n h)^4 is far below 1e-9 of the state).
TEST(CwTransition, ClosedFormsMatchRk4Integration) {
  Vec6 x0;
  x0 << 100.038, -0.0167, -0.023, -0.0076, 0.131, -0.0087;  // Zhou 2018, Table 3
  const Vec3 u(2e-3, -1e-3, 5e-3);
  for (const double tau : {1.0, 3.0, 300.0}) {
    const Vec6 expected = integrate_rk4(x0, u, tau, static_cast<int>(tau * 100.0));
    const Vec6 x = cw_state_transition(kN, tau) * x0 + cw_held_input_transition(kN, tau) * u;
    EXPECT_LT((x - expected).norm(), 1e-9 * expected.norm()) << "tau " << tau;
  }
}

// Short steps keep full accuracy in the held-input matrix (its (x, u_x) entry is a difference of
// terms ~ tau^2 that cancel to ~ tau^2 / 2): at tau = 1e-3 s it equals the double integrator's
// tau^2 / 2 to 1e-9 relative.
TEST(CwTransition, HeldInputIsDoubleIntegratorForShortSteps) {
  const double tau = 1e-3;
  const Mat63 g = cw_held_input_transition(kN, tau);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(g(i, i), 0.5 * tau * tau, 1e-9 * 0.5 * tau * tau);
    EXPECT_NEAR(g(3 + i, i), tau, 1e-9 * tau);
  }
}

}  // namespace
}  // namespace chaser::invsim
