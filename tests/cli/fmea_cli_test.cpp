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

namespace fmea_cli_test {

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
  const fs::path dir = chaser::testing::scratch_path("chaser_fmea_cli_" + name);
  fs::remove_all(dir);
  return dir;
}

// The shipped scenario: header + (nominal + 24 Table 2 + 16 Table 5 rows) for the baseline and its
// two configurations (Schemes I and II; its `faults` is empty); the markdown has the paper's tables,
// the ranking and the comparison of the layouts.
TEST(FmeaCli, ShippedScenarioWritesOneRowPerLayoutAndMode) {
  const fs::path out = fresh_dir("ok");
  const CommandResult r = chaser("fmea scenarios/manual_rvd.yaml --threads 2 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("3 layouts x 41 modes = 123 rows, 110 flown"), std::string::npos) << r.output;
  const std::vector<std::string> csv = lines(read_file(out / "fmea.csv"));
  ASSERT_EQ(csv.size(), 1u + 3u * 41u);
  EXPECT_EQ(csv[0].rfind("configuration,mode,table,failed,x_pos,x_neg,y_pos,y_neg,z_pos,z_neg,total_pulses,k_p,", 0), 0u);
  EXPECT_EQ(csv[1].rfind("baseline,nominal,nominal,,", 0), 0u) << csv[1];
  EXPECT_EQ(csv[2].rfind("baseline,d1,table2,d1,", 0), 0u) << csv[2];
  EXPECT_EQ(csv[26].rfind("baseline,d1/d1~+e1/e1~,table5,d1 d1~ e1 e1~,", 0), 0u) << csv[26];
  EXPECT_EQ(csv[42].rfind("scheme_I,nominal,", 0), 0u) << csv[42];
  EXPECT_EQ(csv[83].rfind("scheme_II,nominal,", 0), 0u) << csv[83];
  const std::string md = read_file(out / "fmea.md");
  for (const char* heading : {"## Table 4", "## Table 5", "## Table 6", "## Ranking by risk", "## Reconfiguration",
                              "### Table 6 with layout scheme_II"})
    EXPECT_NE(md.find(heading), std::string::npos) << heading;
  EXPECT_FALSE(fs::exists(out / "history"));  // only with --history
  EXPECT_FALSE(fs::exists(out / "optimize.csv"));  // only with --optimize
}

// --optimize flies every combination of the free choices (3 x 2 x 2 x 2 x 2 = 48 in the shipped
// scenario) and writes them all, best first; --history writes one file per layout and mode, listed
// in history/index.csv, and python/plot_invsim.py draws them.
TEST(FmeaCli, OptimizeAndHistoryForThePlots) {
  const fs::path out = fresh_dir("opt");
  const CommandResult r = chaser("fmea scenarios/manual_rvd.yaml --optimize --history --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("--optimize: 48 candidates x 41 modes, 939 flown"), std::string::npos) << r.output;
  const std::vector<std::string> ranked = lines(read_file(out / "optimize.csv"));
  ASSERT_EQ(ranked.size(), 1u + 48u);
  EXPECT_EQ(ranked[1].rfind("1,\"attitude_thrust=", 0), 0u) << ranked[1];
  EXPECT_NE(read_file(out / "fmea.md").find("## Optimisation"), std::string::npos);
  const std::vector<std::string> index = lines(read_file(out / "history" / "index.csv"));
  ASSERT_EQ(index.size(), 1u + 3u * 41u);
  EXPECT_EQ(index[0], "configuration,mode,file,draws,draw_seed");
  EXPECT_EQ(index[26], "baseline,d1/d1~+e1/e1~,baseline/25_d1-d1n+e1-e1n.csv,1,");  // smooth: one run, no noise
  const std::vector<std::string> history = lines(read_file(out / "history" / "baseline" / "00_nominal.csv"));
  ASSERT_EQ(history.size(), 1u + 1300u);  // one row per 1 s step of the 1300 s run
  EXPECT_EQ(history[0].rfind("t_s,x_m,y_m,z_m,", 0), 0u);
  const CommandResult plot = chaser::testing::run_shell("/usr/bin/python3 python/plot_invsim.py " + out.string() +
                                                        " --modes nominal d1/d2~+e2/e1~");
  ASSERT_EQ(plot.exit_code, 0) << plot.output;
  EXPECT_TRUE(fs::exists(out / "plots" / "baseline" / "00_nominal.png")) << plot.output;
  EXPECT_TRUE(fs::exists(out / "plots" / "scheme_II" / "31_d1-d2n+e2-e1n.png")) << plot.output;
}

// Under the paper reading with several noise draws the index names the draw each history shows
// (the worst: invsim/fmea.hpp) and its seed, and the summary counts its flight; the plotter says so in the title and does not hold the
// draw's pulse totals against fmea.csv's means (no warning), where a single draw's must match.
TEST(FmeaCli, HistoriesOfNoiseDrawsNameTheDrawAndPlotWithoutMismatch) {
  const fs::path out = fresh_dir("draws");
  const CommandResult r = chaser("fmea scenarios/manual_rvd.yaml --history --set pulses.reading=paper "
                                 "--set pulses.paper.measurement_noise.draws=3 --set pulses.paper.measurement_noise.seed=4 "
                                 "--out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // Every row flown (no sharing between layouts with histories), and its worst draw once more.
  EXPECT_NE(r.output.find("= 123 rows, 123 flown x 3 noise draws, and 123 worst draws again for their histories in "),
            std::string::npos) << r.output;
  const std::vector<std::string> index = lines(read_file(out / "history" / "index.csv"));
  ASSERT_EQ(index.size(), 1u + 3u * 41u);
  for (std::size_t i = 1; i < index.size(); ++i) {
    const std::string tail = index[i].substr(index[i].rfind(".csv,") + 5);
    EXPECT_TRUE(tail == "3,4" || tail == "3,5" || tail == "3,6") << index[i];
  }
  const CommandResult plot = chaser::testing::run_shell("/usr/bin/python3 python/plot_invsim.py " + out.string() +
                                                        " --configuration baseline --modes nominal e1/e1~ 2>&1");
  ASSERT_EQ(plot.exit_code, 0) << plot.output;
  EXPECT_EQ(plot.output.find("warning"), std::string::npos) << plot.output;
  EXPECT_TRUE(fs::exists(out / "plots" / "baseline" / "13_e1-e1n.png")) << plot.output;
}

// python/plot_invsim.py on a small fake fmea directory (2 layouts x 3 modes: classes I-III, one
// out of view): 6 mode plots, 2 overviews and the layouts' comparison; a directory that is not an
// fmea output is exit 2 naming the missing file.
TEST(FmeaCli, PlotterDrawsAFakeDirectoryAndRejectsAWrongOne) {
  const fs::path fake = fresh_dir("fake");
  ASSERT_EQ(chaser::testing::run_shell("/usr/bin/python3 python/tests/make_fake_fmea.py " + fake.string()).exit_code, 0);
  const CommandResult plot = chaser::testing::run_shell("/usr/bin/python3 python/plot_invsim.py " + fake.string());
  ASSERT_EQ(plot.exit_code, 0) << plot.output;
  int pngs = 0;
  for (const auto& entry : fs::recursive_directory_iterator(fake / "plots")) pngs += entry.path().extension() == ".png";
  EXPECT_EQ(pngs, 9) << plot.output;
  EXPECT_TRUE(fs::exists(fake / "plots" / "configurations.png"));
  const fs::path empty = fresh_dir("empty");
  fs::create_directories(empty);
  const CommandResult wrong = chaser::testing::run_shell("/usr/bin/python3 python/plot_invsim.py " + empty.string());
  EXPECT_EQ(wrong.exit_code, 2) << wrong.output;
  EXPECT_NE(wrong.output.find("fmea.csv"), std::string::npos) << wrong.output;
}

// Without free choices, --optimize is bad input (exit 2), not an empty search; an empty list of
// choices is a scenario error naming its key.
TEST(FmeaCli, OptimizeWithoutChoicesIsBadInput) {
  const fs::path out = fresh_dir("noopt");
  fs::create_directories(out);
  const std::string shipped = read_file("scenarios/manual_rvd.yaml");
  const auto cut = shipped.find("\noptimize:");
  ASSERT_NE(cut, std::string::npos);
  const fs::path scenario = out / "no_choices.yaml";
  std::ofstream(scenario) << shipped.substr(0, cut) << "\nfaults: []\n";
  CommandResult r = chaser("fmea " + scenario.string() + " --optimize --out " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("optimize.choices"), std::string::npos) << r.output;
  EXPECT_EQ(chaser("fmea " + scenario.string() + " --out " + out.string()).exit_code, 0);
  r = chaser("fmea scenarios/manual_rvd.yaml --set 'optimize.choices=[]' --optimize --out " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("optimize.choices: must be a list of free choices with 1 to"), std::string::npos)
      << r.output;
}

// --three-axis adds the 64 six-thruster modes to every layout (3 x 105 rows), after Table 5.
TEST(FmeaCli, ThreeAxisModesAddSixtyFourRowsPerLayout) {
  const fs::path out = fresh_dir("three");
  const CommandResult r = chaser("fmea scenarios/manual_rvd.yaml --three-axis --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::vector<std::string> csv = lines(read_file(out / "fmea.csv"));
  ASSERT_EQ(csv.size(), 1u + 3u * 105u);
  EXPECT_EQ(csv[42].rfind("baseline,d1/d1~+e1/e1~+f1/f1~,three_axis,d1 d1~ e1 e1~ f1 f1~,", 0), 0u) << csv[42];
  EXPECT_NE(read_file(out / "fmea.md").find("## Three-axis faults"), std::string::npos);
}

// --nominal-only flies the nominal case of each layout alone (what the calibration reads), and is
// bad input with --optimize or --three-axis.
TEST(FmeaCli, NominalOnlyFliesOneRowPerLayout) {
  const fs::path out = fresh_dir("nominal_only");
  const CommandResult r = chaser("fmea scenarios/manual_rvd.yaml --nominal-only --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::vector<std::string> csv = lines(read_file(out / "fmea.csv"));
  ASSERT_EQ(csv.size(), 1u + 3u);
  EXPECT_EQ(csv[1].rfind("baseline,nominal,nominal,,41,28,37,46,8,44,", 0), 0u) << csv[1];
  const CommandResult bad = chaser("fmea scenarios/manual_rvd.yaml --nominal-only --three-axis --out " + out.string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.output.find("--nominal-only"), std::string::npos) << bad.output;
}

// A user fault set in the scenario adds one last row, named "scenario".
TEST(FmeaCli, ScenarioFaultsAddARow) {
  const fs::path out = fresh_dir("user");
  const CommandResult r = chaser("fmea scenarios/manual_rvd.yaml --set 'faults=[d1, e2~]' --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::vector<std::string> csv = lines(read_file(out / "fmea.csv"));
  ASSERT_EQ(csv.size(), 1u + 3u * 42u);
  EXPECT_EQ(csv[42].rfind("baseline,scenario,scenario,d1 e2~,", 0), 0u) << csv[42];
  EXPECT_EQ(csv.back().rfind("scheme_II,scenario,scenario,d1 e2~,", 0), 0u) << csv.back();
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

// fmea.md's reading paragraph names the paper reading's lateral design: y held (shipped), a return,
// or a brake then a return (--nominal-only: the nominal case alone, 20 draws, a fraction of a second).
TEST(FmeaCli, PaperReadingNamesTheLateralDesign) {
  const auto paragraph = [](const std::string& sets) {
    const fs::path out = fresh_dir("lateral");
    const CommandResult r =
        chaser("fmea scenarios/manual_rvd.yaml --nominal-only --set pulses.reading=paper " + sets + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return read_file(out / "fmea.md");
  };
  EXPECT_NE(paragraph("").find("; y and z held at 0;"), std::string::npos);
  EXPECT_NE(paragraph("--set pulses.paper.lateral_time_constant_s=50")
                .find("; y and z return to the axis with a 50 s time constant;"),
            std::string::npos);
  EXPECT_NE(paragraph("--set pulses.paper.lateral_time_constant_s=200 --set pulses.paper.lateral_brake_mps2=0.0075")
                .find("; y and z brake their initial drift at 0.0075 m/s^2, then return to the axis with a 200 s "
                      "time constant;"),
            std::string::npos);
}

// The paper reading (docs/invsim.md, "Readings of App. B"): fmea.md prints Zhou 2018's figures
// beside ours and names the reading; the rows with their noise draws are the same on one worker;
// python/invsim_study/calibrate_invsim.py, run again on the nominal case,
// finds the scenario's shipped pulses.paper block (--check, exit 0: the calibration is repeatable);
// an unknown reading is exit 2 naming the key and the allowed values.
TEST(FmeaCli, PaperReadingPrintsThePaperBesideUsAndItsCalibrationIsRepeatable) {
  const fs::path out = fresh_dir("paper");
  const CommandResult r = chaser("fmea scenarios/manual_rvd.yaml --set pulses.reading=paper --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // Noise draws included, the rows do not depend on the number of workers.
  const fs::path one = fresh_dir("paper1");
  ASSERT_EQ(chaser("fmea scenarios/manual_rvd.yaml --set pulses.reading=paper --threads 1 --out " + one.string()).exit_code, 0);
  EXPECT_EQ(read_file(one / "fmea.csv"), read_file(out / "fmea.csv"));
  EXPECT_NE(r.output.find("x 20 noise draws"), std::string::npos) << r.output;
  const std::string md = read_file(out / "fmea.md");
  EXPECT_NE(md.find("Reading `paper`"), std::string::npos);
  EXPECT_NE(md.find(" (114) | "), std::string::npos);   // Table 4's nominal x+
  EXPECT_NE(md.find(" (1131) | "), std::string::npos);  // f2~'s z-
  EXPECT_NE(md.find("uncontrollable (`---`)"), std::string::npos);
  const CommandResult cal = chaser::testing::run_shell("/usr/bin/python3 python/invsim_study/calibrate_invsim.py "
                                                       "scenarios/manual_rvd.yaml --check --chaser " +
                                                       std::string(CHASER_BINARY));
  EXPECT_EQ(cal.exit_code, 0) << cal.output;
  EXPECT_NE(cal.output.find("check: the scenario's pulses.paper matches"), std::string::npos) << cal.output;
  const CommandResult bad = chaser("fmea scenarios/manual_rvd.yaml --set pulses.reading=chatter --out " + out.string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.output.find("pulses.reading: must be smooth or paper (got 'chatter')"), std::string::npos) << bad.output;
}

}  // namespace fmea_cli_test
