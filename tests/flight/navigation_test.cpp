#include "flight/navigation.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "core/rotation.hpp"

namespace chaser::flight {
namespace {

constexpr TimeNs kPeriodNs = 100'000'000;  // 0.1 s

model::Scenario test_scenario() {
  model::Scenario s;
  s.navigation.position_process_noise_mps2 = 2e-5;
  s.navigation.attitude_gain = 0.05;
  s.navigation.gyro_bias_gain = 0.0005;
  s.sensors.lidar.noise_sigma_m = 0.002;
  return s;
}

// make_nav_params designs the filter from the scenario's orbit, period, mass and noise figures, and
// copies the attitude gains.
TEST(Navigation, ParamsComeFromScenario) {
  const model::Scenario s = test_scenario();
  const NavParams p = make_nav_params(s);
  const TranslationFilterParams direct =
      design_translation_filter(s.orbit.mean_motion_radps(), s.control_period_s, s.chaser.mass_kg, 2e-5, 0.002);
  EXPECT_TRUE(p.translation.design_converged);
  EXPECT_EQ(p.translation.L, direct.L);
  EXPECT_EQ(p.attitude.attitude_gain, 0.05);
  EXPECT_EQ(p.attitude.gyro_bias_gain, 0.0005);
  EXPECT_EQ(p.attitude.period_s, s.control_period_s);
}

// init_nav takes position and attitude from the first measurement (velocity and bias zero), and a
// repeated sample (same time stamp) changes nothing, so the loop may pass it to step_nav again.
TEST(Navigation, InitialisesFromFirstMeasurementAndIgnoresRepeats) {
  const NavParams p = make_nav_params(test_scenario());
  model::SensorMeasurements first;
  first.t = 5 * kPeriodNs;
  first.r_lvlh_m = Vec3(0.1, -20.0, 0.05);
  first.q_inertial_from_body = quat_from_rotation_vector(Vec3(0.1, 0.2, 1.5));
  first.omega_body_radps = Vec3(1e-3, 0.0, 8e-4);
  NavState state = init_nav(p, first);
  const NavEstimate e0 = nav_estimate(state);
  EXPECT_EQ(e0.r_lvlh_m, first.r_lvlh_m);
  EXPECT_EQ(e0.v_lvlh_mps, Vec3::Zero());
  EXPECT_TRUE(e0.q_inertial_from_body.isApprox(first.q_inertial_from_body, 1e-15));
  EXPECT_EQ(e0.omega_body_radps, first.omega_body_radps);
  const NavEstimate again = step_nav(p, state, first, Vec3(5.0, 0.0, 0.0));
  EXPECT_EQ(again.r_lvlh_m, e0.r_lvlh_m);
  EXPECT_EQ(again.v_lvlh_mps, e0.v_lvlh_mps);
  EXPECT_EQ(state.t_last, first.t);
}

// In a LIDAR gap the translation estimate is the filter's prediction alone (the HCW model under the
// commanded force), to rounding; the attitude filter runs on. Without the target in view at the
// start there is nothing to start from: a clear error.
TEST(Navigation, AGapPropagatesOnTheCommandsAndAStartWithoutTheTargetIsRefused) {
  const model::Scenario s = test_scenario();
  const NavParams p = make_nav_params(s);
  model::SensorMeasurements meas;
  meas.r_lvlh_m = Vec3(0.3, -20.0, 0.1);
  NavState state = init_nav(p, meas);
  const Vec3 force(2.0, -1.0, 0.5);
  meas.t = kPeriodNs;
  meas.r_lvlh_m = Vec3(0.31, -19.99, 0.1);
  step_nav(p, state, meas, force);
  Vec6 predicted = state.translation.x;
  meas.lidar_valid = false;
  meas.r_lvlh_m = Vec3::Zero();
  for (int k = 2; k < 50; ++k) {
    meas.t = k * kPeriodNs;
    predicted = p.translation.Ad * predicted + p.translation.Bd_force * force;
    const NavEstimate e = step_nav(p, state, meas, force);
    EXPECT_LE((e.r_lvlh_m - predicted.head<3>()).norm(), 1e-12) << k;
    EXPECT_LE((e.v_lvlh_mps - predicted.tail<3>()).norm(), 1e-14) << k;
  }
  model::SensorMeasurements blind;
  blind.lidar_valid = false;
  try {
    init_nav(p, blind);
    ADD_FAILURE() << "a start without the target in view was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("fov_half_angle_deg"), std::string::npos) << e.what();
  }
}

// With perfect measurements of a thrusting, turning chaser, the estimate converges to the truth:
// the velocity (never measured) from zero, the gyro bias from zero. This only works if step_nav
// feeds the commanded force into the prediction: ignoring a 2 N force would leave a steady
// velocity lag of order F / m / (filter bandwidth ~0.1 rad/s) ~ 1e-2 m/s.
TEST(Navigation, ConvergesOnThrustingTurningChaser) {
  const model::Scenario s = test_scenario();
  const NavParams p = make_nav_params(s);
  const DiscreteLinear6 hcw = discrete_hcw(s.orbit.mean_motion_radps(), s.control_period_s);
  const Vec3 force(2.0, -1.0, 0.5), omega(1e-3, -5e-4, 8.5e-4), bias(2e-5, 1e-5, -3e-5);
  Vec6 truth;
  truth << 0.3, -20.0, 0.1, 0.01, 0.02, -0.005;
  Quat q_true = quat_from_rotation_vector(Vec3(0.1, 0.2, 1.5));
  model::SensorMeasurements meas{0, truth.head<3>(), q_true, omega + bias};
  NavState state = init_nav(p, meas);
  NavEstimate est;
  for (int k = 1; k <= 30000; ++k) {
    truth = hcw.Ad * truth + hcw.Bd * force / s.chaser.mass_kg;
    q_true = q_true * quat_from_rotation_vector(omega * s.control_period_s);
    meas = model::SensorMeasurements{k * kPeriodNs, truth.head<3>(), q_true, omega + bias};
    est = step_nav(p, state, meas, force);
  }
  EXPECT_LT((est.r_lvlh_m - truth.head<3>()).norm(), 1e-9);
  EXPECT_LT((est.v_lvlh_mps - truth.tail<3>()).norm(), 1e-10);
  EXPECT_LT(attitude_error_body(q_true, est.q_inertial_from_body).norm(), 1e-9);
  EXPECT_LT((est.omega_body_radps - omega).norm(), 1e-9);
  EXPECT_LT((state.attitude.gyro_bias_radps - bias).norm(), 1e-9);
}

}  // namespace
}  // namespace chaser::flight
