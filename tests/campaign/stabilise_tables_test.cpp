// COMRADE Table 8 from runs.csv (campaign/stabilise_tables.hpp): a synthetic campaign of hand-made
// rows read back (a diverged run and a run whose stabilisation never flew left out of the figures
// and counted as not meeting Table 3; a run that never got below 0.5 deg/s left out of the time),
// the statistics by hand, and the markdown's verdicts against Table 3 beside the paper's rates.
#include "campaign/stabilise_tables.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>

#include <unistd.h>

#include "campaign/run_row.hpp"

namespace chaser::campaign {
namespace {

RunRecord stabilised_run(std::int64_t index, const Vec3& final_rate_deg_s, double below_s, double load_Nm, bool met) {
  RunRecord r = error_record(RunSetup{});
  r.run = index;
  r.status = RunStatus::kOk;
  r.reach.stabilise_final_rate_deg_s = final_rate_deg_s;
  r.reach.stabilise_below_goal_s = below_s;
  r.reach.stabilise_peak_load_Nm = load_Nm;
  r.reach.stabilise_propellant_kg = 3.0 + index;
  r.reach.stabilise_table3_met = met;
  return r;
}

TEST(StabiliseTables, ReadsASpinCasesCampaignAndJudgesItAgainstTableThree) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("chaser_stabilise_tables_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  {
    std::ofstream f(dir / "runs.csv");
    f << runs_header(RunColumnSet::kReach) << '\n';
    f << format_row(stabilised_run(0, Vec3(0.003, 0.004, 0.0), 240.0, 90.0, true), RunColumnSet::kReach) << '\n';
    f << format_row(stabilised_run(1, Vec3(-0.001, 0.002, 0.002), 250.0, 80.0, true), RunColumnSet::kReach) << '\n';
    const double nan = std::numeric_limits<double>::quiet_NaN();
    f << format_row(stabilised_run(2, Vec3(0.6, 0.0, 0.0), nan, 200.0, false), RunColumnSet::kReach) << '\n';
    RunRecord diverged = stabilised_run(3, Vec3(0.0, 0.0, 0.0), 1.0, 1.0, true);
    diverged.status = RunStatus::kDiverged;
    f << format_row(diverged, RunColumnSet::kReach) << '\n';
    RunRecord unflown = error_record(RunSetup{});  // ok, but the run ended before the brakes
    unflown.run = 4;
    unflown.status = RunStatus::kOk;
    f << format_row(unflown, RunColumnSet::kReach) << '\n';
  }
  std::string error;
  const auto column = read_stabilise_column("S2", (dir / "runs.csv").string(), error);
  ASSERT_TRUE(column) << error;
  EXPECT_EQ(column->runs, 5);
  EXPECT_EQ(column->flown, 3);
  EXPECT_EQ(column->table3_met.events, 2);
  EXPECT_EQ(column->table3_met.runs, 5);
  // x at the end: 0.003, -0.001, 0.6: mean 0.602 / 3.
  EXPECT_NEAR(column->final_rate_deg_s[0].mean, 0.602 / 3.0, 1e-15);
  EXPECT_DOUBLE_EQ(column->final_rate_norm_deg_s.p95, 0.6);  // nearest rank of 3: the largest, |(0.6, 0, 0)|
  EXPECT_NEAR(column->final_rate_norm_deg_s.min, 0.003, 1e-15);  // |(-0.001, 0.002, 0.002)|
  EXPECT_EQ(column->below_goal_s.n, 2);                      // the run above 0.5 deg/s left out
  EXPECT_DOUBLE_EQ(column->below_goal_s.mean, 245.0);
  EXPECT_DOUBLE_EQ(column->peak_load_Nm.max, 200.0);
  EXPECT_DOUBLE_EQ(column->propellant_kg.mean, 4.0);

  const std::string md = stabilise_markdown({*column});
  EXPECT_NE(md.find("| figure | Table 3 | COMRADE H-inf | S2 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| angular rate X at the end [deg/s], mean +- 1 sigma | | -0.023 | 0.2007 +-"), std::string::npos) << md;
  EXPECT_NE(md.find("| angular rate at the end, magnitude [deg/s], 95th percentile | < 0.5 | | 0.6000 (**not met**) |"),
            std::string::npos) << md;
  EXPECT_NE(md.find("| braked joints' peak load [N m], mean; 95th percentile | < 176 | | 123.3; 200.0 (**not met**) |"),
            std::string::npos) << md;
  EXPECT_NE(md.find("| runs flown of runs | | | 3 of 5 |"), std::string::npos) << md;
  const std::string csv = stabilise_csv({*column});
  EXPECT_NE(csv.find("\nS2,stabilise_final_rate_x_deg_s,3,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",176,nan\n"), std::string::npos) << csv;
  std::filesystem::remove_all(dir);
}

TEST(StabiliseTables, AFileWithoutTheStabilisationsColumnsIsAnError) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("chaser_stabilise_tables_bad_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "runs.csv") << runs_header(RunColumnSet::kStandard) << '\n';
  std::string error;
  EXPECT_FALSE(read_stabilise_column("S1", (dir / "runs.csv").string(), error));
  EXPECT_NE(error.find("no column stabilise_below_goal_s"), std::string::npos) << error;
  EXPECT_FALSE(read_stabilise_column("S1", (dir / "missing.csv").string(), error));
  EXPECT_NE(error.find("cannot be read"), std::string::npos) << error;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace chaser::campaign
