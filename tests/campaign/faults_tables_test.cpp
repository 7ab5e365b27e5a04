// The comrade-faults preset's tables (campaign/faults_tables.hpp): hand-made runs.csv rows read back
// by fault kind (a diverged run counted in runs, not in the figures), right and wrong names from the
// FDIR's columns, the diagnosis-only runs' Table 1 beside the accommodated, the mean and nearest-rank
// 95th percentile of the delays (campaign/table5.hpp's figure_stats), the mode switches per run (a
// recovery and a supervisor's switches), the pooled column and the targets' verdicts.
#include "campaign/faults_tables.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "campaign/run_row.hpp"

namespace chaser::campaign {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A run of `fault_case` on thruster index `thruster`: detected t_d after the onset (NaN: missed),
// named `named` (kNoThruster: none) t_i after it, Table 1 met or not.
RunRecord fault_run(std::int64_t index, FaultCase fault_case, int thruster, double t_d, int named, double t_i,
                    bool table1, RunStatus status = RunStatus::kOk) {
  RunRecord r = error_record(RunSetup{});
  r.run = index;
  r.status = status;
  r.fault_case = fault_case;
  r.fault_thruster = thruster;
  r.fdir = SchemeOutcome{.detection_s = t_d, .isolation_s = t_i, .isolated = named, .false_alarm = false,
                         .missed = std::isnan(t_d) && fault_case != FaultCase::kNone,
                         .wrong_isolation = named != model::kNoThruster && named != thruster,
                         .glr_max_before_onset = 0.0};
  r.capture = table1;
  return r;
}

std::string write_runs(const std::filesystem::path& dir, const std::string& name, const std::vector<RunRecord>& rows) {
  std::filesystem::create_directories(dir);
  std::ofstream f(dir / name);
  f << runs_header(RunColumnSet::kStandard) << '\n';
  for (const RunRecord& r : rows) f << format_row(r, RunColumnSet::kStandard) << '\n';
  return (dir / name).string();
}

TEST(FaultsTables, ReadsEachKindAndJudgesTheTargets) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("chaser_faults_tables_" + std::to_string(::getpid()));
  constexpr int kT1 = 0, kT2 = 1, kT13 = 12;
  // Mode switches: run 0 recovered (one), run 1's supervisor switched three times.
  RunRecord recovered = fault_run(0, FaultCase::kStuckOpen, kT1, 2.0, kT1, 4.0, true);
  recovered.recovery_s = 6.0;
  RunRecord switching = fault_run(1, FaultCase::kStuckOpen, kT1, 3.0, kT13, 5.0, false);  // the opposite thruster named
  switching.supervisor_switches = 3;
  const std::string accommodated = write_runs(
      dir, "runs.csv",
      {recovered, switching,
       fault_run(2, FaultCase::kStuckClosed, kT1, kNaN, model::kNoThruster, kNaN, true),
       fault_run(3, FaultCase::kLeak, kT1, 10.0, kT1, 12.0, true, RunStatus::kDiverged),
       fault_run(4, FaultCase::kLoss, kT1, 500.0, kT1, 510.0, true)});
  const std::string diagnosed = write_runs(
      dir / "diagnosis-only", "runs.csv",
      {fault_run(0, FaultCase::kStuckOpen, kT1, 2.0, kT1, 4.0, false),
       fault_run(1, FaultCase::kStuckOpen, kT1, 3.0, kT13, 5.0, false),
       fault_run(2, FaultCase::kStuckClosed, kT1, kNaN, model::kNoThruster, kNaN, true),
       fault_run(3, FaultCase::kLeak, kT1, 10.0, kT1, 12.0, true, RunStatus::kDiverged),
       fault_run(4, FaultCase::kLoss, kT1, 500.0, kT1, 510.0, false)});
  FaultsColumn t1{.name = "T1", .kinds = {}};
  std::string error;
  ASSERT_TRUE(add_faults_runs(t1, accommodated, false, error)) << error;
  ASSERT_TRUE(add_faults_runs(t1, diagnosed, true, error)) << error;
  const FaultsCell& open = t1.kinds[0];
  EXPECT_EQ(open.runs, 2);
  EXPECT_EQ(open.right, 1);
  EXPECT_EQ(open.wrong, 1);
  EXPECT_EQ(open.detection_s, (std::vector<double>{2.0, 3.0}));
  EXPECT_EQ(open.isolation_s, (std::vector<double>{4.0}));  // the right one only
  EXPECT_EQ(open.table1_met, 1);
  EXPECT_EQ(open.diagnosed_table1_met, 0);
  EXPECT_EQ(t1.kinds[1].missed, 1);
  EXPECT_EQ(t1.kinds[2].runs, 1);
  EXPECT_EQ(t1.kinds[2].flown, 0);  // diverged: no figures
  EXPECT_EQ(t1.kinds[3].diagnosed_flown, 1);

