// The fault population: thruster uniform over branch A, sizes uniform in the scenario's ranges.
#include "campaign/fault_sampling.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>

#include "core/random.hpp"

namespace chaser::campaign {
namespace {

// 8000 draws: each thruster's count is binomial(8000, 1/8), mean 1000, std 29.6; +-150 is five
// standard deviations. Sizes must stay inside [min, max] and their mean near the middle (uniform
// law: std of the mean = width / sqrt(12 n) = 0.00065 for leak; 0.004 is six of them).
TEST(FaultSampling, ThrusterUniformOverBranchASizesInRange) {
  const model::CampaignParams params;
  std::array<int, 8> counts{};
  double leak_sum = 0;
  constexpr int kDraws = 8000;
  for (int i = 0; i < kDraws; ++i) {
    const auto leak = sample_fault(FaultCase::kLeak, params, model::first_thrusters(8), run_seed(2, static_cast<std::uint64_t>(i)));
    ASSERT_TRUE(leak);
    ASSERT_GE(leak->thruster, 0);
    ASSERT_LT(leak->thruster, 8);
    ++counts[static_cast<std::size_t>(leak->thruster)];
    EXPECT_GE(leak->leak_size, params.leak_size_min);
    EXPECT_LE(leak->leak_size, params.leak_size_max);
    EXPECT_EQ(leak->leak_slope_per_s, params.leak_slope_per_s);
    EXPECT_EQ(leak->onset_s, params.onset_s);
    leak_sum += leak->leak_size;
    const auto loss = sample_fault(FaultCase::kLoss, params, model::first_thrusters(8), run_seed(2, static_cast<std::uint64_t>(i)));
    EXPECT_GE(loss->loss_size, params.loss_size_min);
    EXPECT_LE(loss->loss_size, params.loss_size_max);
  }
  for (int c : counts) EXPECT_NEAR(c, kDraws / 8, 150);
  EXPECT_NEAR(leak_sum / kDraws, 0.5 * (params.leak_size_min + params.leak_size_max), 0.004);
}

TEST(FaultSampling, KindsAndReportedSizes) {
  const model::CampaignParams params;
  EXPECT_FALSE(sample_fault(FaultCase::kNone, params, model::first_thrusters(8), 1));
  EXPECT_EQ(fault_size(std::nullopt), 0.0);
  const auto open = sample_fault(FaultCase::kStuckOpen, params, model::first_thrusters(8), 1);
  EXPECT_EQ(open->kind, model::FaultKind::kStuckOpen);
  EXPECT_EQ(fault_size(open), 1.0);
  EXPECT_EQ(sample_fault(FaultCase::kStuckClosed, params, model::first_thrusters(8), 1)->kind, model::FaultKind::kStuckClosed);
  const auto loss = sample_fault(FaultCase::kLoss, params, model::first_thrusters(8), 1);
  EXPECT_EQ(fault_size(loss), loss->loss_size);
}

// campaign.fault_thrusters narrows the draw to its thrusters, uniformly (4 x 2000 draws: binomial
// std 19.4, +-100 is five of them), and campaign.onset_max_s spreads the onsets uniformly over
// [onset_s, onset_max_s] (mean: std width / sqrt(12 n) = 3.2 s for 8000 draws of a 1000 s span; 20 s
// is six of them). Both draw after the thruster and the size: the same run seed gives the same
// size, and without them the same thruster, as a campaign without the keys.
TEST(FaultSampling, NarrowedThrustersAndSpreadOnsets) {
  model::CampaignParams params;
  params.fault_thrusters = (1U << 0) | (1U << 4) | (1U << 12) | (1U << 16);  // T1, T5, T13, T17
  params.onset_s = 1000.0;
  params.onset_max_s = 2000.0;
  std::array<int, 24> counts{};
  double onset_sum = 0.0, earliest = 1e9, latest = 0.0;
  constexpr int kDraws = 8000;
  const model::CampaignParams plain;
  for (int i = 0; i < kDraws; ++i) {
    const std::uint64_t seed = run_seed(3, static_cast<std::uint64_t>(i));
    const auto f = sample_fault(FaultCase::kLoss, params, model::first_thrusters(24), seed);
    ASSERT_TRUE(f);
    ++counts[static_cast<std::size_t>(f->thruster)];
    onset_sum += f->onset_s;
    earliest = std::min(earliest, f->onset_s);
    latest = std::max(latest, f->onset_s);
    const auto same = sample_fault(FaultCase::kLoss, plain, model::first_thrusters(24), seed);
    EXPECT_EQ(f->loss_size, same->loss_size);
    EXPECT_EQ(same->onset_s, plain.onset_s);
  }
  for (int t = 0; t < 24; ++t) {
    if (t == 0 || t == 4 || t == 12 || t == 16)
      EXPECT_NEAR(counts[static_cast<std::size_t>(t)], kDraws / 4, 100) << t;
    else
      EXPECT_EQ(counts[static_cast<std::size_t>(t)], 0) << t;
  }
  EXPECT_GE(earliest, 1000.0);
  EXPECT_LE(latest, 2000.0);
  EXPECT_LT(earliest, 1010.0);
  EXPECT_GT(latest, 1990.0);
  EXPECT_NEAR(onset_sum / kDraws, 1500.0, 20.0);
}

}  // namespace
}  // namespace chaser::campaign
