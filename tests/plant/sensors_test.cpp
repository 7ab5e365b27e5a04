#include "plant/sensors.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "core/rotation.hpp"

namespace chaser::plant {
namespace {

constexpr TimeNs kPeriodNs = 100'000'000;  // 0.1 s

model::SensorParams noiseless() {
  model::SensorParams s;
  s.lidar.noise_sigma_m = 0.0;
  s.star_tracker.noise_sigma_rad = 0.0;
  s.gyro.noise_sigma_radps = 0.0;
  return s;
}

// A truth that changes every period, so that each delayed sample is identifiable.
Vec3 truth_r(int k) { return Vec3(1.0 + 0.1 * k, -20.0 + 0.01 * k, 0.3 * std::sin(k)); }
Quat truth_q(int k) { return quat_from_rotation_vector(Vec3(0.01 * k, -0.2, 0.003 * k * k)); }
Vec3 truth_w(int k) { return Vec3(1e-3 * k, -2e-3, 1e-4 * k * k); }

// Without noise or bias, a sensor returns the truth bit for bit.
TEST(Sensors, ZeroNoiseReturnsTruthExactly) {
  const model::SensorParams params = noiseless();
  SensorState state = make_sensor_state(params, kPeriodNs);
  SensorNoise noise = make_sensor_noise(5);
  for (int k = 0; k < 10; ++k) {
    const auto y = sample_sensors(params, state, k * kPeriodNs, truth_r(k), truth_q(k), truth_w(k), noise);
    EXPECT_EQ(y.t, k * kPeriodNs);
    EXPECT_EQ(y.r_lvlh_m, truth_r(k));
    EXPECT_EQ(y.q_inertial_from_body.coeffs(), truth_q(k).coeffs());
    EXPECT_EQ(y.omega_body_radps, truth_w(k));
  }
}

// A delay of d periods returns exactly the truth of d periods earlier; before d samples exist, the
// oldest sample (the first) is delivered. Each sensor has its own delay.
TEST(Sensors, DelayReturnsTruthOfDPeriodsAgo) {
  model::SensorParams params = noiseless();
  params.lidar.delay_s = 0.3;
  params.star_tracker.delay_s = 0.5;
  params.gyro.delay_s = 3.2;  // 32 periods, the deepest line
  SensorState state = make_sensor_state(params, kPeriodNs);
  SensorNoise noise = make_sensor_noise(5);
  for (int k = 0; k < 80; ++k) {
    const auto y = sample_sensors(params, state, k * kPeriodNs, truth_r(k), truth_q(k), truth_w(k), noise);
    EXPECT_EQ(y.r_lvlh_m, truth_r(std::max(k - 3, 0))) << k;
    EXPECT_EQ(y.q_inertial_from_body.coeffs(), truth_q(std::max(k - 5, 0)).coeffs()) << k;
    EXPECT_EQ(y.omega_body_radps, truth_w(std::max(k - 32, 0))) << k;
  }
}

// Noise statistics over N = 20000 samples: per axis, the mean is the bias within 5 sigma / sqrt(N)
// and the standard deviation is sigma within 5 sigma / sqrt(2N) (standard errors of a Gaussian
// sample's mean and standard deviation). The star-tracker error is read back as the body-frame
// rotation vector q_true^-1 q_meas. Every star-tracker output is a unit quaternion.
TEST(Sensors, NoiseStatisticsMatchBiasAndSigma) {
  model::SensorParams params;
  params.lidar.noise_sigma_m = 0.01;
  params.lidar.bias_m = Vec3(0.02, -0.01, 0.005);
  params.star_tracker.noise_sigma_rad = 2e-4;
  params.star_tracker.bias_rad = Vec3(1e-4, -3e-4, 5e-5);
  params.gyro.noise_sigma_radps = 1e-5;
  params.gyro.bias_radps = Vec3(-2e-5, 1e-5, 3e-5);
  SensorState state = make_sensor_state(params, kPeriodNs);
  SensorNoise noise = make_sensor_noise(17);
  const int n = 20000;
  Vec3 sum[3] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  Vec3 sum2[3] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  for (int k = 0; k < n; ++k) {
    const auto y = sample_sensors(params, state, k * kPeriodNs, truth_r(k), truth_q(k), truth_w(k), noise);
    ASSERT_NEAR(y.q_inertial_from_body.norm(), 1.0, 1e-15);
    const Vec3 e[3] = {y.r_lvlh_m - truth_r(k), attitude_error_body(truth_q(k), y.q_inertial_from_body),
                       y.omega_body_radps - truth_w(k)};
    for (int s = 0; s < 3; ++s) sum[s] += e[s], sum2[s] += e[s].cwiseProduct(e[s]);
  }
  const Vec3 bias[3] = {params.lidar.bias_m, params.star_tracker.bias_rad, params.gyro.bias_radps};
  const double sigma[3] = {params.lidar.noise_sigma_m, params.star_tracker.noise_sigma_rad,
                           params.gyro.noise_sigma_radps};
  for (int s = 0; s < 3; ++s) {
    const Vec3 mean = sum[s] / n;
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(mean[a], bias[s][a], 5 * sigma[s] / std::sqrt(n)) << "sensor " << s << " axis " << a;
      const double sd = std::sqrt(sum2[s][a] / n - mean[a] * mean[a]);
      EXPECT_NEAR(sd, sigma[s], 5 * sigma[s] / std::sqrt(2.0 * n)) << "sensor " << s << " axis " << a;
    }
  }
}

// The three sensors draw from their own named streams: the same seed gives the same measurements.
TEST(Sensors, SameSeedSameMeasurements) {
  const model::SensorParams params;
  SensorState a = make_sensor_state(params, kPeriodNs), b = make_sensor_state(params, kPeriodNs);
  SensorNoise na = make_sensor_noise(9), nb = make_sensor_noise(9);
  for (int k = 0; k < 5; ++k) {
    const auto ya = sample_sensors(params, a, k * kPeriodNs, truth_r(k), truth_q(k), truth_w(k), na);
    const auto yb = sample_sensors(params, b, k * kPeriodNs, truth_r(k), truth_q(k), truth_w(k), nb);
    EXPECT_EQ(ya.r_lvlh_m, yb.r_lvlh_m);
    EXPECT_EQ(ya.q_inertial_from_body.coeffs(), yb.q_inertial_from_body.coeffs());
    EXPECT_EQ(ya.omega_body_radps, yb.omega_body_radps);
  }
}

}  // namespace
}  // namespace chaser::plant

