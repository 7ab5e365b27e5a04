#include "flight/fdi/design/design_figures.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>

#include "test_matrices.hpp"

namespace chaser::flight::fdi {
namespace {

using Eigen::MatrixXcd;
using Eigen::MatrixXd;
using testing::random_matrix;

// R(z) = Q C (zI - A_c)^{-1}, checked against an explicit complex inverse (1e-13 relative).
TEST(DesignFigures, ResolventMatchesExplicitInverse) {
  RandomStream rng(51, "resolvent");
  const MatrixXd A_c = random_matrix(rng, 6, 6, 0.3);
  const MatrixXd QC = random_matrix(rng, 2, 6);
  const std::complex<double> z = std::polar(1.0, 0.7);
  const MatrixXcd m = z * MatrixXcd::Identity(6, 6) - A_c.cast<std::complex<double>>();
  const MatrixXcd expected = QC.cast<std::complex<double>>() * m.inverse();
  EXPECT_LT((residual_resolvent(A_c, QC, z) - expected).norm(), 1e-13 * expected.norm());
}

// A one-state observer r(k+1) = a r(k) + e f(k): |G(e^{jw})| = |e| / |e^{jw} - a|, i.e.
// |e| / (1 - a) at DC and |e| / (1 + a) at Nyquist (1e-14 relative). The delay enters through the
// command difference, so its gain is zero at DC and 2 |g| / (1 + a) at Nyquist for Gamma_1 = g.
TEST(DesignFigures, ScalarObserverClosedForms) {
  const double a = 0.9, e = 3.0, g = 0.5;
  ObserverUnderTest o;
  o.A_bar = MatrixXd::Constant(1, 1, a);
  o.C = MatrixXd::Ones(1, 1);
  o.L = MatrixXd::Zero(1, 1);
  o.Q = MatrixXd::Ones(1, 1);
  o.E_d = MatrixXd::Constant(1, 2, e);  // sigma_max of [e, e] is sqrt(2) e
  o.E_d_star = MatrixXd::Zero(1, 1);
  o.E_f_bar = MatrixXd::Constant(1, 1, e);
  o.gamma1_samples = {MatrixXd::Zero(1, 1), MatrixXd::Constant(1, 1, g)};
  o.fault_inputs = MatrixXd::Ones(1, 1);
  o.period_s = 0.1;
  const DesignFigures f = compute_design_figures(o, {5, 2});
  ASSERT_EQ(f.frequency_hz.size(), 5u);
  EXPECT_EQ(f.frequency_hz.front(), 0.0);
  EXPECT_DOUBLE_EQ(f.frequency_hz.back(), 5.0);
  EXPECT_NEAR(f.fault_gain_dc(0), e / (1 - a), 1e-14 * e / (1 - a));
  EXPECT_NEAR(f.fault_gain(4, 0), e / (1 + a), 1e-14);
  EXPECT_NEAR(f.unknown_input_gain(0), std::sqrt(2.0) * e / (1 - a), 1e-12);
  EXPECT_EQ(f.designed_input_gain_max, 0.0);
  EXPECT_NEAR(f.delay_gain(0), 0.0, 1e-15);
  EXPECT_NEAR(f.delay_gain(4), 2 * g / (1 + a), 1e-14);
  EXPECT_NEAR(f.command_delay_gain_max(0), f.delay_gain_max, 1e-15);
  ASSERT_EQ(f.achieved_eigenvalues.size(), 1u);
  EXPECT_EQ(f.achieved_eigenvalues[0], std::complex<double>(a, 0.0));
  EXPECT_NEAR(dc_fault_gains(o.A_bar, o.C, o.E_f_bar)(0), e / (1 - a), 1e-13);
}

}  // namespace
}  // namespace chaser::flight::fdi
