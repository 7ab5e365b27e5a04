// One-pass statistics against the naive two-pass computation.
#include "campaign/statistics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/random.hpp"

namespace chaser::campaign {
namespace {

// Welford's update is algebraically the two-pass mean and (n - 1) variance; on 10^4 values of
// mean 1000 and spread 0.5 (detection times are like that: a large offset, a small spread, where
// the naive sum-of-squares formula loses ~7 digits) they agree to 1e-9 relative.
TEST(RunningStats, MatchesTwoPassMeanAndSampleStd) {
  RandomStream rng(1, "test/stats");
  std::vector<double> x(10000);
  for (double& v : x) v = 1000.0 + 0.5 * rng.normal();
  RunningStats s;
  for (double v : x) s.add(v);
  double mean = 0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(x.size());
  double ss = 0;
  for (double v : x) ss += (v - mean) * (v - mean);
  const double std_two_pass = std::sqrt(ss / static_cast<double>(x.size() - 1));
  EXPECT_NEAR(s.mean(), mean, 1e-12 * mean);
  EXPECT_NEAR(s.sample_std(), std_two_pass, 1e-9 * std_two_pass);
  EXPECT_EQ(s.count(), 10000);
}

TEST(RunningStats, EmptyAndSingleValue) {
  RunningStats s;
  EXPECT_TRUE(std::isnan(s.mean()));
  s.add(3.0);
  EXPECT_EQ(s.mean(), 3.0);
  EXPECT_TRUE(std::isnan(s.sample_std()));  // n - 1 = 0
}

// Counts per case: a right isolation needs the faulty thruster confirmed after the onset; error
// runs are counted apart and left out of the figures.
TEST(CampaignStats, CountsPerCaseAndScheme) {
  CampaignStats stats({FaultCase::kNone, FaultCase::kLeak});
  const double nan = std::nan("");
  const SchemeFacts detected_right{1.0, 2.0, 3, false, false};
  const SchemeFacts wrong{1.5, 2.5, 4, false, false};
  const SchemeFacts missed{nan, nan, model::kNoThruster, false, true};
  stats.add({FaultCase::kLeak, true, false, false, 3, {detected_right, wrong, missed}, true, true, 0.1});
  stats.add({FaultCase::kLeak, true, false, false, 3, {missed, detected_right, missed}, false, true, 0.3});
  stats.add({FaultCase::kLeak, false, false, true, 3, {detected_right, detected_right, detected_right}, true, true, 9});
  stats.add({FaultCase::kNone, true, true, false, model::kNoThruster, {SchemeFacts{nan, nan, 2, true, false}, missed, missed}, false, false, 0.2});
  const SchemeCaseStats& pos = stats.at(1, 0);
  EXPECT_EQ(pos.runs, 2);
  EXPECT_EQ(pos.detected, 1);
  EXPECT_EQ(pos.missed, 1);
  EXPECT_EQ(pos.right_isolations, 1);
  EXPECT_EQ(stats.at(1, 1).right_isolations, 1);  // the wrong one did not count
  EXPECT_NEAR(pos.propellant_kg.mean(), 0.2, 1e-15);
  EXPECT_EQ(pos.captures, 1);
  EXPECT_EQ(stats.errors(1), 1);
  EXPECT_EQ(stats.at(0, 0).false_alarms, 1);
  EXPECT_EQ(stats.diverged(0), 1);
}

}  // namespace
}  // namespace chaser::campaign
