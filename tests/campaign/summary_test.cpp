// summary.md and summary.csv of a small campaign carry every proportion's 95 % bounds, and the
// --target section; merged shards give the one-go summary with targets too.
#include "campaign/summary.hpp"

#include <gtest/gtest.h>

#include "campaign/campaign.hpp"
#include "campaign/merge.hpp"
#include "campaign_test_util.hpp"

namespace chaser::campaign {
namespace {

using testing::fresh_dir;
using testing::read_file;
using testing::short_plan;

// Three runs of each case: 3 fault-free, 3 stuck open (short runs: onset 20 s, 10 s after).
const std::vector<CaseRuns> kCases = {{FaultCase::kNone, 3}, {FaultCase::kStuckOpen, 3}};

std::vector<Target> targets(std::initializer_list<const char*> texts) {
  std::vector<Target> out;
  for (const char* t : texts) out.push_back(*parse_target(t).target);
  return out;
}

CampaignOutcome run(const std::filesystem::path& dir, std::vector<Target> t, Shard shard = {}) {
  CampaignOptions o;
  o.out_dir = dir.string();
  o.threads = 2;
  o.shard = shard;
  o.targets = std::move(t);
  return run_campaign(short_plan(kCases), o);
}

// No false alarm in 3 fault-free runs reads "0 of 3 (<= 63.16 %)": 1 - 0.05^(1/3) = 0.631597,
// rounded up. summary.csv ends with the ten bound columns. P_f <= 0.5 at 50 % needs one clean run
// (ln 0.5 / ln 0.5 = 1), so three demonstrate it; P_nd <= 1e-3 at 95 % needs 2,995.
TEST(Summary, CarriesTheBoundsAndTheTargets) {
  const auto dir = fresh_dir("summary_targets");
  const CampaignOutcome o = run(dir, targets({"P_nd<=1e-3@0.95", "P_f<=0.5@0.5", "capture_rate>=0.5@0.9"}));
  ASSERT_EQ(o.status, CampaignStatus::kOk) << o.message;
  const std::string md = read_file(dir / "summary.md");
  EXPECT_NE(md.find("| P_f | 0 of 3 (<= 63.16 %) |"), std::string::npos) << md;
  EXPECT_NE(md.find("one-sided 95 % upper bound"), std::string::npos);
  EXPECT_NE(md.find("### Targets"), std::string::npos);
  EXPECT_NE(md.find("`P_nd<=1e-3@0.95`: P_nd <= 0.1 % at 95 %; a case demonstrates it with 2,995 runs and 0 missed "
                    "detections"),
            std::string::npos)
      << md;
  // fdir on case none: P_nd means nothing there ("-"); P_f: 0 false alarms of 3, bound 1 - 0.5^(1/3) = 20.63 %.
  EXPECT_NE(md.find("| fdir | - | no: <= 63.16 % (0 of 3) |"), std::string::npos) << md;
  EXPECT_NE(md.find("| fdir | **yes**: <= 20.63 % (0 of 3) | **yes**: <= 20.63 % (0 of 3) |"), std::string::npos)
      << md;
  EXPECT_NE(md.find("| all schemes |"), std::string::npos);  // the mission rate: one row

  const std::string csv = read_file(dir / "summary.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "scheme,case,runs,detected,mean_td_s,std_td_s,mean_ti_s,std_ti_s,P_nd,P_f,P_i,capture_rate,corridor_rate,"
            "mean_propellant_kg,P_nd_lo95,P_nd_hi95,P_f_lo95,P_f_hi95,P_i_lo95,P_i_hi95,capture_rate_lo95,"
            "capture_rate_hi95,corridor_rate_lo95,corridor_rate_hi95");
}

// Targets only add to summary.md: the other files are those of a campaign without them, and two
// shards merged with the same targets write the one-go summary.md byte for byte.
TEST(Summary, TargetsChangeOnlySummaryMdAndSurviveAMerge) {
  const auto plain = fresh_dir("targets_plain"), with = fresh_dir("targets_with");
  const std::vector<Target> t = targets({"P_i>=0.9@0.95", "corridor_rate>=0.9@0.8"});
  ASSERT_EQ(run(plain, {}).status, CampaignStatus::kOk);
  ASSERT_EQ(run(with, t).status, CampaignStatus::kOk);
  for (const char* name : {"runs.csv", "summary.csv", "campaign.json", "glr_envelope.csv"})
    EXPECT_EQ(read_file(plain / name), read_file(with / name)) << name;
  EXPECT_NE(read_file(plain / "summary.md"), read_file(with / "summary.md"));

  const auto a = fresh_dir("targets_shard0"), b = fresh_dir("targets_shard1"), merged = fresh_dir("targets_merged");
  ASSERT_EQ(run(a, {}, Shard{0, 2}).status, CampaignStatus::kOk);
  ASSERT_EQ(run(b, {}, Shard{1, 2}).status, CampaignStatus::kOk);
  const CampaignOutcome m = merge_shards(merged.string(), {b.string(), a.string()}, t);
  ASSERT_EQ(m.status, CampaignStatus::kOk) << m.message;
  EXPECT_EQ(read_file(merged / "summary.md"), read_file(with / "summary.md"));
}

}  // namespace
}  // namespace chaser::campaign
