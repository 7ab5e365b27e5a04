// COMRADE Tables 5 (reach) and 6 from runs.csv (campaign/reach_tables.hpp): a synthetic campaign of
// hand-made rows read back (a diverged run and a run whose arm never woke left out of the figures
// and counted as not meeting Table 2), the statistics by hand, and the markdown's verdicts against
// Table 2 beside the paper's numbers.
#include "campaign/reach_tables.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "campaign/run_row.hpp"

namespace chaser::campaign {
namespace {

// A flown reach: the gripper's x error `x_m` at the end and over the hold, rates of 0.05 deg/s.
RunRecord reach_run(std::int64_t index, double x_m, bool met) {
  RunRecord r = error_record(RunSetup{});
  r.run = index;
  r.status = RunStatus::kOk;
  r.final_position_error_m = 0.02 + 0.01 * index;
  r.final_speed_mps = 0.002;
  r.final_attitude_error_deg = 0.3;
  r.final_rate_error_deg_s = 0.05;
  r.reach.final_error_m = Vec3(x_m, 0.001, -0.001);
  r.reach.final_velocity_mps = Vec3(0.001, 0.0, 0.0);
  r.reach.final_attitude_deg = Vec3(0.1, 0.2, 0.3);
  r.reach.final_rate_deg_s = Vec3(0.01, 0.02, 0.03);
  r.reach.max_error_m = Vec3(std::abs(x_m) + 0.001, 0.005, 0.005);
  r.reach.max_velocity_mps = Vec3::Constant(0.004);
  r.reach.max_attitude_deg = Vec3::Constant(0.5);
  r.reach.max_rate_deg_s = Vec3::Constant(0.05);
  r.reach.peak_joint_torque_Nm = 5.0 + index;
  r.reach.min_tool_clearance_m = 0.15 - 0.01 * index;
  r.reach.table2_met = met;
  return r;
}

TEST(ReachTables, ReadsALawsCampaignAndJudgesItAgainstTableTwo) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("chaser_reach_tables_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  {
    std::ofstream f(dir / "runs.csv");
    f << runs_header(RunColumnSet::kReach) << '\n';
    f << format_row(reach_run(0, 0.002, true), RunColumnSet::kReach) << '\n';
    f << format_row(reach_run(1, 0.004, true), RunColumnSet::kReach) << '\n';
    f << format_row(reach_run(2, -0.012, false), RunColumnSet::kReach) << '\n';
    RunRecord diverged = reach_run(3, 0.5, false);
    diverged.status = RunStatus::kDiverged;
    f << format_row(diverged, RunColumnSet::kReach) << '\n';
    RunRecord asleep = error_record(RunSetup{});  // ok, but the run ended before the arm woke
    asleep.run = 4;
    asleep.status = RunStatus::kOk;
    f << format_row(asleep, RunColumnSet::kReach) << '\n';
  }
  std::string error;
  const auto column = read_reach_column("compliance", (dir / "runs.csv").string(), error);
  ASSERT_TRUE(column) << error;
  EXPECT_EQ(column->runs, 5);
  EXPECT_EQ(column->flown, 3);
  EXPECT_EQ(column->table2_met.events, 2);
  EXPECT_EQ(column->table2_met.runs, 5);
  // x at the end: 2, 4, -12 mm: mean -2 mm, sd sqrt(((4)^2 + (6)^2 + (10)^2) / 2) = sqrt(76) mm.
  EXPECT_NEAR(column->gripper_final[0][0].mean, -0.002, 1e-15);
  EXPECT_NEAR(column->gripper_final[0][0].sd, std::sqrt(76.0) * 1e-3, 1e-15);
  EXPECT_DOUBLE_EQ(column->gripper_max[0][0].p95, 0.013);  // nearest rank of 3: the largest
  EXPECT_EQ(column->chaser[0].n, 3);
  EXPECT_NEAR(column->chaser[0].mean, 0.03, 1e-15);
  EXPECT_EQ(column->peak_joint_torque_Nm.max, 7.0);
  EXPECT_NEAR(column->tool_clearance_m.min, 0.13, 1e-15);  // the diverged run's 0.12 left out

  const std::string md = reach_markdown({*column});
  EXPECT_NE(md.find("| position x [mm] | +- 10 | 4 +- 3 | -2.0 +- 8.7 | 13.0 (**not met**) |"), std::string::npos) << md;
  EXPECT_NE(md.find("| position y [mm] | +- 22 | 5 +- 3 | 1.0 +- 0.0 | 5.0 (met) |"), std::string::npos) << md;
  EXPECT_NE(md.find("| angular rate z [deg/s] | +- 0.1 | 0.434 +- 0.314 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| position error [m], 95th percentile | < 0.05 | | 0.040 (met) |"), std::string::npos) << md;
  EXPECT_NE(md.find("| velocity error [m/s], mean +- 1 sigma | < 0.005 | 0.001 +- < 0.001 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| runs flown of runs | | 3 of 5 |"), std::string::npos) << md;
  EXPECT_NE(reach_csv({*column}).find("compliance,reach_max_error_x_m,3,"), std::string::npos);

  // A campaign of a scenario without a capture section has no reach columns: a clear error.
  std::ofstream(dir / "standard.csv") << runs_header(RunColumnSet::kStandard) << '\n';
  EXPECT_FALSE(read_reach_column("hinf", (dir / "standard.csv").string(), error));
  EXPECT_NE(error.find("no column reach_"), std::string::npos) << error;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace chaser::campaign
