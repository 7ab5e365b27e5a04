// chaser campaign --target: the grammar, its errors, and the verdict against the zero-failure
// count and the one-sided bound.
#include "campaign/target.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "campaign/confidence.hpp"

namespace chaser::campaign {
namespace {

TEST(Target, ParsesEachIndexWithItsDirection) {
  const TargetParse nd = parse_target("P_nd<=1e-3@0.95");
  ASSERT_TRUE(nd.target) << nd.error;
  EXPECT_EQ(nd.target->index, RateIndex::kPNd);
  EXPECT_TRUE(nd.target->at_most);
  EXPECT_EQ(nd.target->bound, 1e-3);
  EXPECT_EQ(nd.target->confidence, 0.95);
  EXPECT_EQ(nd.target->zero_failure_runs, 2995);  // ceil(ln 0.05 / ln 0.999) = ceil(2994.23)
  EXPECT_EQ(nd.target->text, "P_nd<=1e-3@0.95");

  const TargetParse capture = parse_target("capture_rate>=0.99@0.9");
  ASSERT_TRUE(capture.target) << capture.error;
  EXPECT_EQ(capture.target->index, RateIndex::kCaptureRate);
  EXPECT_FALSE(capture.target->at_most);
  EXPECT_NEAR(capture.target->failure_max(), 0.01, 1e-15);  // 1 - 0.99 in double
  EXPECT_EQ(capture.target->zero_failure_runs, 230);        // ceil(ln 0.1 / ln 0.99) = ceil(229.1)

  for (const char* text : {"P_f<=0.01@0.9", "P_i>=0.9@0.95", "corridor_rate>=0.5@0.5", " P_i >= 0.9 @ 0.95 "})
    EXPECT_TRUE(parse_target(text).target) << text << ": " << parse_target(text).error;
}

// Every bad text is refused with a message naming the option, the text and the grammar.
TEST(Target, RefusesBadTextNamingTheOptionAndTheGrammar) {
  struct Bad {
    const char* text;
    const char* why;
  };
  for (const Bad& b : {Bad{"P_nd<1e-3@0.95", "no '<=' or '>='"}, Bad{"P_nd>=0.9@0.95", "P_nd takes '<='"},
                       Bad{"P_i<=0.1@0.95", "P_i takes '>='"}, Bad{"P_x<=0.1@0.9", "unknown index 'P_x'"},
                       Bad{"P_nd<=0@0.95", "the bound '0' is not a number in (0, 1)"},
                       Bad{"P_nd<=1.5@0.95", "the bound '1.5'"}, Bad{"P_nd<=nan@0.95", "the bound 'nan'"},
                       Bad{"P_nd<=0.1%@0.95", "the bound '0.1%'"}, Bad{"P_nd<=abc@0.95", "the bound 'abc'"},
                       Bad{"P_nd<=1e-3", "give the confidence once"}, Bad{"P_nd<=1e-3@95", "the confidence '95'"},
                       Bad{"P_nd<=1e-3@0.95@0.9", "give the confidence once"}, Bad{"", "give the confidence once"},
                       Bad{"P_nd<=1e-30@0.95", "more than 1000000000000000 runs"}}) {
    const TargetParse parsed = parse_target(b.text);
    EXPECT_FALSE(parsed.target) << b.text;
    EXPECT_NE(parsed.error.find(std::string("--target '") + b.text + "'"), std::string::npos) << parsed.error;
    EXPECT_NE(parsed.error.find(b.why), std::string::npos) << parsed.error;
    EXPECT_NE(parsed.error.find(kTargetGrammar), std::string::npos) << parsed.error;
  }
}

// The zero-failure count is exactly where the verdict turns: 2,995 clean runs show P_nd <= 1e-3 at
// 95 %, 2,994 do not, nor do 2,995 with one miss (its bound is 1 - (upper of 1 of 2995) > 1e-3).
// For ">= q" the failures are the runs without the event: 230 captures of 230 show >= 0.99 at 90 %.
TEST(Target, VerdictTurnsAtTheZeroFailureCount) {
  const Target nd = *parse_target("P_nd<=1e-3@0.95").target;
  EXPECT_TRUE(judge_target(nd, {0, 2995}).demonstrated);
  EXPECT_FALSE(judge_target(nd, {0, 2994}).demonstrated);
  EXPECT_FALSE(judge_target(nd, {1, 2995}).demonstrated);
  // One miss: the bound B(0.95; 2, n - 1) is 1.00021e-3 at n = 4,741 and 0.9999984e-3 at 4,742
  // (scipy.stats.beta.isf(0.05, 2, n - 1)), 1.6e-9 relative clear of the target, far beyond the
  // bound's own error (~1e-15).
  EXPECT_TRUE(judge_target(nd, {1, 4742}).demonstrated);
  EXPECT_FALSE(judge_target(nd, {1, 4741}).demonstrated);
  // A tie demonstrates: two clean runs bound P_f by 1 - 0.25^(1/2) = 0.5 exactly at 75 %.
  EXPECT_TRUE(judge_target(*parse_target("P_f<=0.5@0.75").target, {0, 2}).demonstrated);
  const TargetVerdict v = judge_target(nd, {0, 2995});
  EXPECT_EQ(v.index_bound, clopper_pearson_upper(0, 2995, 0.95));

  const Target capture = *parse_target("capture_rate>=0.99@0.9").target;
  EXPECT_TRUE(judge_target(capture, {230, 230}).demonstrated);
  EXPECT_FALSE(judge_target(capture, {229, 229}).demonstrated);
  const TargetVerdict c = judge_target(capture, {229, 230});
  EXPECT_EQ(c.failures.events, 1);
  EXPECT_FALSE(c.demonstrated);
  EXPECT_NEAR(c.index_bound, clopper_pearson_lower(229, 230, 0.9), 1e-15);  // lower = 1 - upper of the failures
}

}  // namespace
}  // namespace chaser::campaign
