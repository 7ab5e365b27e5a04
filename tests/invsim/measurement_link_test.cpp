#include "invsim/measurement_link.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace chaser::invsim {
namespace {

// No noise: the truth, bit for bit (the link then draws nothing).
TEST(MeasurementLink, PerfectWithoutNoise) {
  MeasurementLink link(model::InvSimMeasurementNoise{});
  const Vec3 r(100.038, -0.0167, -0.023);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(link.measured_position_hill_m(r, 103.0), r);
}

// Eq. 14 to first order: the error along x has the range's sigma, across (y, z) the angle's sigma
// times the range; zero mean, independent components. 40,000 draws: the sample sigma is within
// 2 % (its standard error is 0.35 %), the mean within 4 standard errors, the correlation below 0.02.
TEST(MeasurementLink, ErrorsHaveTheSensorsSigmasAlongAndAcrossTheLineOfSight) {
  model::InvSimMeasurementNoise noise;
  noise.range_sigma_m = 0.02;
  noise.angle_sigma_rad = 1e-3;
  noise.seed = 7;
  MeasurementLink link(noise);
  const Vec3 r(50.0, 1.0, -2.0);
  const double range_m = 53.0;
  const int n = 40000;
  Vec3 sum = Vec3::Zero(), sum_sq = Vec3::Zero();
  double sum_yz = 0.0;
  for (int i = 0; i < n; ++i) {
    const Vec3 e = link.measured_position_hill_m(r, range_m) - r;
    sum += e;
    sum_sq += e.cwiseProduct(e);
    sum_yz += e.y() * e.z();
  }
  const Vec3 expected_sigma(0.02, range_m * 1e-3, range_m * 1e-3);
  for (int i = 0; i < 3; ++i) {
    const double mean = sum(i) / n;
    const double sigma = std::sqrt(sum_sq(i) / n - mean * mean);
    EXPECT_NEAR(sigma / expected_sigma(i), 1.0, 0.02) << i;
    EXPECT_LT(std::abs(mean), 4.0 * expected_sigma(i) / std::sqrt(n)) << i;
  }
  EXPECT_LT(std::abs(sum_yz / n) / (expected_sigma(1) * expected_sigma(2)), 0.02);
}

// The sequence depends on the seed only: the same seed, the same errors (every fault mode of a
// study meets the same noise); another seed, others.
TEST(MeasurementLink, TheSeedFixesTheSequence) {
  model::InvSimMeasurementNoise noise;
  noise.angle_sigma_rad = 2e-4;
  noise.seed = 3;
  MeasurementLink a(noise), b(noise);
  noise.seed = 4;
  MeasurementLink c(noise);
  const Vec3 r(80.0, 0.0, 0.0);
  bool differs = false;
  for (int i = 0; i < 100; ++i) {
    const Vec3 ea = a.measured_position_hill_m(r, 83.0);
    EXPECT_EQ(ea, b.measured_position_hill_m(r, 83.0));
    EXPECT_EQ(ea.x(), r.x());  // range sigma 0: no error along the line of sight
    differs = differs || ea != c.measured_position_hill_m(r, 83.0);
  }
  EXPECT_TRUE(differs);
}

}  // namespace
}  // namespace chaser::invsim
