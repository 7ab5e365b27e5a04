#include "core/random.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace chaser {
namespace {

// Same seed and name give the same sequence; another name gives an unrelated one.
TEST(Random, StreamsAreNamedAndReproducible) {
  RandomStream a(42, "sensors/lidar"), b(42, "sensors/lidar"), c(42, "thrusters/delay");
  int equal_to_c = 0;
  for (int i = 0; i < 1000; ++i) {
    const auto x = a.next_u64();
    EXPECT_EQ(x, b.next_u64());
    equal_to_c += x == c.next_u64();
  }
  EXPECT_EQ(equal_to_c, 0);
}

// Moments of 200,000 draws: the standard error of the mean is 1/sqrt(N) = 0.0022 for the normal,
// so 5 standard errors bound a correct generator's failure rate far below 1e-6.
TEST(Random, NormalMoments) {
  RandomStream s(7, "test");
  const int n = 200000;
  double sum = 0, sum2 = 0, sum4 = 0;
  for (int i = 0; i < n; ++i) {
    const double x = s.normal();
    sum += x, sum2 += x * x, sum4 += x * x * x * x;
  }
  EXPECT_NEAR(sum / n, 0.0, 5.0 / std::sqrt(n));
  EXPECT_NEAR(sum2 / n, 1.0, 5.0 * std::sqrt(2.0 / n));
  EXPECT_NEAR(sum4 / n, 3.0, 5.0 * std::sqrt(96.0 / n));
}

TEST(Random, UniformRangeAndMean) {
  RandomStream s(9, "u");
  const int n = 100000;
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double u = s.uniform(2.0, 4.0);
    ASSERT_GE(u, 2.0);
    ASSERT_LT(u, 4.0);
    sum += u;
  }
  EXPECT_NEAR(sum / n, 3.0, 5.0 * (2.0 / std::sqrt(12.0)) / std::sqrt(n));
}

// Truncation: no draw beyond k sigma; the variance of a normal truncated at 3 sigma is 0.9733.
TEST(Random, TruncatedNormal) {
  RandomStream s(11, "t");
  const int n = 200000;
  double sum2 = 0;
  for (int i = 0; i < n; ++i) {
    const double x = s.truncated_normal(2.0, 3.0);
    ASSERT_LE(std::abs(x), 6.0);
    sum2 += x * x;
  }
  EXPECT_NEAR(sum2 / n / 4.0, 0.97333, 0.01);
}

// Run seeds differ between runs and between campaigns.
TEST(Random, RunSeedsDiffer) {
  EXPECT_NE(run_seed(1, 0), run_seed(1, 1));
  EXPECT_NE(run_seed(1, 0), run_seed(2, 0));
  EXPECT_EQ(run_seed(5, 17), run_seed(5, 17));
}

}  // namespace
}  // namespace chaser
