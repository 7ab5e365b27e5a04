// The rigidisation's law (flight/rigidise.hpp) without a plant: COMRADE 2018's linear saturation has
// the properties its stability proof asks of it (identity up to L, strictly increasing, bounded by
// M, odd) and is C1 at L; the law is -s(K_d q' + K_p (q - q_d)) about the angles it found at its
// first step; the brakes come after every rate has stayed below the threshold for the dwell, and a
// rate above it restarts the dwell.
#include "flight/rigidise.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "control/joint_design.hpp"
#include "flight/arm/arm_kinematics.hpp"
#include "flight/arm/floating_base_mass_matrix.hpp"

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

// The H-infinity law's chain: the default servicer holding ENVISAT's catalogue body 1.8 m beyond the
// tool, at an arm pose away from its singularities.
RigidiseLawParams hinf_law() {
  RigidiseLawParams p;
  p.rigidise.law = model::RigidiseLaw::kHinf;
  p.rigidise.brake_dwell_s = 1e9;  // never braked: the tests watch the law alone
  p.torque_limit_Nm = kM;
  const arm::ServicerArmParams servicer = arm::servicer_arm_of(model::MultibodySceneParams{});
  Mat3 envisat;
  envisat << 17023.0, 397.0, -2171.0, 397.0, 124826.0, 344.0, -2171.0, 344.0, 129112.0;
  p.held = arm::with_payload(servicer, arm::grasped_payload(servicer, 7828.0, envisat, Vec3(-1.8, 0.3, 0.2), Quat::Identity()));
  p.joint_period_s = 1e-3;
  p.delay_s = 0.5e-3 + 1.0 / 300.0;
  return p;
}

arm::JointVector hold_pose() {
  arm::JointVector q;
  q << 0.2, 1.1, -0.3, -1.4, 0.4, 0.9, -0.2;
  return q;
}

// Each joint's loop on H*'s diagonal meets the design's margins with the exact delay (PM above 30
// deg, GM above 6 dB: the synchronisation's loops are held to the same), and is stable.
TEST(RigidiseHinf, EachJointsLoopHasItsMargins) {
  const RigidiseLawParams p = hinf_law();
  const arm::JointMatrix h_star = rigidise_joint_inertia(p, hold_pose());
  std::array<double, model::kArmJoints> diagonal{};
  for (int j = 0; j < model::kArmJoints; ++j) diagonal[static_cast<std::size_t>(j)] = h_star(j, j);
  for (const control::AxisDesignSpec& spec : control::joint_specs(p.rigidise.hinf, p.torque_limit_Nm, diagonal, p.delay_s)) {
    const control::AxisDesign design = control::design_axis(spec);
    ASSERT_TRUE(design.ok()) << spec.name;
    EXPECT_GT(design.margins.phase_margin_deg, 30.0) << spec.name;
    EXPECT_GT(20.0 * std::log10(design.margins.gain_margin_up), 6.0) << spec.name;
  }
  EXPECT_THROW(control::joint_specs(p.rigidise.hinf, p.torque_limit_Nm, {1.0, 1.0, 1.0, 0.0, 1.0, 1.0, 1.0}, p.delay_s),
               std::invalid_argument);
}

