// The fault population: thruster uniform over branch A, sizes uniform in the scenario's ranges.
#include "campaign/fault_sampling.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace chaser::campaign
