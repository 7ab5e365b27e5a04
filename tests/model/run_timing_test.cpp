#include "model/run_timing.hpp"

#include <gtest/gtest.h>

namespace chaser::model {
namespace {

// MSR's 1200 s at 0.1 s: 12,000 periods of exactly 1e8 ns, the duration their product.
TEST(RunTiming, WholeNanosecondPeriodsCountTheDurationExactly) {
  Scenario s;
  s.duration_s = 1200.0;
  s.control_period_s = 0.1;
  const RunTiming t = run_timing(s);
  EXPECT_EQ(t.control_period_ns, 100'000'000);
  EXPECT_EQ(t.periods, 12'000);
  EXPECT_EQ(t.duration_ns, 1'200'000'000'000);
  EXPECT_TRUE(check(t).empty());
}

// What the fuzz harness traps on: a period that rounded to nothing, or no period at all.
TEST(RunTiming, CheckNamesEachBrokenPart) {
  EXPECT_EQ(check(RunTiming{.control_period_ns = 0, .duration_ns = 0, .periods = 1}),
            (std::vector<std::string>{"control_period_ns < 1"}));
  EXPECT_EQ(check(RunTiming{.control_period_ns = 10, .duration_ns = 0, .periods = 0}),
            (std::vector<std::string>{"periods < 1"}));
  EXPECT_EQ(check(RunTiming{.control_period_ns = 10, .duration_ns = 25, .periods = 2}),
            (std::vector<std::string>{"duration_ns != periods * control_period_ns"}));
}

}  // namespace
}  // namespace chaser::model
