// chaser fmea as a user meets it: the shipped scenario gives the two files with one row per mode,
// a bad key exits 2 naming it, and the files do not depend on --threads.
#include <gtest/gtest.h>

#include "tests/support/command.hpp"

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

using chaser::testing::CommandResult;
using chaser::testing::read_file;

CommandResult chaser(const std::string& args) {
  return chaser::testing::run_shell(std::string(CHASER_BINARY) + " " + args);
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("chaser_fmea_cli_" + name);
  fs::remove_all(dir);
  return dir;
}

// The shipped scenario: header + nominal + 24 Table 2 + 16 Table 5 rows (its `faults` is empty);
// the markdown has the paper's tables and the ranking.
TEST(FmeaCli, ShippedScenarioWritesOneRowPerMode) {
  const fs::path out = fresh_dir("ok");
  const CommandResult r = chaser("fmea scenarios/manual_rvd.yaml --threads 2 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("41 modes"), std::string::npos) << r.output;
  const std::vector<std::string> csv = lines(read_file(out / "fmea.csv"));
  ASSERT_EQ(csv.size(), 42u);
  EXPECT_EQ(csv[0].rfind("mode,table,failed,x_pos,x_neg,y_pos,y_neg,z_pos,z_neg,total_pulses,k_p,", 0), 0u);
  EXPECT_EQ(csv[1].rfind("nominal,nominal,,", 0), 0u) << csv[1];
  EXPECT_EQ(csv[2].rfind("d1,table2,d1,", 0), 0u) << csv[2];
  EXPECT_EQ(csv[26].rfind("d1/d1~+e1/e1~,table5,d1 d1~ e1 e1~,", 0), 0u) << csv[26];
  const std::string md = read_file(out / "fmea.md");
  for (const char* heading : {"## Table 4", "## Table 5", "## Table 6", "## Ranking by risk"})
    EXPECT_NE(md.find(heading), std::string::npos) << heading;
}

// A user fault set in the scenario adds one last row, named "scenario".
TEST(FmeaCli, ScenarioFaultsAddARow) {
  const fs::path out = fresh_dir("user");
  const CommandResult r = chaser("fmea scenarios/manual_rvd.yaml --set 'faults=[d1, e2~]' --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::vector<std::string> csv = lines(read_file(out / "fmea.csv"));
  ASSERT_EQ(csv.size(), 43u);
  EXPECT_EQ(csv.back().rfind("scenario,scenario,d1 e2~,", 0), 0u) << csv.back();
}

TEST(FmeaCli, BadInputExitsWith2AndNamesTheKey) {
  const fs::path out = fresh_dir("bad");
  CommandResult r = chaser("fmea scenarios/manual_rvd.yaml --set sensor.bogus_key=1 --out " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("sensor.bogus_key"), std::string::npos) << r.output;
  r = chaser("fmea scenarios/manual_rvd.yaml --set pulses.time_sensitivity=-1 --out " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("pulses.time_sensitivity"), std::string::npos) << r.output;
  r = chaser("fmea scenarios/manual_rvd.yaml --threads 0 --out " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--threads"), std::string::npos) << r.output;
  EXPECT_EQ(chaser("fmea").exit_code, 2);
  EXPECT_FALSE(fs::exists(out / "fmea.csv"));
}

// Every mode is an independent run, so the files are byte-identical whatever the worker count.
TEST(FmeaCli, OutputDoesNotDependOnThreads) {
  const fs::path one = fresh_dir("t1");
  const fs::path two = fresh_dir("t2");
  ASSERT_EQ(chaser("fmea scenarios/manual_rvd.yaml --threads 1 --out " + one.string()).exit_code, 0);
  ASSERT_EQ(chaser("fmea scenarios/manual_rvd.yaml --threads 2 --out " + two.string()).exit_code, 0);
  EXPECT_EQ(read_file(one / "fmea.csv"), read_file(two / "fmea.csv"));
  EXPECT_EQ(read_file(one / "fmea.md"), read_file(two / "fmea.md"));
  EXPECT_FALSE(read_file(one / "fmea.csv").empty());
}

}  // namespace
