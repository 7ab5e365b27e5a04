// Whole campaigns through run_campaign and merge_shards: the result files do not depend on the
// thread count, the shard layout or an interruption, and the summary is what runs.csv says.
#include "campaign/campaign.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <fstream>

#include "campaign/confidence.hpp"
#include "campaign/csv.hpp"
#include "campaign/merge.hpp"
#include "campaign/run_one.hpp"
#include "campaign/run_row.hpp"
#include "campaign_test_util.hpp"
#include "core/random.hpp"

namespace chaser::campaign {
namespace {

using testing::fresh_dir;
using testing::read_file;
using testing::short_plan;

const std::vector<CaseRuns> kCases = {{FaultCase::kNone, 3}, {FaultCase::kStuckOpen, 3}, {FaultCase::kLeak, 2},
                                      {FaultCase::kLoss, 2}};
const char* kResultFiles[] = {"runs.csv", "summary.csv", "summary.md", "glr_envelope.csv", "campaign.json"};

CampaignOutcome run(const CampaignPlan& plan, const std::filesystem::path& dir, int threads, Shard shard = {},
                    bool resume = false) {
  CampaignOptions o;
  o.out_dir = dir.string();
  o.threads = threads;
  o.shard = shard;
  o.resume = resume;
  return run_campaign(plan, o);
}

void expect_same_files(const std::filesystem::path& a, const std::filesystem::path& b) {
  for (const char* name : kResultFiles) {
    const std::string fa = read_file(a / name), fb = read_file(b / name);
    EXPECT_FALSE(fa.empty()) << name;
    EXPECT_TRUE(fa == fb) << name << " differs between " << a << " and " << b;
  }
}

// The same campaign on 1 and 2 threads writes byte-identical result files: each run depends only
// on (campaign seed, run index), rows are written in index order, statistics are taken in order.
TEST(Campaign, ThreadCountDoesNotChangeAByte) {
  const CampaignPlan plan = short_plan(kCases);
  const auto one = fresh_dir("threads1"), two = fresh_dir("threads2");
  ASSERT_EQ(run(plan, one, 1).status, CampaignStatus::kOk);
  const CampaignOutcome o = run(plan, two, 2);
  ASSERT_EQ(o.status, CampaignStatus::kOk) << o.message;
  EXPECT_EQ(o.executed.runs, 10);
  expect_same_files(one, two);
}

// Three shards merged give the one-shard campaign byte for byte (campaign.json included).
TEST(Campaign, ThreeShardsMergedEqualOneShard) {
  const CampaignPlan plan = short_plan(kCases);
  const auto whole = fresh_dir("whole"), merged = fresh_dir("merged");
  ASSERT_EQ(run(plan, whole, 2).status, CampaignStatus::kOk);
  std::vector<std::string> shards;
  for (int i = 2; i >= 0; --i) {  // any order on the command line
    const auto dir = fresh_dir("shard" + std::to_string(i));
    ASSERT_EQ(run(plan, dir, 1, {i, 3}).status, CampaignStatus::kOk);
    shards.push_back(dir.string());
  }
  const CampaignOutcome m = merge_shards(merged.string(), shards);
  ASSERT_EQ(m.status, CampaignStatus::kOk) << m.message;
  expect_same_files(whole, merged);
}

TEST(Campaign, MergeRejectsOverlapMissingIncompleteAndForeignShards) {
  const CampaignPlan plan = short_plan({{FaultCase::kNone, 2}, {FaultCase::kLoss, 2}});
  std::vector<std::string> dirs;
  for (int i = 0; i < 2; ++i) {
    const auto dir = fresh_dir("mshard" + std::to_string(i));
    ASSERT_EQ(run(plan, dir, 1, {i, 2}).status, CampaignStatus::kOk);
    dirs.push_back(dir.string());
  }
  const auto out = fresh_dir("mout");
  const auto expect_error = [&](const std::vector<std::string>& shards, const std::string& fragment) {
    const CampaignOutcome m = merge_shards(out.string(), shards);
    EXPECT_EQ(m.status, CampaignStatus::kBadInput);
    EXPECT_NE(m.message.find(fragment), std::string::npos) << m.message;
  };
  expect_error({dirs[0], dirs[0]}, "both shard 0/2");
  expect_error({dirs[1]}, "shard 0/2 is missing");
  expect_error({dirs[0], "/nonexistent/dir"}, "does not exist");
  const auto foreign = fresh_dir("mforeign");
  ASSERT_EQ(run(short_plan({{FaultCase::kNone, 2}, {FaultCase::kLoss, 2}}, {"campaign.seed=9"}), foreign, 1, {1, 2}).status,
            CampaignStatus::kOk);
  expect_error({dirs[0], foreign.string()}, "not shards of the same campaign (differ in: scenario_hash, campaign_seed)");
  // Cut the last row of shard 1: incomplete.
  const std::string runs = read_file(std::filesystem::path(dirs[1]) / "runs.csv");
  std::ofstream(std::filesystem::path(dirs[1]) / "runs.csv", std::ios::binary)
      << runs.substr(0, runs.rfind('\n', runs.size() - 2) + 1);
  expect_error(dirs, "shard 1/2 in " + dirs[1] + " is incomplete (1 of 2 runs valid)");
  EXPECT_FALSE(std::filesystem::exists(out / "runs.csv"));
}

// Resume after an interruption: keep the valid rows, cut a torn one, fly the rest; the files are
// the uninterrupted campaign's. (The CLI test does the same with a real SIGKILL.)
TEST(Campaign, ResumeAfterATornRowGivesTheSameFiles) {
  const CampaignPlan plan = short_plan(kCases);
  const auto whole = fresh_dir("rwhole"), cut = fresh_dir("rcut");
  ASSERT_EQ(run(plan, whole, 2).status, CampaignStatus::kOk);
  ASSERT_EQ(run(plan, cut, 2).status, CampaignStatus::kOk);
  const std::string runs = read_file(cut / "runs.csv");
  std::size_t at = 0;
  for (int line = 0; line < 6; ++line) at = runs.find('\n', at) + 1;  // header + 5 rows
  std::ofstream(cut / "runs.csv", std::ios::binary) << runs.substr(0, at) << runs.substr(at, 40);  // torn 6th row
  std::filesystem::remove(cut / "summary.csv");
  const CampaignOutcome o = run(plan, cut, 2, {}, true);
  ASSERT_EQ(o.status, CampaignStatus::kOk) << o.message;
  EXPECT_EQ(o.resumed, 5);
  EXPECT_EQ(o.executed.runs, 5);
  expect_same_files(whole, cut);
}

// A stop request ends the runs early: the rows written are a prefix, no summary is written, and a
// resume gives the uninterrupted campaign's files (the Python module stops this way on Ctrl-C).
TEST(Campaign, AStoppedCampaignLeavesAPrefixThatResumeFinishes) {
  const CampaignPlan plan = short_plan(kCases);
  const auto whole = fresh_dir("swhole"), stopped = fresh_dir("sstopped");
  ASSERT_EQ(run(plan, whole, 2).status, CampaignStatus::kOk);
  for (const int threads : {1, 2}) {
    std::filesystem::remove_all(stopped);
    std::atomic<int> asked = 0;
    CampaignOptions o;
    o.out_dir = stopped.string();
    o.threads = threads;
    o.stop_requested = [&] { return ++asked > 4; };  // the fifth question and after: stop
    const CampaignOutcome s = run_campaign(plan, o);
    ASSERT_EQ(s.status, CampaignStatus::kStopped) << s.message;
    EXPECT_GE(s.executed.runs, 1);
    EXPECT_LT(s.executed.runs, 10);
    EXPECT_TRUE(s.executed.stopped);
    EXPECT_FALSE(std::filesystem::exists(stopped / "summary.csv"));
    const std::string rows = read_file(stopped / "runs.csv");
    EXPECT_EQ(read_file(whole / "runs.csv").substr(0, rows.size()), rows);
    const CampaignOutcome resumed = run(plan, stopped, 2, {}, true);
    ASSERT_EQ(resumed.status, CampaignStatus::kOk) << resumed.message;
    EXPECT_EQ(resumed.resumed, s.executed.runs);
    expect_same_files(whole, stopped);
  }
}

TEST(Campaign, ResumeOfAnotherCampaignAndOverwriteAreRefused) {
  const auto dir = fresh_dir("refuse");
  ASSERT_EQ(run(short_plan({{FaultCase::kNone, 1}}), dir, 1).status, CampaignStatus::kOk);
  const CampaignOutcome again = run(short_plan({{FaultCase::kNone, 1}}), dir, 1);
  EXPECT_EQ(again.status, CampaignStatus::kBadInput);
  EXPECT_NE(again.message.find("already holds a campaign"), std::string::npos) << again.message;
  const CampaignOutcome other = run(short_plan({{FaultCase::kNone, 2}}), dir, 1, {}, true);
  EXPECT_EQ(other.status, CampaignStatus::kBadInput);
  EXPECT_NE(other.message.find("different campaign (differs in: cases, total_runs, shard_runs)"), std::string::npos)
      << other.message;
  const CampaignOutcome nothing = run(short_plan({{FaultCase::kNone, 1}}), fresh_dir("nothing"), 1, {}, true);
  EXPECT_EQ(nothing.status, CampaignStatus::kBadInput);
}

// The summary re-derived here from runs.csv by a naive two-pass computation: detection time mean
// and (n - 1) std over detected runs, P_nd, P_f, P_i per scheme and case, and the 95 % interval of
// each proportion from its counts (summary.csv read by column name: the intervals are appended).
TEST(Campaign, SummaryIsWhatRunsCsvSays) {
  const CampaignPlan plan = short_plan(kCases);
  const auto dir = fresh_dir("summary");
  ASSERT_EQ(run(plan, dir, 2).status, CampaignStatus::kOk);
  std::ifstream runs(dir / "runs.csv");
  std::string line;
  std::getline(runs, line);
  const std::string header_text = line;
  const auto header = split_fields(header_text);
  std::vector<std::vector<std::string>> rows;
  while (std::getline(runs, line)) {
    std::vector<std::string> row;
    for (auto f : split_fields(line)) row.emplace_back(f);
    rows.push_back(row);
  }
  ASSERT_EQ(rows.size(), 10u);
  const auto col = [&](const std::string& name) { return static_cast<std::size_t>(column_index(header, name)); };
  std::ifstream summary(dir / "summary.csv");
  std::getline(summary, line);
  const std::string summary_header_text = line;
  const auto summary_header = split_fields(summary_header_text);
  int checked = 0;
  while (std::getline(summary, line)) {
    const auto f = split_fields(line);
    ASSERT_EQ(f.size(), summary_header.size());
    const auto field = [&](const std::string& name) {
      const int i = column_index(summary_header, name);
      EXPECT_GE(i, 0) << name;
      return *parse_number(f[static_cast<std::size_t>(std::max(i, 0))]);
    };
    const std::string scheme(f[0]), fault_case(f[1]);
    std::vector<double> td;
    int n = 0, missed = 0, false_alarms = 0, right = 0, captures = 0, corridors = 0;
    for (const auto& r : rows) {
      if (r[col("case")] != fault_case) continue;
      ++n;
      const double t = *parse_number(r[col(scheme + "_detection_s")]);
      if (!std::isnan(t)) td.push_back(t);
      missed += r[col(scheme + "_missed")] == "1";
      false_alarms += r[col(scheme + "_false_alarm")] == "1";
      right += r[col(scheme + "_isolated")] == r[col("fault_thruster")] && r[col(scheme + "_isolation_s")] != "nan";
      captures += r[col("capture")] == "1";
      corridors += r[col("corridor_kept")] == "1";
    }
    EXPECT_EQ(field("runs"), n);
    EXPECT_EQ(field("detected"), static_cast<double>(td.size()));
    // The bounds are written with 17 digits, so they read back to the very double computed.
    const auto expect_interval = [&](const std::string& name, int events) {
      const ProportionInterval ci = clopper_pearson(events, n, 0.95);
      EXPECT_EQ(field(name + "_lo95"), ci.lower) << scheme << " " << fault_case << " " << name;
      EXPECT_EQ(field(name + "_hi95"), ci.upper) << scheme << " " << fault_case << " " << name;
      EXPECT_DOUBLE_EQ(field(name), static_cast<double>(events) / n) << name;
    };
    expect_interval("P_f", false_alarms);
    expect_interval("capture_rate", captures);
    expect_interval("corridor_rate", corridors);
    if (fault_case == "none") {
      for (const char* name : {"P_nd", "P_nd_lo95", "P_nd_hi95", "P_i", "P_i_lo95", "P_i_hi95"})
        EXPECT_TRUE(std::isnan(field(name))) << name;
      continue;
    }
    expect_interval("P_nd", missed);
    expect_interval("P_i", right);
    if (td.size() >= 2) {
      double mean = 0, ss = 0;
      for (double t : td) mean += t / static_cast<double>(td.size());
      for (double t : td) ss += (t - mean) * (t - mean);
      EXPECT_NEAR(field("mean_td_s"), mean, 1e-12 * std::abs(mean) + 1e-15);
      EXPECT_NEAR(field("std_td_s"), std::sqrt(ss / static_cast<double>(td.size() - 1)), 1e-9 * (1 + mean));
      ++checked;
    }
  }
  EXPECT_GT(checked, 0);  // at least one case with two detections exercised the time statistics
}

// A run whose truth leaves the bounds (a 1 g chaser thrown far by 22 N thrusters) is recorded as
// diverged, with its seed, and cut short; the campaign goes on.
TEST(Campaign, DivergingRunIsRecordedNotFatal) {
  CampaignPlan plan = short_plan({{FaultCase::kNone, 1}});
  const flight::FlightParams flight = flight::make_flight_params(plan.nominal);
  plan.nominal.chaser.mass_kg = 1e-3;
  const RunOutput out = run_one(plan, flight, 0);
  const auto f = split_fields(out.row);
  const auto header_text = runs_header(RunColumnSet::kStandard);
  const auto header = split_fields(header_text);
  EXPECT_EQ(f[static_cast<std::size_t>(column_index(header, "status"))], "diverged");
  EXPECT_EQ(f[1], std::to_string(run_seed(plan.nominal.campaign.seed, 0)));
  EXPECT_LT(*parse_number(f[static_cast<std::size_t>(column_index(header, "simulated_s"))]), 30.0);
  EXPECT_TRUE(out.diverged);
}

// Every row has the spec's columns, and the run's truth is what the row reports.
TEST(Campaign, RowMatchesTheRunSetup) {
  const CampaignPlan plan = short_plan({{FaultCase::kNone, 1}, {FaultCase::kLoss, 1}});
  const RunSetup setup = make_run_setup(plan, 1);
  EXPECT_EQ(setup.truth.duration_s, 30.0);
  ASSERT_EQ(setup.truth.faults.size(), 1u);
  EXPECT_EQ(setup.truth.faults[0].kind, model::FaultKind::kLoss);
  EXPECT_EQ(setup.truth.seed, run_seed(plan.nominal.campaign.seed, 1));
  const flight::FlightParams flight = flight::make_flight_params(plan.nominal);
  const RunOutput out = run_one(plan, flight, 1);  // split_fields' views point into out.row
  const auto f = split_fields(out.row);
  EXPECT_EQ(f.size(), run_columns(RunColumnSet::kStandard).size());
  EXPECT_EQ(f[2], "loss");
  EXPECT_EQ(*parse_integer(f[4]), setup.truth.faults[0].thruster + 1);
  EXPECT_EQ(*parse_number(f[5]), setup.truth.faults[0].loss_size);
  EXPECT_EQ(*parse_number(f[7]), setup.truth.chaser.mass_kg);
  EXPECT_TRUE(make_run_setup(plan, 0).truth.faults.empty());
}

}  // namespace
}  // namespace chaser::campaign
