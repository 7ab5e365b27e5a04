// The target attitude estimator (flight/target_estimator.hpp) against a tumbling ENVISAT: the truth
// is integrated here independently (RK4 at 1 ms, torque-free Euler with its full inertia), the
// measurements are the truth rotated by Gaussian noise at 3 Hz, with and without latency.
#include "flight/target_estimator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "core/constants.hpp"
#include "core/random.hpp"
#include "core/rotation.hpp"
#include "tests/support/torque_free_body.hpp"

namespace chaser::flight {
namespace {

using testing::TorqueFreeBody;

Quat noisy(const Quat& q, RandomStream& rng, double sigma) {
  return q * quat_from_rotation_vector(Vec3(rng.normal(), rng.normal(), rng.normal()) * sigma);
}

struct Errors {
  double attitude_rms_rad = 0, attitude_max_rad = 0, rate_rms_radps = 0, mean_nis = 0;
  double prediction_30s_rad = 0;  // attitude error of the estimate carried 30 s ahead, at the end
};

// ENVISAT tumbling at 2.5 deg/s about an axis off its principal ones (it nutates), measured at
// 3 Hz with 1 deg per axis; errors over the last 600 s of a 900 s run. latency: the measurement
// is of the truth `latency_s` before the time the filter is asked about.
Errors fly(double latency_s, std::uint64_t seed) {
  const Mat3 inertia = testing::envisat_inertia_kgm2();
  TargetEstimatorParams params;
  params.inertia_kgm2 = inertia;
  params.attitude_noise_rad = kPi / 180.0;
  params.torque_noise_Nm = 1e-3;
  TargetEstimator filter(params);
  RandomStream rng(seed, "test/target_estimator");
  TorqueFreeBody truth{.inertia_kgm2 = inertia,
                       .q_inertial_from_body = quat_from_rotation_vector(Vec3(0.3, -0.2, 0.5)),
                       .omega_body_radps = Vec3(0.2, 1.0, 0.3).normalized() * (2.5 * kPi / 180.0)};
  const double dt = 1.0 / 3.0;
  Errors e;
  int counted = 0;
  for (int k = 0; k <= 2700; ++k) {
    const double t = k * dt;
    if (k > 0) truth.advance(dt);
    EXPECT_TRUE(filter.update(t, noisy(truth.q_inertial_from_body, rng, params.attitude_noise_rad))) << k;
    if (t < 300.0) continue;
    // The estimate the flight software would use at t + latency (the measurement is that old).
    TorqueFreeBody later = truth;
    later.advance(latency_s);
    const TargetEstimate est = filter.predict(t + latency_s);
    const double att = rotation_vector_from_quat(later.q_inertial_from_body.conjugate() * est.q_inertial_from_target).norm();
    const double rate = (est.omega_target_radps - later.omega_body_radps).norm();
    e.attitude_rms_rad += att * att;
    e.rate_rms_radps += rate * rate;
    e.attitude_max_rad = std::max(e.attitude_max_rad, att);
    e.mean_nis += filter.last_innovation_nis();
    ++counted;
  }
  e.attitude_rms_rad = std::sqrt(e.attitude_rms_rad / counted);
  e.rate_rms_radps = std::sqrt(e.rate_rms_radps / counted);
  e.mean_nis /= counted;
  TorqueFreeBody ahead = truth;
  ahead.advance(30.0);
  e.prediction_30s_rad =
      rotation_vector_from_quat(ahead.q_inertial_from_body.conjugate() * filter.predict(2700 * dt + 30.0).q_inertial_from_target).norm();
  return e;
}

// With 1 deg of noise per measurement, averaging over the rotation's dynamics gives a far better
// estimate: measured 0.053 deg RMS attitude (0.12 deg worst) and 2.9e-3 deg/s RMS rate after the
// first 300 s; the bounds (0.2 deg, 0.5 deg worst, 0.01 deg/s) leave a factor of 3 to 4. The filter is consistent: the mean
// normalised innovation over 1,800 updates is chi-square(3)'s mean, 3, within its sampling error
// (sd of the mean ~ sqrt(6 / 1800) = 0.06, but updates are correlated: bound 2.5-3.5). Carried
// 30 s ahead, as the guidance's feed-forward would, the attitude stays within 0.5 deg (measured
// 0.10 deg).
TEST(TargetEstimator, TracksATumblingEnvisatFromNoisyPoses) {
  const Errors e = fly(0.0, 1);
  std::printf("attitude rms %.3f deg max %.3f deg, rate rms %.2e deg/s, mean NIS %.2f, 30 s ahead %.3f deg\n",
              e.attitude_rms_rad * 180 / kPi, e.attitude_max_rad * 180 / kPi, e.rate_rms_radps * 180 / kPi, e.mean_nis,
              e.prediction_30s_rad * 180 / kPi);
  EXPECT_LT(e.attitude_rms_rad, 0.2 * kPi / 180);
  EXPECT_LT(e.attitude_max_rad, 0.5 * kPi / 180);
  EXPECT_LT(e.rate_rms_radps, 0.01 * kPi / 180);
  EXPECT_GT(e.mean_nis, 2.5);
  EXPECT_LT(e.mean_nis, 3.5);
  EXPECT_LT(e.prediction_30s_rad, 0.5 * kPi / 180);
}

// A measurement 0.5 s old, carried forward by predict(): the same accuracy as without latency
// (within 20 %), where using it as if current would be 1.25 deg off at 2.5 deg/s.
TEST(TargetEstimator, LatencyIsCarriedForward) {
  const Errors fresh = fly(0.0, 2);
  const Errors late = fly(0.5, 2);
  std::printf("attitude rms: fresh %.4f deg, 0.5 s late %.4f deg\n", fresh.attitude_rms_rad * 180 / kPi,
              late.attitude_rms_rad * 180 / kPi);
  EXPECT_LT(late.attitude_rms_rad, 1.2 * fresh.attitude_rms_rad + 1e-4);
}

TEST(TargetEstimator, RefusesOldAndBadMeasurements) {
  TargetEstimator filter(TargetEstimatorParams{});
  EXPECT_TRUE(filter.update(10.0, Quat::Identity()));
  EXPECT_FALSE(filter.update(9.0, Quat::Identity()));
  EXPECT_FALSE(filter.update(11.0, Quat(std::nan(""), 0, 0, 0)));
  EXPECT_TRUE(filter.update(11.0, Quat::Identity()));
}

}  // namespace
}  // namespace chaser::flight
