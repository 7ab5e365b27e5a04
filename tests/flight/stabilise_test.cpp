// The stabilisation's law (flight/stabilise.hpp) without a plant. The composite's inertia: hub and
// arm against the floating-base mass matrix's base block (the composite-rigid-body algorithm, a
// second method), the target added by the two-body formula with the reduced mass. The law on a
// rigid body integrated apart (Euler's equations by RK4): with the right inertia the inertial
// momentum follows the linear reference to the zero-order hold's error, the couple is |H_0| / D;
// with the target's inertia 20 % off and its mass 10 % off it still brings the rate to zero.
#include "flight/stabilise.hpp"

#include <cmath>
#include <functional>

#include <gtest/gtest.h>

#include "flight/arm/arm_kinematics.hpp"
#include "control/axis_design.hpp"
#include "flight/arm/floating_base_mass_matrix.hpp"
#include "tests/flight/arm/arm_test_support.hpp"

namespace chaser::flight {
namespace {

arm::JointVector bent() {
  arm::JointVector q;
  q << 0.3, -0.7, 0.5, 1.2, -0.4, 0.8, 0.2;
  return q;
}

GraspedTarget envisat() {
  GraspedTarget t;
  t.mass_kg = 7828.0;
  t.inertia_kgm2 << 17023.3, 397.1, -2171.4, 397.1, 124825.7, 344.2, -2171.4, 344.2, 129112.2;
  t.grasp_point_target_m = Vec3(3.9, 0.0, 0.6);
  t.q_target_from_tool = Quat(Eigen::AngleAxisd(0.4, Vec3(0.2, 1.0, -0.3).normalized()));
  return t;
}

// Hub and arm alone: the mass matrix's base block is [m I, -m [c]x; m [c]x, I_O] in the hub's
// axes at the hub's origin (v's linear part first), I_O = I_c + m (|c|^2 I - c c^T).
TEST(CompositeInertia, HubAndArmAreTheMassMatrixsBaseBlock) {
  const arm::ServicerArmParams servicer = arm::servicer_arm_of(arm::testing::skewed_scene());
  GraspedTarget none = envisat();
  none.mass_kg = 0.0;
  none.inertia_kgm2.setZero();
  const CompositeInertia c = composite_inertia(servicer, bent(), none);
  const arm::ServicerMatrix H =
      arm::floating_base_mass_matrix(servicer, arm::arm_kinematics(servicer, Vec3::Zero(), Quat::Identity(), bent()));
  const double m = H(0, 0);
  const Mat3 moment = H.block<3, 3>(3, 0);  // m [c]x
  const Vec3 com(moment(2, 1) / m, moment(0, 2) / m, moment(1, 0) / m);
  const Mat3 about_com = H.block<3, 3>(3, 3) - m * (com.squaredNorm() * Mat3::Identity() - com * com.transpose());
  EXPECT_NEAR(c.mass_kg, m, 1e-12 * m);
  EXPECT_LT((c.com_hub_m - com).norm(), 1e-12);
  EXPECT_LT((c.inertia_kgm2 - about_com).norm(), 1e-10 * about_com.norm());
}

// The target adds its own inertia (turned into the hub's axes) and mu (|d|^2 I - d d^T), mu the
// reduced mass, d from the servicer's CoM to the target's, the target's CoM where the grasp puts it.
TEST(CompositeInertia, TheTargetAddsByTheReducedMass) {
  const arm::ServicerArmParams servicer = arm::servicer_arm_of(arm::testing::skewed_scene());
  const GraspedTarget target = envisat();
  GraspedTarget none = target;
  none.mass_kg = 0.0;
  none.inertia_kgm2.setZero();
  const CompositeInertia alone = composite_inertia(servicer, bent(), none);
  const CompositeInertia both = composite_inertia(servicer, bent(), target);
  const arm::ArmKinematics k = arm::arm_kinematics(servicer, Vec3::Zero(), Quat::Identity(), bent());
  const Mat3 hub_from_target = k.world_from_link[6] * target.q_target_from_tool.toRotationMatrix().transpose();
  const Vec3 target_com = k.r_tool_world_m - hub_from_target * target.grasp_point_target_m;
  // The grasp point, carried from the target's frame, is the tool point.
  EXPECT_LT((target_com + hub_from_target * target.grasp_point_target_m - k.r_tool_world_m).norm(), 1e-12);
  const double mu = alone.mass_kg * target.mass_kg / (alone.mass_kg + target.mass_kg);
  const Vec3 d = target_com - alone.com_hub_m;
  const Mat3 expected = alone.inertia_kgm2 + hub_from_target * target.inertia_kgm2 * hub_from_target.transpose() +
                        mu * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
  EXPECT_NEAR(both.mass_kg, alone.mass_kg + target.mass_kg, 1e-9);
  EXPECT_LT((both.com_hub_m - (alone.mass_kg * alone.com_hub_m + target.mass_kg * target_com) /
                                  (alone.mass_kg + target.mass_kg)).norm(), 1e-12);
  EXPECT_LT((both.inertia_kgm2 - expected).norm(), 1e-10 * expected.norm());
}

// A rigid body of inertia J (body axes) under the law's couple, held over each 0.1 s period,
// integrated by RK4 at 0.01 s. Returns the largest |H - s H_0| / |H_0| and |T| / (|H_0| / D) seen.
struct Flown {
  double max_tracking = 0.0, max_couple = 0.0, min_couple = 1e9;
  Vec3 final_rate_radps = Vec3::Zero();
};
Flown fly(const StabiliseLawParams& params, const arm::ServicerArmParams& servicer, const Mat3& inertia_true,
          const Vec3& omega0_radps, double duration_s) {
  const Mat3 inverse = inertia_true.inverse();
  Quat q = Quat(Eigen::AngleAxisd(0.7, Vec3(1.0, -0.5, 0.3).normalized()));
  Vec3 w = omega0_radps;
  StabiliseState state;
  Flown f;
  double h0 = 0.0;
  Vec3 momentum0 = Vec3::Zero();
  const auto derivative = [&](const Quat& qq, const Vec3& ww, const Vec3& torque, Quat& dq, Vec3& dw) {
    dw = inverse * (torque - ww.cross(inertia_true * ww));
    dq.coeffs() = 0.5 * (qq * Quat(0.0, ww.x(), ww.y(), ww.z())).coeffs();
  };
  constexpr double kPeriod = 0.1, kStep = 0.01;
  for (int k = 0; k * kPeriod < duration_s; ++k) {
    const double t = k * kPeriod;
    const Vec3 couple = stabilise_couple(params, servicer, state, bent(), q, w, t);
    const Vec3 momentum = q * (inertia_true * w);
    if (k == 0) momentum0 = momentum, h0 = momentum.norm();
    const double share = stabilise_reference_share(params.stabilise, state, t);
    f.max_tracking = std::max(f.max_tracking, (momentum - share * momentum0).norm() / h0);
    if (share > 0.05) {
      const double ratio = couple.norm() / (h0 / params.stabilise.duration_s);
      f.max_couple = std::max(f.max_couple, ratio);
      f.min_couple = std::min(f.min_couple, ratio);
    }
    for (int i = 0; i < 10; ++i) {  // RK4 over the period
      Quat dq1, dq2, dq3, dq4;
      Vec3 dw1, dw2, dw3, dw4;
      const auto at = [](const Quat& a, const Quat& da, double s) { return Quat(a.coeffs() + s * da.coeffs()); };
      derivative(q, w, couple, dq1, dw1);
      derivative(at(q, dq1, kStep / 2), w + kStep / 2 * dw1, couple, dq2, dw2);
      derivative(at(q, dq2, kStep / 2), w + kStep / 2 * dw2, couple, dq3, dw3);
      derivative(at(q, dq3, kStep), w + kStep * dw3, couple, dq4, dw4);
      q.coeffs() += kStep / 6 * (dq1.coeffs() + 2 * dq2.coeffs() + 2 * dq3.coeffs() + dq4.coeffs());
      q.normalize();
      w += kStep / 6 * (dw1 + 2 * dw2 + 2 * dw3 + dw4);
    }
  }
  f.final_rate_radps = w;
  return f;
}

StabiliseLawParams law(const GraspedTarget& target) {
  StabiliseLawParams p;
  p.stabilise.duration_s = 300.0;
  p.stabilise.bandwidth_radps = 0.02;
  p.target = target;
  return p;
}

// The H-infinity law's loops as comrade_capture designs them (control/composite_design.hpp): the
// angular impulse's double integrator, 60 N m of couple, the loop's 0.06 s delay, omega_B 0.02 rad/s.
StabiliseLawParams hinf_law(const GraspedTarget& target) {
  StabiliseLawParams p = law(target);
  p.stabilise.law = model::StabiliseLaw::kHinf;
  p.period_s = 0.1;
  control::AxisDesignSpec spec;
  spec.name = "H";
  spec.authority = 60.0;
  spec.delay_s = 0.0625;
  spec.bandwidth_radps = 0.02;
  spec.peak_sensitivity = 2.0;
  spec.low_frequency_gain = 1e-3;
  spec.error_scale = 2000.0;
  const control::AxisDesign design = control::design_axis(spec);
  EXPECT_TRUE(design.ok());
  for (DiscreteLoop& loop : p.hinf_loops) loop = discrete_loop(design, p.period_s);
  return p;
}

// ENVISAT's 2.5 deg/s about a non-principal axis: the momentum follows the reference to 0.2 % of
// H_0 (the hold turns the body-fixed couple by w T / 2 = 0.2 % of a period's), the couple is
// |H_0| / D within 2 %, and 200 s after the reference's end the composite is at rest (below 1e-4
// deg/s: measured 2e-6; Table 3 asks 0.5).
TEST(StabiliseLaw, WithTheRightInertiaTheMomentumFollowsTheLinearReference) {
  const arm::ServicerArmParams servicer = arm::servicer_arm_of(arm::testing::default_scene());
  const StabiliseLawParams params = law(envisat());
  const Mat3 inertia = composite_inertia(servicer, bent(), params.target).inertia_kgm2;
  const Vec3 omega0 = 2.5 * std::numbers::pi / 180.0 * Vec3(0.3, 0.9, 0.3).normalized();
  const Flown f = fly(params, servicer, inertia, omega0, 500.0);
  EXPECT_LT(f.max_tracking, 2e-3);
  EXPECT_NEAR(f.max_couple, 1.0, 0.02);
  EXPECT_NEAR(f.min_couple, 1.0, 0.02);
  EXPECT_LT(f.final_rate_radps.norm() * 180.0 / std::numbers::pi, 1e-4);
}

// The law assumes the catalogue target; the true one has 20 % more inertia about two axes, 20 %
// less about the third, 10 % less mass. The momentum it estimates is then off by up to ~20 % and
// turns with the tumble, which the feedback chases: the couple peaks at 1.84 |H_0| / D (measured;
// at bandwidth 0.05 rad/s 2.7, at 0.1 rad/s 3.4: why the bandwidth is low), the path is off the
// reference by 14 % of H_0, and 200 s after the reference's end the rate is 0.004 deg/s.
TEST(StabiliseLaw, ATargetInertiaOffBy20PercentStillEndsAtRest) {
  const arm::ServicerArmParams servicer = arm::servicer_arm_of(arm::testing::default_scene());
  const StabiliseLawParams params = law(envisat());
  GraspedTarget truth = envisat();
  truth.mass_kg *= 0.9;
  const Eigen::DiagonalMatrix<double, 3> scale(1.2, 0.8, 1.2);
  truth.inertia_kgm2 = scale * truth.inertia_kgm2 * scale;  // stays symmetric positive definite
  truth.inertia_kgm2 = 0.5 * (truth.inertia_kgm2 + truth.inertia_kgm2.transpose()).eval();
  const Mat3 inertia = composite_inertia(servicer, bent(), truth).inertia_kgm2;
  const Vec3 omega0 = 2.5 * std::numbers::pi / 180.0 * Vec3(0.3, 0.9, 0.3).normalized();
  const Flown f = fly(params, servicer, inertia, omega0, 500.0);
  EXPECT_GT(f.max_tracking, 0.05);  // it is off the reference ...
  EXPECT_LT(f.max_couple, 2.0);
  EXPECT_LT(f.final_rate_radps.norm() * 180.0 / std::numbers::pi, 0.01);  // ... and ends near rest
}

// The H-infinity law (COMRADE 2018, sec. 6.1.4) on the same rigid body: with the right inertia the
// feed-forward alone follows the reference and the loops see only the hold's error (measured: the
// momentum within 8e-5 of H_0, the couple |H_0| / D to 1e-4, 1e-6 deg/s at the end); with the
// target's inertia 20 % off the loops chase the turning error harder than the momentum law (the
// couple peaks at 2.44 |H_0| / D against 1.84) and end closer to rest (4e-4 deg/s against 4e-3).
TEST(StabiliseLaw, TheHinfLoopsDetumbleToo) {
  const arm::ServicerArmParams servicer = arm::servicer_arm_of(arm::testing::default_scene());
  const StabiliseLawParams params = hinf_law(envisat());
  const Vec3 omega0 = 2.5 * std::numbers::pi / 180.0 * Vec3(0.3, 0.9, 0.3).normalized();
  const Flown exact = fly(params, servicer, composite_inertia(servicer, bent(), params.target).inertia_kgm2, omega0, 500.0);
  EXPECT_LT(exact.max_tracking, 2e-3);
  EXPECT_NEAR(exact.max_couple, 1.0, 0.02);
  EXPECT_LT(exact.final_rate_radps.norm() * 180.0 / std::numbers::pi, 1e-4);
  GraspedTarget truth = envisat();
  truth.mass_kg *= 0.9;
  const Eigen::DiagonalMatrix<double, 3> scale(1.2, 0.8, 1.2);
  truth.inertia_kgm2 = scale * truth.inertia_kgm2 * scale;
  const Flown off = fly(params, servicer, composite_inertia(servicer, bent(), truth).inertia_kgm2, omega0, 500.0);
  EXPECT_LT(off.max_couple, 3.0);
  EXPECT_LT(off.final_rate_radps.norm() * 180.0 / std::numbers::pi, 2e-3);
}

}  // namespace
}  // namespace chaser::flight
