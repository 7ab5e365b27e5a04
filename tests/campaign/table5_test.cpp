// COMRADE Table 5 from runs.csv (campaign/table5.hpp): the statistics against closed forms, a
// synthetic campaign read back (diverged runs counted as not captured and left out of the errors),
// and the markdown's verdicts against Table 1.
#include "campaign/table5.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include <unistd.h>

#include "campaign/run_row.hpp"

namespace chaser::campaign {
namespace {

// 1..20: mean 10.5, sample sd sqrt(35), nearest-rank 95th percentile the 19th value; NaNs left out.
TEST(Table5, FigureStatsAreTheSamplesOwn) {
  std::vector<double> v;
  for (int i = 20; i >= 1; --i) v.push_back(i);
  v.push_back(std::numeric_limits<double>::quiet_NaN());
  const FigureStats s = figure_stats(v);
  EXPECT_EQ(s.n, 20);
  EXPECT_DOUBLE_EQ(s.mean, 10.5);
  EXPECT_NEAR(s.sd, std::sqrt(35.0), 1e-12);
  EXPECT_EQ(s.p95, 19.0);
  EXPECT_EQ(s.min, 1.0);
  EXPECT_EQ(s.max, 20.0);
  EXPECT_TRUE(std::isnan(figure_stats({}).mean));
}

RunRecord run(std::int64_t index, bool captured, double position_m) {
  RunRecord r = error_record(RunSetup{});
  r.run = index;
  r.status = RunStatus::kOk;
  r.capture = captured;
  r.final_position_error_m = position_m;
  r.final_speed_mps = 0.002;
  r.final_attitude_error_deg = 0.5;
  r.final_rate_error_deg_s = 0.05;
  r.min_clearance_unsynchronised_m = 5.0 + index;
  r.min_clearance_synchronised_m = 0.8 - 0.1 * index;
  r.propellant_kg = 9.0;
  return r;
}

TEST(Table5, ReadsACampaignAndJudgesItAgainstTableOne) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("chaser_table5_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  {
    std::ofstream f(dir / "runs.csv");
    f << runs_header(RunColumnSet::kStandard) << '\n';
    f << format_row(run(0, true, 0.05), RunColumnSet::kStandard) << '\n' << format_row(run(1, true, 0.07), RunColumnSet::kStandard) << '\n';
    f << format_row(run(2, false, 0.30), RunColumnSet::kStandard) << '\n';
    RunRecord diverged = run(3, false, 5.0);
    diverged.status = RunStatus::kDiverged;
    f << format_row(diverged, RunColumnSet::kStandard) << '\n';
  }
  std::string error;
  const auto column = read_table5_column("S1", (dir / "runs.csv").string(), error);
  ASSERT_TRUE(column) << error;
  EXPECT_EQ(column->runs, 4);
  EXPECT_EQ(column->flown, 3);
  EXPECT_EQ(column->captured.events, 2);
  EXPECT_EQ(column->captured.runs, 4);
  EXPECT_EQ(column->position_m.n, 3);
  EXPECT_NEAR(column->position_m.mean, 0.14, 1e-15);
  EXPECT_EQ(column->position_m.p95, 0.30);
  EXPECT_EQ(column->least_clearance_unsynchronised_m, 5.0);
  EXPECT_NEAR(column->least_clearance_synchronised_m, 0.6, 1e-15);  // the diverged run's 0.5 left out
  const std::string md = table5_markdown({*column});
  EXPECT_NE(md.find("| position error [m], 95th percentile | < 0.1 | | 0.3 (**not met**) |"), std::string::npos) << md;
  EXPECT_NE(md.find("| pointing error [deg], 95th percentile | < 2 | | 0.5 (met) |"), std::string::npos) << md;
  EXPECT_NE(md.find("0.067 +- 0.028"), std::string::npos);
  EXPECT_NE(table5_csv({*column}).find("S1,4,3,2,"), std::string::npos);
  std::ofstream(dir / "old.csv") << "run,status,capture\n0,ok,1\n";
  EXPECT_FALSE(read_table5_column("S1", (dir / "old.csv").string(), error));
  EXPECT_NE(error.find("no column final_position_error_m"), std::string::npos) << error;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace chaser::campaign
