#include "flight/fdi/design/residual_design.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <chrono>
#include <cmath>
#include <iostream>
#include <stdexcept>

#include "../msr_test_setup.hpp"
#include "test_matrices.hpp"

namespace chaser::flight::fdi {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using testing::random_matrix;

constexpr double kT = 0.1;

DesignInputs msr_position() {
  const model::Scenario s = testing::msr_test_scenario();
  return position_design_inputs(s, testing::msr_test_configuration(s));
}

DesignInputs msr_attitude() {
  const model::Scenario s = testing::msr_test_scenario();
  return attitude_design_inputs(s, testing::msr_test_configuration(s));
}

double miss_formula(double lambda) { return kT / std::sqrt((1 - lambda) * (1 - lambda) + kT * kT); }

void print_figures(const ResidualDesign& d, double seconds) {
  const DesignFigures& f = d.figures;
  std::cout << "[ figures  ] " << d.inputs.name << ": design " << seconds * 1e3 << " ms, Q = ["
            << d.Q << "], miss " << d.assignment.relative_miss[0] << ", cond(P) "
            << d.assignment.p_condition << "\n[ figures  ]   DC fault gain per thruster ["
            << d.inputs.residual_unit << " per unit on-time]: " << f.fault_gain_dc.transpose()
            << "\n[ figures  ]   command-through-delay gain per thruster (max): "
            << f.command_delay_gain_max.transpose() << "\n[ figures  ]   unknown input gain max "
            << f.unknown_input_gain_max << " (DC " << f.unknown_input_gain(0) << "), E_d* "
            << f.designed_input_gain_max << ", delay gain max " << f.delay_gain_max << " per "
            << (d.inputs.name == "position" ? "N" : "N m") << "\n";
}

// Built backwards so that the assignability condition holds exactly: e_1^T is a left eigenvector
// of A (first row (a, 0, 0, 0)), B has a zero first row, C measures x_1 and x_2. Then every column
// of E_d (A^{i-1} B and A^{i-1} e^{AT} B) has a zero first entry, rank(C E_d) = 1 = n_y - n_r,
// Q = e_1^T and H = e_1^T C is assignable for any lambda_1 != e^{aT}: the residual is exactly
// decoupled from the unknown input and from the delay (1e-10), and its fault transfer is
// H E_f_bar / (z - lambda_1), so the DC gain of fault i is |E_f(0, i)| (e^{aT} - 1) / a / (1 - lambda_1).
TEST(ResidualDesign, ExactDecouplingOnAConstructedSystem) {
  RandomStream rng(61, "constructed");
  const double a = -0.5;
  DesignInputs in;
  in.A = random_matrix(rng, 4, 4);
  in.A.row(0) << a, 0.0, 0.0, 0.0;
  in.B = random_matrix(rng, 4, 2);
  in.B.row(0).setZero();
  in.C = MatrixXd::Identity(2, 4);
  in.E_f = random_matrix(rng, 4, 3);
  in.fault_inputs = MatrixXd();
  in.period_s = kT;
  in.delta_max_s = kT;
  in.eigenvalues = {0.8, 0.84, 0.88, 0.92};
  const ResidualDesign d = design_residual_generator(in);
  EXPECT_LT((d.Q - MatrixXd::Identity(1, 2)).norm(), 1e-12);
  EXPECT_LT(d.low_rank_error, 1e-12 * d.E_d.norm());
  EXPECT_LT(d.assignment.relative_miss[0], 1e-12);
  EXPECT_LT(d.figures.unknown_input_gain.maxCoeff(), 1e-10);
  EXPECT_LT(d.figures.delay_gain_max, 1e-10);
  const double lambda1 = in.eigenvalues[0];
  for (int i = 0; i < 3; ++i) {
    const double expected = std::abs(in.E_f(0, i)) * (std::exp(a * kT) - 1) / a / (1 - lambda1);
    EXPECT_NEAR(d.figures.fault_gain_dc(i), expected, 1e-12 * expected) << "fault " << i;
  }
}

// MSR position model, the paper's design (delay in [0, T], h = 2, n_r = 1, the paper's
// eigenvalues): the structural facts of the analysis note, the design's defining equations, and
// the time it takes (well under a second).
TEST(ResidualDesign, MsrPositionDesign) {
  const DesignInputs in = msr_position();
  const auto start = std::chrono::steady_clock::now();
  const ResidualDesign d = design_residual_generator(in);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 1.0);
  // A three-way tie, so Q is a choice: the singular values differ only by O((n T)^2) ~ 2e-9
  // (Coriolis coupling), and any direction inside the tie is optimal to that order.
  const VectorXd& s = d.low_rank.singular_values;
  EXPECT_LT((s(0) - s(2)) / s(0), 1e-8);
  EXPECT_EQ(d.low_rank.tied.cols(), 3);
  EXPECT_NEAR(d.low_rank_error, d.low_rank_optimum, 1e-8 * d.low_rank_optimum);
  EXPECT_LT((d.Q * in.C * d.E_d_star).norm(), 1e-12 * d.E_d.norm());  // eq. 33
  EXPECT_LT((d.Q * in.C * d.E_d_factors.E1).norm(), 1e-12 * d.E_d.norm());
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(d.figures.achieved_eigenvalues[i].real(), in.eigenvalues[i], 1e-9);
    EXPECT_NEAR(d.figures.achieved_eigenvalues[i].imag(), 0.0, 1e-9);
  }
  EXPECT_NEAR(d.assignment.relative_miss[0], miss_formula(0.85), 1e-3 * miss_formula(0.85));
  EXPECT_GT(d.figures.fault_gain_dc.minCoeff(), 0.0);  // no thruster invisible
  // (A, B) is controllable, so E_d spans R^6 and holds every fault direction (analysis note).
  MatrixXd both(6, d.E_d.cols() + d.E_f_bar.cols());
  both << d.E_d, d.E_f_bar;
  EXPECT_EQ(Eigen::FullPivLU<MatrixXd>(d.E_d).setThreshold(1e-9).rank(), 6);
  EXPECT_EQ(Eigen::FullPivLU<MatrixXd>(both).setThreshold(1e-9).rank(), 6);
  EXPECT_NEAR(d.figures.delay_gain(0), 0.0, 1e-15);   // the delay acts on command differences
  print_figures(d, seconds);
}

