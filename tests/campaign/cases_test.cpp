// Run layout, shards and the parsing of --cases, --runs and --shard.
#include "campaign/cases.hpp"

#include <gtest/gtest.h>

namespace chaser::campaign {
namespace {

TEST(Cases, LayoutPlacesCasesInOrder) {
  const RunLayout layout({{FaultCase::kLeak, 2}, {FaultCase::kNone, 3}});
  EXPECT_EQ(layout.total_runs(), 5);
  EXPECT_EQ(layout.case_of(0), FaultCase::kLeak);
  EXPECT_EQ(layout.case_of(1), FaultCase::kLeak);
  EXPECT_EQ(layout.case_of(2), FaultCase::kNone);
  EXPECT_EQ(layout.case_of(4), FaultCase::kNone);
}

// The shards of any (N, m) tile [0, N) exactly, in order, with sizes differing by at most one.
TEST(Cases, ShardsTileTheRunsExactly) {
  for (std::int64_t n : {0, 1, 7, 10, 6600})
    for (int m : {1, 2, 3, 7, 16}) {
      std::int64_t next = 0;
      for (int i = 0; i < m; ++i) {
        const RunRange r = shard_range({i, m}, n);
        EXPECT_EQ(r.begin, next);
        EXPECT_LE(r.size(), n / m + 1);
        EXPECT_GE(r.size(), n / m);
        next = r.end;
      }
      EXPECT_EQ(next, n);
    }
}

TEST(Cases, ParseShard) {
  EXPECT_EQ(parse_shard("2/3").shard->index, 2);
  for (const char* bad : {"3/3", "-1/3", "1", "a/b", "1/0", "1/3x", "/3"}) {
    const ShardParse p = parse_shard(bad);
    EXPECT_FALSE(p.shard) << bad;
    EXPECT_NE(p.error.find("--shard"), std::string::npos);
  }
}

TEST(Cases, ParseLayout) {
  LayoutParse all = parse_layout("", "", 4);
  ASSERT_EQ(all.cases.size(), 5u);
  EXPECT_EQ(all.cases[0].runs, 4);
  LayoutParse per_case = parse_layout("", "loss=3,none=2", 4);
  ASSERT_EQ(per_case.cases.size(), 2u);
  EXPECT_EQ(per_case.cases[0].fault_case, FaultCase::kLoss);
  EXPECT_EQ(per_case.cases[1].runs, 2);
  LayoutParse some = parse_layout("none,leak", "leak=9", 4);
  ASSERT_EQ(some.cases.size(), 2u);
  EXPECT_EQ(some.cases[0].runs, 4);
  EXPECT_EQ(some.cases[1].runs, 9);
  EXPECT_EQ(parse_layout("none", "7", 4).cases[0].runs, 7);
}

TEST(Cases, ParseLayoutErrorsNameTheOption) {
  EXPECT_NE(parse_layout("none,bogus", "", 1).error.find("--cases: unknown case 'bogus' (allowed: none, stuck_open"),
            std::string::npos);
  EXPECT_NE(parse_layout("none,none", "", 1).error.find("--cases"), std::string::npos);
  EXPECT_NE(parse_layout("", "0", 1).error.find("--runs"), std::string::npos);
  EXPECT_NE(parse_layout("", "-3", 1).error.find("--runs"), std::string::npos);
  EXPECT_NE(parse_layout("", "leak=0", 1).error.find("--runs"), std::string::npos);
  EXPECT_NE(parse_layout("none", "leak=2", 1).error.find("not in --cases"), std::string::npos);
  EXPECT_NE(parse_layout("", "leak=2,leak=3", 1).error.find("twice"), std::string::npos);
}

}  // namespace
}  // namespace chaser::campaign
