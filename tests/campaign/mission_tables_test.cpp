// The whole mission over a campaign (campaign/mission_tables.hpp): hand-made runs.csv rows read back
// (a diverged run left out), the phases not met decoded from their bits in flight order with the
// first one each run broke, and the markdown's and the CSV's counts.
#include "campaign/mission_tables.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "campaign/run_row.hpp"
#include "sim/phase_verdicts.hpp"

namespace chaser::campaign {
namespace {

std::int64_t bit(const char* phase) {
  for (std::size_t i = 0; i < sim::kMissionPhases.size(); ++i)
    if (std::string(sim::kMissionPhases[i]) == phase) return std::int64_t{1} << i;
  return std::int64_t{1} << sim::kMissionPhases.size();  // another phase
}

RunRecord mission_run(std::int64_t index, RunStatus status, std::int64_t not_met) {
  RunRecord r = error_record(RunSetup{});
  r.run = index;
  r.status = status;
  r.mission_met = not_met == 0;
  r.phases_not_met = not_met;
  return r;
}

TEST(MissionTables, CountsThePhasesEachRunBrokeAndTheFirst) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("chaser_mission_tables_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  {
    std::ofstream f(dir / "runs.csv");
    f << runs_header(RunColumnSet::kReach) << '\n';
    for (const RunRecord& r : {mission_run(0, RunStatus::kOk, 0), mission_run(1, RunStatus::kOk, bit("reach")),
                               mission_run(2, RunStatus::kOk, bit("capture") | bit("reach")),
                               mission_run(3, RunStatus::kDiverged, bit("line")),
                               mission_run(4, RunStatus::kOk, bit("escape_retreat") | bit("elsewhere"))})
      f << format_row(r, RunColumnSet::kReach) << '\n';
  }
  std::string error;
  const std::optional<MissionColumn> c = read_mission_column("S1", (dir / "runs.csv").string(), error);
  ASSERT_TRUE(c) << error;
  EXPECT_EQ(c->runs, 5);
  EXPECT_EQ(c->flown, 4);
  EXPECT_EQ(c->mission_met, 1);
  const std::vector<std::pair<std::string, int>> not_met = {{"reach", 2}, {"capture", 1}, {"escape_retreat", 1}, {"other", 1}};
  const std::vector<std::pair<std::string, int>> first = {{"reach", 2}, {"escape_retreat", 1}};
  EXPECT_EQ(c->not_met, not_met);
  EXPECT_EQ(c->first_not_met, first);

  MissionColumn s2 = *c;
  s2.name = "S2";
  s2.not_met = {{"capture", 3}};
  s2.first_not_met = {{"capture", 3}};
  const std::string md = mission_markdown({*c, s2});
  EXPECT_NE(md.find("| | S1 | S2 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| runs (flown to the end) | 5 (4) | 5 (4) |"), std::string::npos) << md;
  EXPECT_NE(md.find("| every phase's requirements met | 1 of 4 | 1 of 4 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| reach not met (first) | 2 (2) | 0 (0) |\n| capture not met (first) | 1 (0) | 3 (3) |"),
            std::string::npos) << md;
  EXPECT_NE(md.find("| other not met (first) | 1 (0) | 0 (0) |"), std::string::npos) << md;
  const std::string csv = mission_csv({*c});
  EXPECT_EQ(csv, "case,phase,runs_not_met,runs_first_not_met,runs_flown\nS1,every,3,3,4\nS1,reach,2,2,4\n"
                 "S1,capture,1,0,4\nS1,escape_retreat,1,1,4\nS1,other,1,0,4\n");
  std::filesystem::remove_all(dir);
}

TEST(MissionTables, RefusesACampaignWithoutTheMissionsColumns) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("chaser_mission_plain_" + std::to_string(::getpid()) + ".csv");
  std::ofstream(path) << "run,status\n0,ok\n";
  std::string error;
  EXPECT_FALSE(read_mission_column("S1", path.string(), error));
  EXPECT_NE(error.find("no column mission_met"), std::string::npos) << error;
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace chaser::campaign