// The chosen Q is at least as good, for the weakest thruster's DC gain, as every axis and as the
// SVD's own choice (1e-9 relative: the search stops at 1e-6 rad on a smooth maximum).
TEST(ResidualDesign, WeightingMaximisesTheWeakestThruster) {
  DesignInputs in = msr_position();
  // Thrusters along x, along y, and oblique: an axis-aligned Q is blind to some of them.
  in.E_f = in.B * (MatrixXd(3, 3) << 22, 0, 10, 0, 22, -12, 0, 0, 15).finished();
  in.fault_inputs = MatrixXd();
  const ResidualDesign d = design_residual_generator(in);
  const double chosen = d.figures.fault_gain_dc.minCoeff();
  for (int axis = 0; axis < 3; ++axis) {
    const MatrixXd q = MatrixXd::Identity(3, 3).row(axis);
    EXPECT_GE(chosen, (1 - 1e-9) * weakest_dc_fault_gain(d.A_bar, in.C, q, in.eigenvalues, d.E_f_bar));
  }
  in.weighting = WeightingChoice::kSvdOrder;
  const ResidualDesign svd = design_residual_generator(in);
  EXPECT_GE(chosen, (1 - 1e-9) * svd.figures.fault_gain_dc.minCoeff());
  EXPECT_GT(chosen, 0.1 * d.figures.fault_gain_dc.maxCoeff());
}

