// The rigidisation's law (flight/rigidise.hpp) without a plant: COMRADE 2018's linear saturation has
// the properties its stability proof asks of it (identity up to L, strictly increasing, bounded by
// M, odd) and is C1 at L; the law is -s(K_d q' + K_p (q - q_d)) about the angles it found at its
// first step; the brakes come after every rate has stayed below the threshold for the dwell, and a
// rate above it restarts the dwell.
#include "flight/rigidise.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace chaser::flight {
namespace {

constexpr double kL = 88.0, kM = 176.0;

TEST(LinearSaturation, IsTheIdentityUpToLThenStrictlyIncreasingBelowMAndOdd) {
  for (double tau = -kL; tau <= kL; tau += 0.5) EXPECT_EQ(linear_saturation(tau, kL, kM), tau);
  // Strictly increasing and below M where a double can tell: tanh(x) rounds to 1 from x ~ 19, so
  // up to L + 10 (M - L), where 1 - tanh is 4e-9 and its steps per 1 N m are 1e-9 N m.
  const double reach = kL + 10.0 * (kM - kL);
  double previous = linear_saturation(-reach, kL, kM);
  for (double tau = -reach + 1.0; tau <= reach; tau += 1.0) {
    const double s = linear_saturation(tau, kL, kM);
    EXPECT_GT(s, previous) << tau;
    EXPECT_LT(std::abs(s), kM) << tau;
    EXPECT_EQ(linear_saturation(-tau, kL, kM), -s) << tau;
    previous = s;
  }
  for (const double tau : {1e4, 1e9, -1e9}) EXPECT_LE(std::abs(linear_saturation(tau, kL, kM)), kM) << tau;
  // Far out it approaches M: (M - L) (1 - tanh(x)) ~ 2 (M - L) exp(-2x).
  EXPECT_NEAR(linear_saturation(kL + 5.0 * (kM - kL), kL, kM), kM, 2.0 * (kM - kL) * std::exp(-10.0) * 1.01);
}

// Its slope is 1 on both sides of L (tanh'(0) = 1): no kink where the saturation begins. Central
// differences of step h either side: error h^2 s''' / 6 with |s'''| <= 2 / (M - L)^2.
TEST(LinearSaturation, IsContinuouslyDifferentiableAtL) {
  const double h = 1e-3;
  const double inside = (linear_saturation(kL - h, kL, kM) - linear_saturation(kL - 3.0 * h, kL, kM)) / (2.0 * h);
  const double outside = (linear_saturation(kL + 3.0 * h, kL, kM) - linear_saturation(kL + h, kL, kM)) / (2.0 * h);
  EXPECT_NEAR(inside, 1.0, 1e-9);
  EXPECT_NEAR(outside, 1.0, 4.0 * 9.0 * h * h / ((kM - kL) * (kM - kL)) + 1e-9);  // s'' ~ -2x/(M-L)^2 at x = 2h
}

TEST(ClipSaturation, ClipsAtM) {
  EXPECT_EQ(clip_saturation(100.0, kM), 100.0);
  EXPECT_EQ(clip_saturation(300.0, kM), kM);
  EXPECT_EQ(clip_saturation(-300.0, kM), -kM);
}

model::ArmMeasurements joints_at(double q_rad, double rate_radps) {
  model::ArmMeasurements m;
  m.joints = model::kArmJoints;
  for (int j = 0; j < model::kArmJoints; ++j) {
    m.q_rad[static_cast<std::size_t>(j)] = q_rad + 0.1 * j;
    m.q_dot_radps[static_cast<std::size_t>(j)] = rate_radps;
  }
  return m;
}

RigidiseLawParams law(model::RigidiseSaturation saturation) {
  RigidiseLawParams p;
  p.rigidise.stiffness_Nm_per_rad = 100.0;
  p.rigidise.damping_Nms_per_rad = 2000.0;
  p.rigidise.linear_limit_Nm = kL;
  p.rigidise.saturation = saturation;
  p.rigidise.brake_rate_degps = 0.01;
  p.rigidise.brake_dwell_s = 1.0;
  p.torque_limit_Nm = kM;
  return p;
}

TEST(Rigidise, IsTheSaturatedPdAboutTheAnglesAtItsFirstStep) {
  for (const auto saturation : {model::RigidiseSaturation::kLinear, model::RigidiseSaturation::kClip}) {
    const RigidiseLawParams p = law(saturation);
    RigidiseState state;
    step_rigidise(p, state, joints_at(0.5, 0.0), 10.0);  // holds these angles
    EXPECT_DOUBLE_EQ(state.q_hold_rad(3), 0.8);
    // 0.01 rad off at 0.01 rad/s: 1 + 20 = 21 N m, inside L: the PD itself.
    model::ArmCommand c = step_rigidise(p, state, joints_at(0.51, 0.01), 10.001);
    for (int j = 0; j < model::kArmJoints; ++j) EXPECT_NEAR(c.torque_Nm[static_cast<std::size_t>(j)], -21.0, 1e-9);
    EXPECT_FALSE(c.engage_brakes);
    // 1 deg/s on every joint (Table 7's compliance start): 34.9 N m, and 0.1 rad/s: 200 N m, saturated.
    c = step_rigidise(p, state, joints_at(0.5, 0.1), 10.002);
    const double expected = saturation == model::RigidiseSaturation::kClip ? -kM : -linear_saturation(200.0, kL, kM);
    EXPECT_NEAR(c.torque_Nm[0], expected, 1e-9);
    EXPECT_GT(std::abs(c.torque_Nm[0]), kL);
    EXPECT_LE(std::abs(c.torque_Nm[0]), kM);
  }
}

// Joint steps of 1 ms at t = k / 1000 s: the dwell is met at the first step at least 1 s after the
// rates fell below (within a step of it, as the times are rounded).
TEST(Rigidise, BrakesOnceEveryRateStaysBelowTheThresholdForTheDwell) {
  const RigidiseLawParams p = law(model::RigidiseSaturation::kLinear);
  const double below = 0.5 * 0.01 * std::numbers::pi / 180.0, above = 2.0 * 0.01 * std::numbers::pi / 180.0;
  RigidiseState state;
  const auto time = [](int k) { return 1e-3 * k; };
  int k = 0;
  for (; k < 800; ++k) EXPECT_FALSE(step_rigidise(p, state, joints_at(0.5, below), time(k)).engage_brakes);
  step_rigidise(p, state, joints_at(0.5, above), time(k++));  // one joint step above: the dwell starts again
  const double restarted_s = time(k);
  model::ArmCommand braked;
  for (; k < 5000; ++k) {
    braked = step_rigidise(p, state, joints_at(0.5, below), time(k));
    if (braked.engage_brakes) break;
  }
  ASSERT_TRUE(braked.engage_brakes);
  EXPECT_GE(state.brakes_s - restarted_s, 1.0 - 1e-9);
  EXPECT_LE(state.brakes_s - restarted_s, 1.001 + 1e-9);
  for (const double tau : braked.torque_Nm) EXPECT_EQ(tau, 0.0);  // the drives are off
  // Braked for good, whatever the rates then.
  EXPECT_TRUE(step_rigidise(p, state, joints_at(0.5, above), time(k + 1)).engage_brakes);
}

}  // namespace
}  // namespace chaser::flight