namespace chaser::plant {
namespace {

// The target pose sensor at 3 Hz on 0.1 s periods with 0.1 s latency: samples are taken at the
// first period starting at or after each 1/3 s tick (0, 0.4, 0.7, 1.0, 1.4, ...) and each is
// delivered one period later; without noise it is the truth, q_body_from_target, exactly.
TEST(Sensors, TargetPoseSampledAtItsRateAndDeliveredAfterItsLatency) {
  model::TargetPoseSensorParams pose;
  pose.period_s = 1.0 / 3.0;
  pose.latency_s = 0.1;
  pose.attitude_noise_rad = 0.0;
  SensorState state;
  RandomStream noise(1, "test/target_pose");
  std::vector<double> taken, delivered;
  for (int k = 0; k <= 20; ++k) {
    const double t = 0.1 * k;
    const Quat q_body = truth_q(k), q_target = quat_from_rotation_vector(Vec3(0.02 * k, 0.1, -0.3));
    const model::TargetPoseMeasurement m = sample_target_pose(pose, state, t, q_body, q_target, noise);
    if (!m.valid) continue;
    taken.push_back(m.taken_s);
    delivered.push_back(t);
    const int k_taken = static_cast<int>(std::lround(m.taken_s / 0.1));
    const Quat truth = truth_q(k_taken).conjugate() * quat_from_rotation_vector(Vec3(0.02 * k_taken, 0.1, -0.3));
    EXPECT_LE(rotation_vector_from_quat(truth.conjugate() * m.q_body_from_target).norm(), 1e-15) << t;
  }
  const std::vector<double> expected_taken{0.0, 0.4, 0.7, 1.0, 1.4, 1.7};
  ASSERT_GE(taken.size(), expected_taken.size());
  for (std::size_t i = 0; i < expected_taken.size(); ++i) {
    EXPECT_NEAR(taken[i], expected_taken[i], 1e-12) << i;
    EXPECT_NEAR(delivered[i], expected_taken[i] + 0.1, 1e-12) << i;
  }
}

// With noise, the delivered attitude is off the truth by a rotation of sigma per axis: over 3,000
// samples the RMS per axis is sigma within 5 % (the standard error of an RMS of 9,000 draws is 0.7 %).
TEST(Sensors, TargetPoseNoiseHasItsSigma) {
  model::TargetPoseSensorParams pose;
  pose.period_s = 0.1;
  pose.latency_s = 0.0;
  pose.attitude_noise_rad = 0.01;
  SensorState state;
  RandomStream noise(2, "test/target_pose");
  double sum_sq = 0;
  int n = 0;
  for (int k = 0; k < 3000; ++k) {
    const model::TargetPoseMeasurement m =
        sample_target_pose(pose, state, 0.1 * k, Quat::Identity(), Quat::Identity(), noise);
    ASSERT_TRUE(m.valid) << k;
    sum_sq += rotation_vector_from_quat(m.q_body_from_target).squaredNorm();
    n += 3;
  }
  EXPECT_NEAR(std::sqrt(sum_sq / n), 0.01, 0.0005);
}

// The view: inside the cone about body +x (20 deg here) and the range, on both sides of each edge
// (the cone's by 1e-6 rad, the range's by 1 mm).
TEST(Sensors, TheTargetIsSeenInsideTheConeAndRangeOnly) {
  const double cone = 20.0 * std::numbers::pi / 180.0, range = 100.0;
  const auto at = [](double angle_rad, double distance_m) {
    return Vec3(distance_m * std::cos(angle_rad), distance_m * std::sin(angle_rad) * 0.6,
                distance_m * std::sin(angle_rad) * 0.8);
  };
  EXPECT_TRUE(sees_target(cone, range, at(0.0, 30.0)));
  EXPECT_TRUE(sees_target(cone, range, at(cone - 1e-6, 30.0)));
  EXPECT_FALSE(sees_target(cone, range, at(cone + 1e-6, 30.0)));
  EXPECT_TRUE(sees_target(cone, range, at(0.1, range - 1e-3)));
  EXPECT_FALSE(sees_target(cone, range, at(0.1, range + 1e-3)));
  EXPECT_FALSE(sees_target(cone, range, Vec3(-30.0, 0.0, 0.0)));  // behind
  // The line of sight in body axes: the chaser 10 m along LVLH +y, LVLH turned 90 deg about z in
  // inertial space, the body turned as LVLH: the target is along body -y.
  const Quat quarter(Eigen::AngleAxisd(std::numbers::pi / 2.0, Vec3::UnitZ()));
  EXPECT_LE((line_of_sight_body_m(Vec3(0.0, 10.0, 0.0), quarter, quarter) - Vec3(0.0, -10.0, 0.0)).norm(), 1e-14);
}

// A sample taken out of view is a gap, delivered with the LIDAR's delay like any sample (its
// position zero, never a value), and it shifts no noise stream: the samples after it are those of
// a run without the gap, bit for bit. The pose sensor takes no sample out of view.
TEST(Sensors, AGapIsDeliveredAsAGapAndShiftsNoStream) {
  model::SensorParams params;
  params.lidar.delay_s = 0.2;
  SensorState with_gap = make_sensor_state(params, kPeriodNs), without = make_sensor_state(params, kPeriodNs);
  SensorNoise noise_gap = make_sensor_noise(9), noise_without = make_sensor_noise(9);
  for (int k = 0; k < 20; ++k) {
    const bool in_view = k < 5 || k >= 8;  // taken out of view at 5, 6, 7
    const auto a = sample_sensors(params, with_gap, k * kPeriodNs, truth_r(k), truth_q(k), truth_w(k), noise_gap, in_view);
    const auto b = sample_sensors(params, without, k * kPeriodNs, truth_r(k), truth_q(k), truth_w(k), noise_without);
    const bool gap = k >= 7 && k < 10;  // delivered 2 periods later
    EXPECT_EQ(a.lidar_valid, !gap) << k;
    EXPECT_EQ(a.r_lvlh_m, gap ? Vec3::Zero() : b.r_lvlh_m) << k;
    EXPECT_EQ(a.q_inertial_from_body.coeffs(), b.q_inertial_from_body.coeffs()) << k;
    EXPECT_EQ(a.omega_body_radps, b.omega_body_radps) << k;
  }
  model::TargetPoseSensorParams pose;
  pose.period_s = 0.1;
  pose.latency_s = 0.0;
  SensorState state;
  RandomStream noise(3, "test/target_pose");
  EXPECT_FALSE(sample_target_pose(pose, state, 0.0, Quat::Identity(), Quat::Identity(), noise, false).valid);
  EXPECT_TRUE(sample_target_pose(pose, state, 0.1, Quat::Identity(), Quat::Identity(), noise, true).valid);
}

}  // namespace
}  // namespace chaser::plant