// MSR attitude model: distinct singular values (inertia diag(2000, 2500, 3000)), so Q is forced:
// the axis of largest inertia, where the delay's unknown input is weakest. The observer then
// stays per-axis, and each thruster's DC gain is proportional to its torque about that axis.
// The naive truncation gives the same Q (analysis note), at a larger Frobenius error.
TEST(ResidualDesign, MsrAttitudeDesign) {
  const DesignInputs in = msr_attitude();
  const auto start = std::chrono::steady_clock::now();
  const ResidualDesign d = design_residual_generator(in);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 1.0);
  EXPECT_EQ(d.low_rank.choose, 0);
  EXPECT_LT((d.Q - MatrixXd::Identity(3, 3).row(2)).norm(), 1e-12);
  EXPECT_NEAR(d.assignment.relative_miss[0], miss_formula(0.85), 1e-12);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(d.figures.achieved_eigenvalues[i].real(), in.eigenvalues[i], 1e-9);
  const VectorXd torque_z = in.fault_inputs.row(2).cwiseAbs().transpose();
  const VectorXd ratio = d.figures.fault_gain_dc.cwiseQuotient(torque_z);
  EXPECT_LT((ratio.maxCoeff() - ratio.minCoeff()) / ratio.maxCoeff(), 1e-9);
  DesignInputs naive_in = in;
  naive_in.low_rank = LowRankMethod::kTruncateWhole;
  const ResidualDesign naive = design_residual_generator(naive_in);
  EXPECT_LT((naive.Q - d.Q).norm(), 1e-6);
  EXPECT_GT(naive.low_rank_error, d.low_rank_error);
  print_figures(d, seconds);
}

// n_r = n_y: every output direction is a residual, C E_d* = 0 and each row of H = Q C misses its
// assignable subspace by the formula at its own eigenvalue (double integrator: exact, 1e-12).
TEST(ResidualDesign, FullResidualDimension) {
  DesignInputs in = msr_attitude();
  in.residual_dim = 3;
  const ResidualDesign d = design_residual_generator(in);
  EXPECT_LT((d.Q * d.Q.transpose() - MatrixXd::Identity(3, 3)).norm(), 1e-14);
  EXPECT_LT((in.C * d.E_d_star).norm(), 1e-12 * d.E_d.norm());
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(d.assignment.relative_miss[i], miss_formula(in.eigenvalues[i]), 1e-12);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(d.figures.achieved_eigenvalues[i].real(), in.eigenvalues[i], 1e-9);
}

// A smaller delay bound shrinks the unknown input: every vertex scales down, so the gain from
// E_d drops (delta_max = 0.02 s versus T).
TEST(ResidualDesign, SmallerDelayBoundShrinksTheUnknownInput) {
  DesignInputs in = msr_attitude();
  const double full = design_residual_generator(in).figures.unknown_input_gain_max;
  in.delta_max_s = 0.02;
  const double small = design_residual_generator(in).figures.unknown_input_gain_max;
  EXPECT_LT(small, 0.5 * full);
}

// The polytopes are selectable, and h sets the Taylor polytope's size: E_d has 2 n_x n_u columns
// from Cayley-Hamilton (eq. 51) and (h + 1) n_u from Taylor (eq. 52).
TEST(ResidualDesign, PolytopeSelectionSetsTheUnknownInput) {
  DesignInputs in = msr_attitude();
  in.use_taylor = false;
  EXPECT_EQ(design_residual_generator(in).E_d.cols(), 36);
  in.use_taylor = true;
  in.use_cayley_hamilton = false;
  in.taylor_order = 4;
  EXPECT_EQ(design_residual_generator(in).E_d.cols(), 15);
}

// Every problem with the inputs is reported at once.
TEST(ResidualDesign, RejectsBadInputsListingEveryProblem) {
  DesignInputs in = msr_position();
  in.eigenvalues = {0.9};
  in.delta_max_s = 0.5;
  in.residual_dim = 4;
  try {
    design_residual_generator(in);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("eigenvalues"), std::string::npos) << what;
    EXPECT_NE(what.find("delta_max_s"), std::string::npos) << what;
    EXPECT_NE(what.find("residual_dim"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace chaser::flight::fdi