  FaultsColumn rest{.name = "other 1", .kinds = {}};
  ASSERT_TRUE(add_faults_runs(rest, write_runs(dir / "T2", "runs.csv", {fault_run(0, FaultCase::kStuckOpen, kT2, 1.0, kT2, 2.0, true)}),
                              false, error));
  const FaultFreeFigures free{.runs = 2, .flown = 2, .false_alarms = 0, .table1_met = 2};
  // The others' column pooled from each of theirs, which are listed one by one too.
  FaultsColumn t2 = rest;
  t2.name = "T2";
  const FaultsColumn pooled = pooled_column("other 1", {t2});
  EXPECT_EQ(pooled.kinds[0].right, rest.kinds[0].right);
  EXPECT_EQ(pooled.kinds[0].detection_s, rest.kinds[0].detection_s);
  const std::string with_each = faults_markdown(free, {t1, pooled}, {t2});
  EXPECT_NE(with_each.find("| T2 | 0, 0, 1 of 1 | 0, 0, 0 of 0 | 0, 0, 0 of 0 | 0, 0, 0 of 0 |"), std::string::npos)
      << with_each;
  EXPECT_NE(faults_csv(free, {t1, pooled}, {t2}).find("\nT2,stuck_open,1,1,0,0,0,1,1,1,2,2,1,0,0,0,0\n"), std::string::npos);
  const std::string md = faults_markdown(free, {t1, rest});
  EXPECT_NE(md.find("| stuck open | missed, wrong, right | 0, 1, 1 of 2 | 0, 0, 1 of 1 | 0, 1, 2 of 3 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| stuck open | Table 1 met: accommodated; diagnosis only | 1 of 2; 0 of 2 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| stuck open | mode switches per run, mean / max | 2.00 / 3 | 0.00 / 0 | 1.33 / 3 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| no false alarm in the fault-free runs | 0 of 2 | met |"), std::string::npos) << md;
  EXPECT_NE(md.find("| no stuck-open fault missed | 0 missed | met |"), std::string::npos) << md;
  // 3 right of 5 flown faulty runs (T1's 4 flown and T2's one): short of 99 %.
  EXPECT_NE(md.find("| the right thruster named in >= 99 % of the faulty runs | 60.00 %"), std::string::npos) << md;
  EXPECT_NE(md.find("**not met**"), std::string::npos) << md;
  const std::string csv = faults_csv(free, {t1, rest});
  EXPECT_NE(csv.find("none,none,2,2,0,0,0,0,nan,nan,nan,nan,2,0,0,0,0\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find("T1,stuck_open,2,2,0,0,1,1,2.5,3,4,4,1,2,0,4,3\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find("all,stuck_open,3,3,0,0,1,2,2,3,3,4,2,2,0,4,3\n"), std::string::npos) << csv;

  // A file that is not a runs file is refused with its path.
  std::ofstream(dir / "bad.csv") << "a,b\n1,2\n";
  EXPECT_FALSE(add_faults_runs(t1, (dir / "bad.csv").string(), false, error));
  EXPECT_NE(error.find("bad.csv"), std::string::npos) << error;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace chaser::campaign
