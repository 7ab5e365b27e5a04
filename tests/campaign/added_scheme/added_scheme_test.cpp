// A diagnosis scheme added as a module and one row of flight/diagnosis_schemes.hpp, and nothing
// else: a trivial "ramp" scheme (its residual and statistic are the run time, it alarms at 5 s and
// confirms its first lane, T1, at 7 s) registered at start-up shows up everywhere a scheme does:
// telemetry channels, the run's result and summary.json, its report, runs.csv columns and a
// campaign's Table 2. Its own binary: the registration is process-wide.
#include <gtest/gtest.h>

#include <algorithm>

#include "../campaign_test_util.hpp"
#include "campaign/campaign.hpp"
#include "campaign/run_row.hpp"
#include "campaign/statistics.hpp"
#include "flight/diagnosis_schemes.hpp"
#include "flight/fdir.hpp"
#include "sim/run.hpp"
#include "sim/summary.hpp"

namespace chaser {
namespace {

void ramp_step(const flight::FdirParams&, flight::FdirState&, const model::SensorMeasurements&,
               const flight::FdirInput& in, flight::fdi::FdiSchemeOutput& out) {
  out.residual[0] = in.t_s;
  out.glr = flight::fdi::GlrStatistic::of_value(in.t_s);
  out.alarm = in.t_s >= 5.0;
  out.alarm_time_s = out.alarm ? 5.0 : -1.0;
  out.candidate = out.confirmed = in.t_s >= 7.0 ? 0 : -1;
}

const int kRampSlot = flight::register_diagnosis_scheme(
    {.name = "ramp", .residual_channels = 1, .enabled = [](const flight::FdirParams&) { return true; }, .step = ramp_step});

model::Scenario msr(double duration_s) {
  const io::LoadResult loaded = io::load_scenario_file(
      "scenarios/msr_terminal.yaml", {"duration_s=" + std::to_string(duration_s), "fdi.recovery=none"});
  EXPECT_TRUE(loaded.scenario) << io::format_errors(loaded.errors);
  return *loaded.scenario;
}

TEST(AddedScheme, TakesTheNextSlotAndRefusesATakenOrUnplainName) {
  EXPECT_EQ(kRampSlot, 5);  // after the five built in
  ASSERT_EQ(flight::diagnosis_schemes().size(), 6u);
  EXPECT_EQ(flight::register_diagnosis_scheme({.name = "ramp", .residual_channels = 0,
                                               .enabled = [](const flight::FdirParams&) { return true; }, .step = ramp_step}),
            -1);
  EXPECT_EQ(flight::register_diagnosis_scheme({.name = "../x", .residual_channels = 0,
                                               .enabled = [](const flight::FdirParams&) { return true; }, .step = ramp_step}),
            -1);
  EXPECT_EQ(flight::diagnosis_schemes().size(), 6u);
}

TEST(AddedScheme, AppearsInTelemetryTheResultAndSummaryJson) {
  const model::Scenario s = msr(20.0);
  sim::TelemetryRows rows;
  const sim::RunResult r = sim::run_scenario(s, {.telemetry_path = {}, .telemetry_channels = {}, .telemetry_rows = &rows,
                                                 .record_glr_per_second = true});
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(rows.channels.begin(), rows.channels.end(), name) - rows.channels.begin());
  };
  const std::size_t glr = column("glr_ramp"), alarm = column("alarm_ramp"), confirmed = column("confirmed_ramp");
  ASSERT_LT(confirmed, rows.channels.size());
  EXPECT_EQ(column("residual_ramp_1") + 1, glr);
  EXPECT_EQ(column("confirmed_rate_check") + 2, glr);  // after the five built in
  const std::size_t width = rows.channels.size();
  for (std::size_t k = 0; k < 200; ++k) {
    const double t = 0.1 * static_cast<double>(k);
    const double* row = rows.values.data() + k * width;
    EXPECT_DOUBLE_EQ(row[glr], row[0]) << k;           // the statistic is the run time
    EXPECT_EQ(row[alarm], t >= 5.0 - 1e-9 ? 1.0 : 0.0) << k;
    EXPECT_EQ(row[confirmed], t >= 7.0 - 1e-9 ? 1.0 : 0.0) << k;  // T1
  }
  const sim::SchemeResult& ramp = sim::scheme_result(r.fdir, "ramp");
  EXPECT_TRUE(ramp.enabled);
  EXPECT_NEAR(ramp.alarm_s, 5.0, 1e-9);
  EXPECT_NEAR(ramp.isolated_s, 7.0, 1e-9);
  EXPECT_EQ(ramp.isolated_thruster, 0);
  EXPECT_EQ(r.fdir.isolated_thruster, 0);  // the FDIR's first confirmation, no built-in scheme confirming
  EXPECT_FLOAT_EQ(r.glr_max_per_s[10][kRampSlot], 10.9f);  // the largest in second 10
  const nlohmann::json j = sim::run_summary(s, "hash", r);
  EXPECT_EQ(j["fdir"]["ramp_scheme"]["isolated_thruster"], "T1");
  EXPECT_NEAR(j["fdir"]["ramp_scheme"]["alarm_s"].get<double>(), 5.0, 1e-9);
  EXPECT_TRUE(j["fdir"]["diagnoses"][0].contains("ramp_scheme"));
  EXPECT_NE(sim::summary_text(s, r).find("ramp scheme: FALSE ALARM at 5.0 s, T1 isolated at 7.0 s"), std::string::npos)
      << sim::summary_text(s, r);
}

TEST(AddedScheme, AppearsInRunsCsvAndTheCampaignsTable) {
  const std::string header = campaign::runs_header(campaign::RunColumnSet::kStandard);
  EXPECT_NE(header.find("rate_check_glr_max_before_onset,ramp_detection_s,ramp_isolation_s,ramp_isolated,ramp_false_alarm,"
                        "ramp_missed,ramp_wrong_isolation,ramp_glr_max_before_onset,fdir_detection_s"),
            std::string::npos)
      << header;
  EXPECT_EQ(campaign::statistics_schemes(),
            (std::vector<std::string>{"position", "attitude", "deficit", "bank", "rate_check", "ramp", "fdir"}));
  // Two fault-free runs of 30 s: the ramp alarms in each (a false alarm, P_f = 1), the others do not.
  const campaign::CampaignPlan plan = campaign::testing::short_plan({{campaign::FaultCase::kNone, 2}}, {"fdi.recovery=none"});
  const auto dir = campaign::testing::fresh_dir("added_scheme");
  campaign::CampaignOptions o;
  o.out_dir = dir.string();
  o.threads = 1;
  ASSERT_EQ(campaign::run_campaign(plan, o).status, campaign::CampaignStatus::kOk);
  const std::string md = campaign::testing::read_file(dir / "summary.md");
  EXPECT_NE(md.find("### Scheme: ramp"), std::string::npos) << md;
  const std::string csv = campaign::testing::read_file(dir / "summary.csv");
  EXPECT_NE(csv.find("\nramp,none,2,"), std::string::npos) << csv;
  const std::string runs = campaign::testing::read_file(dir / "runs.csv");
  EXPECT_NE(runs.find("ramp_false_alarm"), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace chaser
