// The campaign section: every key read with its range, the cross-key rules, the shipped values.
#include <gtest/gtest.h>

#include "scenario_test_util.hpp"

namespace chaser::io {
namespace {

using testing::has_error;
using testing::load_msr;

TEST(CampaignReader, ShippedValuesAreThePapers) {
  const LoadResult r = load_msr();
  ASSERT_TRUE(r.errors.empty()) << format_errors(r.errors);
  const model::CampaignParams& c = r.scenario->campaign;
  EXPECT_EQ(c.onset_s, 1000.0);  // Fonod 2015, section V: faults at 1000 s
  EXPECT_EQ(c.horizon_after_onset_s, 200.0);
  EXPECT_EQ(c.mass_3sigma_rel, 0.10);  // Table 1
  EXPECT_EQ(c.inertia_3sigma_rel, 0.20);
  EXPECT_EQ(c.com_3sigma_m, 0.03);
  EXPECT_EQ(c.leak_size_min, 0.1);
  EXPECT_EQ(c.leak_size_max, 0.3);
  EXPECT_EQ(c.leak_slope_per_s, 0.1);
  EXPECT_EQ(c.loss_size_min, 0.4);
  EXPECT_EQ(c.loss_size_max, 0.9);
  EXPECT_EQ(c.threshold_margin, 1.5);
  EXPECT_EQ(c.runs_per_case, 100u);
}

TEST(CampaignReader, RangesAreChecked) {
  EXPECT_TRUE(has_error(load_msr({"campaign.onset_s=-1"}), "campaign.onset_s", "must be in [0, 1000000)"));
  EXPECT_TRUE(has_error(load_msr({"campaign.horizon_after_onset_s=0"}), "campaign.horizon_after_onset_s", "must be in (0"));
  EXPECT_TRUE(has_error(load_msr({"campaign.mass_3sigma_rel=1"}), "campaign.mass_3sigma_rel", "must be in [0, 1)"));
  EXPECT_TRUE(has_error(load_msr({"campaign.com_3sigma_m=-0.1"}), "campaign.com_3sigma_m", "must be >= 0"));
  EXPECT_TRUE(has_error(load_msr({"campaign.leak_size_min=0"}), "campaign.leak_size_min", "must be in (0, 1]"));
  EXPECT_TRUE(has_error(load_msr({"campaign.threshold_margin=0"}), "campaign.threshold_margin", "must be > 0"));
  EXPECT_TRUE(has_error(load_msr({"campaign.runs_per_case=0"}), "campaign.runs_per_case", ">= 1"));
  EXPECT_TRUE(has_error(load_msr({"campaign.seed=-3"}), "campaign.seed", ""));
}

// A [min, max] pair must be ordered; one error, at the max key.
TEST(CampaignReader, RangesMustBeOrdered) {
  const LoadResult r = load_msr({"campaign.leak_size_min=0.5", "campaign.leak_size_max=0.2"});
  EXPECT_TRUE(has_error(r, "campaign.leak_size_max", "must be >= campaign.leak_size_min = 0.5 (got 0.2)"));
  EXPECT_EQ(r.errors.size(), 1u) << format_errors(r.errors);
  EXPECT_TRUE(load_msr({"campaign.loss_size_min=0.5", "campaign.loss_size_max=0.5"}).errors.empty());
}

// A run flies onset + horizon: whole control periods, and bounded (the per-second GLR record).
TEST(CampaignReader, RunLengthIsWholePeriodsAndBounded) {
  const LoadResult r = load_msr({"campaign.horizon_after_onset_s=20.05"});
  EXPECT_TRUE(has_error(r, "campaign.horizon_after_onset_s", "must be a whole multiple of control_period_s = 0.1"));
  EXPECT_EQ(r.errors.size(), 1u) << format_errors(r.errors);
  EXPECT_TRUE(has_error(load_msr({"campaign.onset_s=900000", "campaign.horizon_after_onset_s=200000"}),
                        "campaign.horizon_after_onset_s", "must be <= 1000000"));
  EXPECT_TRUE(load_msr({"campaign.onset_s=100", "campaign.horizon_after_onset_s=20"}).errors.empty());
}

// The optional fault population keys: onsets spread within the run, faults drawn among named
// thrusters of the starting active set (MSR's branch A: T1..T8; T9..T16 are its standby branch).
TEST(CampaignReader, OnsetSpreadAndFaultThrusters) {
  const LoadResult r = load_msr({"campaign.onset_max_s=1150", "campaign.fault_thrusters=[T1, T5]"});
  ASSERT_TRUE(r.errors.empty()) << format_errors(r.errors);
  EXPECT_EQ(r.scenario->campaign.onset_max_s, 1150.0);
  EXPECT_EQ(r.scenario->campaign.fault_thrusters, model::ThrusterMask{0b10001});
  EXPECT_FALSE(load_msr().scenario->campaign.onset_max_s);
  EXPECT_EQ(load_msr().scenario->campaign.fault_thrusters, 0u);
  EXPECT_TRUE(has_error(load_msr({"campaign.onset_max_s=900"}), "campaign.onset_max_s",
                        "must be in [campaign.onset_s = 1000, onset_s + horizon_after_onset_s = 1200) (got 900)"));
  EXPECT_TRUE(has_error(load_msr({"campaign.onset_max_s=1200"}), "campaign.onset_max_s", "(got 1200)"));
  EXPECT_TRUE(has_error(load_msr({"campaign.fault_thrusters=[T1, X2]"}), "campaign.fault_thrusters.1",
                        "must be a thruster name T1..T32"));
  EXPECT_TRUE(has_error(load_msr({"campaign.fault_thrusters=[]"}), "campaign.fault_thrusters", "a list of 1 to 32"));
  EXPECT_TRUE(has_error(load_msr({"campaign.fault_thrusters=[T9]"}), "campaign.fault_thrusters",
                        "T9 is not in the starting active set"));
}

}  // namespace
}  // namespace chaser::io
