#include "flight/fdi/residual_generator.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <cstdio>

#include "core/random.hpp"
#include "flight/fdi/design/residual_design.hpp"
#include "msr_test_setup.hpp"

namespace chaser::flight::fdi {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

ResidualDesign msr_design(bool position, int residual_dim = 1) {
  const model::Scenario s = testing::msr_test_scenario();
  const SchemeConfig M = testing::msr_test_configuration(s);
  DesignInputs in = position ? position_design_inputs(s, M) : attitude_design_inputs(s, M);
  in.residual_dim = residual_dim;
  return design_residual_generator(in);
}

Vec3 random_vec3(RandomStream& rng, double sigma) {
  return Vec3(rng.normal(0, sigma), rng.normal(0, sigma), rng.normal(0, sigma));
}

// The runtime parameters are the design's matrices, rearranged: A_c = A_bar - L C, Q padded with
// zero rows, and C^+ = [I; 0] for C = [I 0] (the initial estimate: position = y, rate = 0).
TEST(ResidualGenerator, ParamsAreTheDesignsMatrices) {
  const ResidualDesign d = msr_design(true);
  const ResidualGeneratorParams p = make_residual_generator(d);
  EXPECT_EQ(p.residual_dim, 1);
  EXPECT_LT((MatrixXd(p.A_c) - (d.A_bar - d.L * d.inputs.C)).norm(), 1e-15);
  EXPECT_EQ(MatrixXd(p.B_bar), d.B_bar);
  EXPECT_EQ(MatrixXd(p.Q.topRows(1)), d.Q);
  EXPECT_TRUE(p.Q.bottomRows(2).isZero(0.0));
  Mat63 pinv = Mat63::Zero();
  pinv.topRows(3).setIdentity();
  EXPECT_LT((p.x_from_y - pinv).norm(), 1e-15);
  EXPECT_TRUE(validate(p).empty());
}

// Eq. 30 with exact model knowledge: the error e = x - x_hat obeys e(k+1) = A_c e(k) with A_c
// stable (eigenvalues 0.85..0.95), so r = Q C e vanishes after the start transient; only rounding
// remains. After 800 periods the transient (0.95^800 ~ 1e-18 of the initial rate error) is far
// below rounding, which is of order 1e-16 times the size of y; the bound 1e-13 |y|max leaves room
// for accumulation and still fails if u_c or any matrix were wrong.
TEST(ResidualGenerator, NoiseFreeLinearModelGivesZeroResidual) {
  for (bool position : {true, false}) {
    const ResidualDesign d = msr_design(position);
    const ResidualGeneratorParams p = make_residual_generator(d);
    RandomStream rng(3, "residual/noise-free");
    Vec6 x;
    x << random_vec3(rng, position ? 10.0 : 0.05), random_vec3(rng, position ? 0.02 : 1e-3);
    ResidualGeneratorState state;
    double max_late = 0.0;
    double max_y = 0.0;
    for (int k = 0; k < 1200; ++k) {
      const Vec3 u = random_vec3(rng, position ? 10.0 : 5.0);
      const Vec3 y = p.C * x;
      const Vec3 r = step_residual(p, state, y, u);
      if (k == 0) {
        EXPECT_EQ(r, Vec3::Zero()) << "x_hat(0) from y(0) gives r(0) = 0";
      }
      if (k >= 800) max_late = std::max(max_late, r.norm());
      max_y = std::max(max_y, y.norm());
      x = p.A_c * x + p.L * p.C * x + p.B_bar * u;  // A_bar x + B_bar u
    }
    EXPECT_LT(max_late, 1e-13 * std::max(max_y, 1.0)) << (position ? "position" : "attitude");
    std::printf("[ measured ] %s: max |r| after the transient %.3g, max |y| %.3g\n",
                position ? "position" : "attitude", max_late, max_y);
  }
}

// A constant additive fault f on thruster i (u = u_c + d_i f, d_i = M_F e_i or M_C e_i) gives the
// residual Q C (I - A_c)^-1 B_bar d_i f in steady state, whose magnitude is the design's DC fault
// gain (eq. 31 at z = 1) times f. After 1500 periods the slowest mode (0.95) has decayed to 1e-33.
TEST(ResidualGenerator, ConstantFaultConvergesToTheDesignDcGain) {
  const double f = 0.5;  // [-] scaled on-time
  for (bool position : {true, false}) {
    const ResidualDesign d = msr_design(position);
    const ResidualGeneratorParams p = make_residual_generator(d);
    const MatrixXd& F = d.inputs.fault_inputs;  // 3 x 8
    for (int i = 0; i < kSchemeThrusters; ++i) {
      const Vec3 d_i = F.col(i);
      Vec6 x = Vec6::Zero();
      ResidualGeneratorState state;
      Vec3 r = Vec3::Zero();
      for (int k = 0; k < 1500; ++k) {
        r = step_residual(p, state, p.C * x, Vec3::Zero());
        x = (p.A_c + p.L * p.C) * x + p.B_bar * d_i * f;
      }
      const double expected = d.figures.fault_gain_dc(i) * f;
      EXPECT_NEAR(r.norm(), expected, 1e-9 * expected) << d.inputs.name << " thruster " << i;
      const Vec3 signed_dc = p.Q * p.C * (Mat6::Identity() - p.A_c).inverse() * p.B_bar * d_i * f;
      EXPECT_LT((r - signed_dc).norm(), 1e-9 * expected);
    }
  }
}

// The fixed-size step against eq. 30 evaluated with the design's dynamic matrices on arbitrary
// (not model-consistent) y and u: same arithmetic up to operation order, so 1e-12 relative.
TEST(ResidualGenerator, MatchesDynamicSizeRecomputation) {
  const ResidualDesign d = msr_design(false);
  const ResidualGeneratorParams p = make_residual_generator(d);
  const MatrixXd& C = d.inputs.C;
  const MatrixXd A_c = d.A_bar - d.L * C;
  RandomStream rng(5, "residual/dynamic");
  ResidualGeneratorState state;
  VectorXd x_hat;
  double worst = 0.0;
  for (int k = 0; k < 300; ++k) {
    const Vec3 y = random_vec3(rng, 0.01);
    const Vec3 u = random_vec3(rng, 3.0);
    if (k == 0) {
      x_hat = VectorXd::Zero(6);
      x_hat.head(3) = y;
    }
    const VectorXd r_ref = d.Q * (VectorXd(y) - C * x_hat);
    x_hat = A_c * x_hat + d.B_bar * VectorXd(u) + d.L * VectorXd(y);
    const Vec3 r = step_residual(p, state, y, u);
    worst = std::max(worst, std::abs(r(0) - r_ref(0)) / std::max(std::abs(r_ref(0)), 1e-6));
    EXPECT_EQ(r(1), 0.0);
    EXPECT_EQ(r(2), 0.0);
  }
  EXPECT_LT(worst, 1e-12);
}

// With n_r = 3 (no decoupling, eq. 34 with nothing discarded) every residual component is used.
TEST(ResidualGenerator, FullResidualHasThreeComponents) {
  const ResidualDesign d = msr_design(true, 3);
  const ResidualGeneratorParams p = make_residual_generator(d);
  EXPECT_EQ(p.residual_dim, 3);
  ResidualGeneratorState state;
  step_residual(p, state, Vec3::Zero(), Vec3::Zero());
  const Vec3 r = step_residual(p, state, Vec3(1e-3, 2e-3, -1e-3), Vec3::Zero());
  EXPECT_GT(r.cwiseAbs().minCoeff(), 0.0);
}

TEST(ResidualGenerator, ValidateNamesTheProblems) {
  ResidualGeneratorParams p;
  p.residual_dim = 1;
  p.Q(2, 0) = 1.0;
  p.A_c(0, 0) = std::nan("");
  const std::vector<std::string> problems = validate(p);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_NE(problems[0].find("residual.Q"), std::string::npos);
  p.residual_dim = 4;
  EXPECT_NE(validate(p)[0].find("residual_dim"), std::string::npos);
}

}  // namespace
}  // namespace chaser::flight::fdi