// On the linearised chain, H* q'' = tau + d, d a constant force on the hub seen by the free-floating
// joints (as the turning composite's centripetal load is; the drives' torque loop left out): from
// 1 deg/s on every joint (Table 7's compliance start) the PD comes to rest yielding d / K_p exactly
// (the closed form), the H-infinity law a hundredth of that; both within M.
struct ChainRun {
  arm::JointVector load_Nm, error_rad;  // d, and q - q_d at the end
  double final_rate_radps = 0.0, peak_torque_Nm = 0.0;
};
ChainRun fly_linear_chain(const RigidiseLawParams& p, double load_Nm, double duration_s) {
  const arm::JointMatrix h_star = rigidise_joint_inertia(p, hold_pose());
  const Eigen::LDLT<arm::JointMatrix> solve(h_star);
  // A force on the hub along its x, seen by the free-floating joints: d = -H_qb H_bb^-1 (F; 0).
  const arm::ServicerMatrix H =
      arm::floating_base_mass_matrix(p.held, arm::arm_kinematics(p.held, Vec3::Zero(), Quat::Identity(), hold_pose()));
  Eigen::Matrix<double, arm::kBaseDofs, 1> hub_force = Eigen::Matrix<double, arm::kBaseDofs, 1>::Zero();
  hub_force(0) = load_Nm;
  const arm::JointVector d = -H.bottomLeftCorner<model::kArmJoints, arm::kBaseDofs>() *
                             H.topLeftCorner<arm::kBaseDofs, arm::kBaseDofs>().ldlt().solve(hub_force);
  arm::JointVector q = hold_pose(), rate = arm::JointVector::Constant(std::numbers::pi / 180.0);
  RigidiseState state;
  ChainRun out;
  const int steps = static_cast<int>(std::lround(duration_s / p.joint_period_s));
  for (int k = 0; k < steps; ++k) {
    model::ArmMeasurements m;
    m.joints = model::kArmJoints;
    for (int j = 0; j < model::kArmJoints; ++j) {
      m.q_rad[static_cast<std::size_t>(j)] = q(j);
      m.q_dot_radps[static_cast<std::size_t>(j)] = rate(j);
    }
    // The first step holds the angles it sees: the start, q_d = hold_pose().
    const model::ArmCommand c = step_rigidise(p, state, m, k * p.joint_period_s);
    arm::JointVector tau;
    for (int j = 0; j < model::kArmJoints; ++j) tau(j) = c.torque_Nm[static_cast<std::size_t>(j)];
    out.peak_torque_Nm = std::max(out.peak_torque_Nm, tau.cwiseAbs().maxCoeff());
    const arm::JointVector acceleration = solve.solve(tau + d);  // exact for the held torque
    q += p.joint_period_s * rate + 0.5 * p.joint_period_s * p.joint_period_s * acceleration;
    rate += p.joint_period_s * acceleration;
  }
  out.load_Nm = d;
  out.error_rad = q - hold_pose();
  out.final_rate_radps = rate.cwiseAbs().maxCoeff();
  return out;
}

TEST(RigidiseHinf, HoldsTheAnglesFarCloserThanThePdWhichYieldsTheLoadOverItsStiffness) {
  const double hub_force_N = 12.0;  // the turning composite's centripetal load on the hub (docs/servicing.md)
  const ChainRun hinf = fly_linear_chain(hinf_law(), hub_force_N, 120.0);
  RigidiseLawParams pd = law(model::RigidiseSaturation::kLinear);
  pd.rigidise.stiffness_Nm_per_rad = 1000.0;
  pd.rigidise.brake_dwell_s = 1e9;
  pd.held = hinf_law().held;
  const ChainRun compliance = fly_linear_chain(pd, hub_force_N, 120.0);
  // The PD's yield: K_p (q - q_d) = d at rest, joint by joint (the largest 0.0094 rad), to 1 %: its
  // slowest mode, the composite's, decays at K_d / (2 H*) ~ 0.01 /s (measured 0.3 % left at 120 s).
  EXPECT_LT((compliance.error_rad - compliance.load_Nm / 1000.0).cwiseAbs().maxCoeff(),
            1e-2 * compliance.load_Nm.cwiseAbs().maxCoeff() / 1000.0);
  // The H-infinity loops' low-frequency gain A = 1e-3 leaves about a hundredth of it (measured
  // 1.3e-4 rad), both from 1 deg/s on every joint, at rest by 120 s and within M.
  EXPECT_LT(hinf.error_rad.cwiseAbs().maxCoeff(), 0.02 * compliance.error_rad.cwiseAbs().maxCoeff());
  EXPECT_LT(hinf.final_rate_radps, 1e-5);
  EXPECT_LT(compliance.final_rate_radps, 1e-5);
  EXPECT_LT(hinf.peak_torque_Nm, kM);
  EXPECT_LT(compliance.peak_torque_Nm, kM);
}

}  // namespace
}  // namespace chaser::flight
