#include "control/mixed_sensitivity.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <Eigen/SVD>
#include <stdexcept>

#include "control/frequency_response.hpp"
#include "test_systems.hpp"

namespace chaser::control {
namespace {

using Eigen::MatrixXcd;
using Eigen::MatrixXd;

// A 2x2 plant with feedthrough (so D22 = -D_G != 0) and a dynamic 2x2 controller with feedthrough:
// both small, stable, and coupled, chosen to exercise every block of the LFT.
StateSpace coupled_plant_with_feedthrough() {
  StateSpace g;
  g.a = (MatrixXd(3, 3) << -1.0, 0.5, 0.0, 0.0, -2.0, 1.0, 0.3, 0.0, -0.5).finished();
  g.b = (MatrixXd(3, 2) << 1.0, 0.0, 0.2, 1.0, 0.0, 0.4).finished();
  g.c = (MatrixXd(2, 3) << 1.0, 0.0, 0.5, 0.0, 1.0, -0.2).finished();
  g.d = (MatrixXd(2, 2) << 0.1, 0.0, 0.05, -0.2).finished();
  return g;
}

StateSpace dynamic_controller() {
  StateSpace k;
  k.a = (MatrixXd(2, 2) << -3.0, 1.0, 0.0, -4.0).finished();
  k.b = (MatrixXd(2, 2) << 1.0, 0.5, -0.3, 2.0).finished();
  k.c = (MatrixXd(2, 2) << 2.0, 0.0, 1.0, 1.5).finished();
  k.d = (MatrixXd(2, 2) << 0.7, 0.1, -0.2, 0.4).finished();
  return k;
}

// F_l(P, K)(j omega) from the state-space LFT against [W_S S; W_KS K S; W_T T] computed from
// G(j omega) and K(j omega) directly with S = (I + G K)^-1: a second, independent route through
// the block diagram. Tolerance 1e-12 relative to the largest entry: both are a few small complex
// solves at well-conditioned points (|I + G K| and |j omega I - A| far from singular here), each
// ~10 eps.
TEST(MixedSensitivity, LftOfThePlantIsTheWeightedSensitivityStack) {
  const StateSpace g = coupled_plant_with_feedthrough();
  const StateSpace k = dynamic_controller();
  const StateSpace w_s = testing::diagonal_weight(performance_weight(2.0, 1.0, 1e-3), 2);
  const StateSpace w_ks = static_gain(0.5 * MatrixXd::Identity(2, 2));
  const StateSpace w_t = testing::diagonal_weight(performance_weight(0.5, 5.0, 2.0), 2);
  const GeneralisedPlant gp = mixed_sensitivity_plant(g, {w_s, w_ks, w_t, {}});
  ASSERT_EQ(gp.p.states(), 3 + 2 + 0 + 2);
  ASSERT_EQ(gp.p.inputs(), 4);
  ASSERT_EQ(gp.p.outputs(), 2 + 2 + 2 + 2);
  const StateSpace cl = lower_lft(gp.p, gp.n_meas, gp.n_ctrl, k);
  for (double omega : log_grid(1e-3, 1e3, 25)) {
    const MatrixXcd G = frequency_response(g, omega), K = frequency_response(k, omega);
    const MatrixXcd S = (MatrixXcd::Identity(2, 2) + G * K).inverse();
    MatrixXcd expected(6, 2);
    expected << frequency_response(w_s, omega) * S, frequency_response(w_ks, omega) * K * S,
        frequency_response(w_t, omega) * G * K * S;
    const MatrixXcd got = frequency_response(cl, omega);
    EXPECT_LE((got - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff()) << "omega " << omega;
  }
}

// With an input disturbance d' = W_d w_d at G's input (y = G (u + d')): e = S r - S G d',
// u = K e, y = T r + S G d', so the second column block of F_l is [-W_S S G W_d; -W_KS K S G W_d;
// W_T S G W_d], computed from the frequency responses as above (same tolerance, same reasons); the
// first block is unchanged. A dynamic, coupled W_d exercises its states' rows.
TEST(MixedSensitivity, InputDisturbanceAddsTheGsBlocks) {
  const StateSpace g = coupled_plant_with_feedthrough();
  const StateSpace k = dynamic_controller();
  const StateSpace w_s = testing::diagonal_weight(performance_weight(2.0, 1.0, 1e-3), 2);
  const StateSpace w_ks = static_gain(0.5 * MatrixXd::Identity(2, 2));
  const StateSpace w_t = testing::diagonal_weight(performance_weight(0.5, 5.0, 2.0), 2);
  StateSpace w_d;
  w_d.a = (MatrixXd(2, 2) << -0.5, 0.2, 0.0, -2.0).finished();
  w_d.b = (MatrixXd(2, 2) << 1.0, 0.0, 0.3, 1.0).finished();
  w_d.c = (MatrixXd(2, 2) << 0.4, 0.0, 0.1, 0.8).finished();
  w_d.d = (MatrixXd(2, 2) << 0.05, 0.0, 0.0, 0.02).finished();
  const GeneralisedPlant gp = mixed_sensitivity_plant(g, {w_s, w_ks, w_t, w_d});
  ASSERT_EQ(gp.p.states(), 3 + 2 + 0 + 2 + 2);
  ASSERT_EQ(gp.p.inputs(), 2 + 2 + 2);  // [r; w_d; u]
  ASSERT_EQ(gp.p.outputs(), 2 + 2 + 2 + 2);
  const StateSpace cl = lower_lft(gp.p, gp.n_meas, gp.n_ctrl, k);
  for (double omega : log_grid(1e-3, 1e3, 25)) {
    const MatrixXcd G = frequency_response(g, omega), K = frequency_response(k, omega);
    const MatrixXcd Wd = frequency_response(w_d, omega);
    const MatrixXcd S = (MatrixXcd::Identity(2, 2) + G * K).inverse();
    const MatrixXcd Ws = frequency_response(w_s, omega), Wks = frequency_response(w_ks, omega);
    const MatrixXcd Wt = frequency_response(w_t, omega);
    MatrixXcd expected(6, 4);
    expected << Ws * S, -Ws * S * G * Wd,  //
        Wks * K * S, -Wks * K * S * G * Wd,  //
        Wt * G * K * S, Wt * S * G * Wd;
    const MatrixXcd got = frequency_response(cl, omega);
    EXPECT_LE((got - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff()) << "omega " << omega;
  }
}

TEST(MixedSensitivity, AbsentWeightsLeaveTheirRowsOut) {
  const StateSpace g = testing::skogestad_siso_plant();
  const GeneralisedPlant gp =
      mixed_sensitivity_plant(g, {performance_weight(1.5, 10.0, 1e-4), static_gain(MatrixXd::Ones(1, 1)), {}, {}});
  EXPECT_EQ(gp.p.states(), 4);   // G's 3 + W_S's 1
  EXPECT_EQ(gp.p.outputs(), 3);  // z = [W_S e; W_KS u], then e
  EXPECT_EQ(gp.p.inputs(), 2);   // [r; u]
  EXPECT_EQ(gp.n_meas, 1);
  EXPECT_EQ(gp.n_ctrl, 1);
}

TEST(MixedSensitivity, WrongWeightSizesAreNamed) {
  const StateSpace g = testing::distillation_plant();
  try {
    mixed_sensitivity_plant(g, {performance_weight(2.0, 0.05, 1e-4), {}, {}, {}});  // SISO W_S on a 2x2 plant
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("W_S: must have 2 inputs"), std::string::npos) << e.what();
  }
  EXPECT_THROW(mixed_sensitivity_plant(g, {}), std::invalid_argument);  // no weight at all
}

}  // namespace
}  // namespace chaser::control
