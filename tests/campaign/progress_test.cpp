// The campaign's progress: shown only when enabled, through the caller's function when one is given,
// and always ending with one final call that has every run done.
#include "campaign/progress.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace chaser::campaign {
namespace {

TEST(Progress, AGivenFunctionGetsTheFinalCountsOnceAndNothingWhenDisabled) {
  std::vector<ProgressCounts> calls;
  Progress shown(5, true, [&](const ProgressCounts& c) { calls.push_back(c); });
  shown.finish(5, 1);
  ASSERT_EQ(calls.size(), 1u);
  EXPECT_TRUE(calls[0].final);
  EXPECT_EQ(calls[0].done, 5);
  EXPECT_EQ(calls[0].total, 5);
  EXPECT_EQ(calls[0].diverged, 1);
  EXPECT_GE(calls[0].elapsed_s, 0.0);

  Progress hidden(5, false, [&](const ProgressCounts& c) { calls.push_back(c); });
  hidden.update(3, 0);
  hidden.finish(5, 0);
  EXPECT_EQ(calls.size(), 1u);
}

TEST(Progress, TheLineSaysRunsRateEtaAndDiverged) {
  EXPECT_EQ(progress_line({.done = 10, .total = 40, .diverged = 2, .elapsed_s = 5.0}),
            "campaign: 10/40 runs, 2.0 runs/s, ETA 0m15s, 2 diverged   ");
  EXPECT_EQ(progress_line({.done = 0, .total = 40, .diverged = 0, .elapsed_s = 0.0}),
            "campaign: 0/40 runs, 0.0 runs/s, ETA ?, 0 diverged   ");
}

}  // namespace
}  // namespace chaser::campaign
