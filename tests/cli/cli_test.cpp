// The `chaser` command as a user meets it: exit codes, messages, files written.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <csignal>
#include <thread>
#include <vector>

#include <sys/wait.h>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/support/command.hpp"

namespace {

using chaser::testing::CommandResult;

CommandResult run_chaser_shell(const std::string& command) { return chaser::testing::run_shell(command); }

CommandResult run_chaser(const std::string& args) {
  return chaser::testing::run_shell(std::string(CHASER_BINARY) + " " + args);
}

TEST(Cli, ValidateAcceptsTheShippedScenario) {
  const CommandResult r = run_chaser("validate scenarios/msr_terminal.yaml");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("valid"), std::string::npos);
}

// Bad input exits with code 2 and names every offending key.
TEST(Cli, ValidateReportsEveryProblemWithExitCode2) {
  const CommandResult r = run_chaser(
      "validate scenarios/msr_terminal.yaml --set chaser.mass_kg=-5 --set control_period_s=0 "
      "--set 'faults=[{thruster: T17, kind: stuck_open, onset_s: 10}]'");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("chaser.mass_kg"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("control_period_s"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("T17"), std::string::npos) << r.output;
}

// A period below the clock's nanosecond rounded to 0 ns, and validation then divided by it: the
// process died of SIGFPE (a held-out fuzz of comrade_sync.yaml found it). Now refused at its key.
TEST(Cli, ValidateRefusesAPeriodBelowOneNanosecondAtItsKey) {
  for (const char* scenario : {"scenarios/comrade_sync.yaml", "scenarios/msr_terminal.yaml"}) {
    const CommandResult r = run_chaser(std::string("validate ") + scenario + " --set control_period_s=1e-320");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("control_period_s: must be in [1e-09, 10] (got 1e-320)"), std::string::npos) << r.output;
  }
}

TEST(Cli, MissingFileAndBadArgumentsExitWith2) {
  EXPECT_EQ(run_chaser("validate no/such/file.yaml").exit_code, 2);
  EXPECT_EQ(run_chaser("run").exit_code, 2);
  EXPECT_EQ(run_chaser("fly scenarios/msr_terminal.yaml").exit_code, 2);
  EXPECT_EQ(run_chaser("run scenarios/msr_terminal.yaml --seed notanumber").exit_code, 2);
}

// A short run writes telemetry.csv (a header plus one row per period) and summary.json.
// A run killed mid-way (SIGKILL while the telemetry is being written) leaves no file that looks
// complete: telemetry.csv and summary.json appear only when the run has finished them; what is on
// disk is telemetry.csv.partial, and an earlier run's files in the same directory (here an npy
// run's, geometry.json included) are gone, not left to pass for this run's. The same command run to
// the end leaves exactly its three files.
TEST(Cli, RunKilledMidwayLeavesNoFileThatLooksComplete) {
  const auto dir = chaser::testing::scratch_path("chaser_cli_killed");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string out = dir.string();
  ASSERT_EQ(run_chaser("run scenarios/msr_terminal.yaml --set duration_s=5 --telemetry npy --out " + out).exit_code, 0);
  ASSERT_TRUE(std::filesystem::exists(dir / "telemetry.npy") && std::filesystem::exists(dir / "summary.json"));
  const pid_t pid = chaser::testing::start_process(
      CHASER_BINARY, {"run", "scenarios/msr_terminal.yaml", "--set", "duration_s=200000", "--out", out});
  const auto partial = dir / "telemetry.csv.partial";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < deadline &&
         !(std::filesystem::exists(partial) && std::filesystem::file_size(partial) > (1u << 20)))
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "the run ended before it was killed";
  EXPECT_TRUE(std::filesystem::exists(partial));
  EXPECT_FALSE(std::filesystem::exists(dir / "telemetry.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir / "summary.json"));
  EXPECT_FALSE(std::filesystem::exists(dir / "telemetry.npy"));
  EXPECT_FALSE(std::filesystem::exists(dir / "geometry.json"));

  std::filesystem::remove_all(dir);
  ASSERT_EQ(run_chaser("run scenarios/msr_terminal.yaml --set duration_s=5 --telemetry npy --out " + out).exit_code, 0);
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(dir)) files.push_back(e.path().filename().string());
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, (std::vector<std::string>{"geometry.json", "summary.json", "telemetry.npy"}));
  std::filesystem::remove_all(dir);
}

// --channels keeps the named channels (and t_s); a pattern that matches nothing is a typo: exit 2.
TEST(Cli, RunWritesTheChosenChannelsAndRefusesUnknownOnes) {
  const auto dir = chaser::testing::scratch_path("chaser_cli_channels");
  std::filesystem::remove_all(dir);
  const CommandResult r = run_chaser("run scenarios/msr_terminal.yaml --set duration_s=1 --channels 'r_lvlh_?_m,glr_*' --out " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream telemetry(dir / "telemetry.csv");
  std::string header;
  std::getline(telemetry, header);
  EXPECT_EQ(header, "t_s,r_lvlh_x_m,r_lvlh_y_m,r_lvlh_z_m,glr_position,glr_attitude,glr_deficit,glr_bank,glr_rate_check");
  const CommandResult bad = run_chaser("run scenarios/msr_terminal.yaml --channels r_lvhl_x_m --out " + dir.string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.output.find("--channels: r_lvhl_x_m match no telemetry channel"), std::string::npos) << bad.output;
  std::filesystem::remove_all(dir);
}

// The plotting scripts read either telemetry format (python/chaser_telemetry.py) and draw every
// figure from a real run. Skipped where /usr/bin/python3 lacks numpy or matplotlib.
TEST(Cli, PlotScriptsReadCsvAndNpyTelemetry) {
  if (run_chaser_shell("/usr/bin/python3 -c 'import numpy, matplotlib'").exit_code != 0) GTEST_SKIP() << "no numpy/matplotlib";
  for (const std::string format : {"csv", "npy"}) {
    const auto dir = chaser::testing::scratch_path("chaser_cli_plots_" + format);
    std::filesystem::remove_all(dir);
    ASSERT_EQ(run_chaser("run scenarios/msr_terminal.yaml --set duration_s=30 --telemetry " + format + " --out " +
                         dir.string()).exit_code, 0);
    for (const char* script : {"python/plot_run.py", "python/plot_fdi.py"}) {
      const CommandResult r = run_chaser_shell(std::string("/usr/bin/python3 ") + script + " " + dir.string());
      EXPECT_EQ(r.exit_code, 0) << format << " " << script << ": " << r.output;
    }
    for (const char* png : {"trajectory.png", "attitude.png", "thrusters.png", "fdi.png"})
      EXPECT_TRUE(std::filesystem::exists(dir / png)) << format << " " << png;
    std::filesystem::remove_all(dir);
  }
}

TEST(Cli, RunWritesTelemetryAndSummary) {
  const auto dir = chaser::testing::scratch_path("chaser_cli_test");
  std::filesystem::remove_all(dir);
  const CommandResult r =
      run_chaser("run scenarios/msr_terminal.yaml --set duration_s=20 --seed 7 --out " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream telemetry(dir / "telemetry.csv");
  std::string line;
  int lines = 0;
  std::string header;
  while (std::getline(telemetry, line)) {
    if (lines == 0) header = line;
    ++lines;
  }
  EXPECT_EQ(lines, 1 + 200);  // 20 s at T = 0.1 s
  for (const char* channel : {"t_s", "r_lvlh_x_m", "v_lvlh_z_mps", "q_inertial_from_body_w", "omega_body_y_radps",
                              "r_est_lvlh_x_m", "force_demand_lvlh_x_N", "torque_demand_body_z_Nm", "ton_cmd_1",
                              "ton_cmd_8", "ton_real_8", "propellant_used_kg"})
    EXPECT_NE(header.find(channel), std::string::npos) << channel;
  std::ifstream summary_file(dir / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(summary_file);
  EXPECT_EQ(summary["seed"], 7);
  EXPECT_EQ(summary["scenario_hash"].get<std::string>().size(), 16u);
  for (const char* key : {"chaser_version", "final_position_error_m", "corridor_kept", "capture_achieved",
                          "propellant_used_kg", "max_attitude_error_deg", "wall_s"})
    EXPECT_TRUE(summary.contains(key)) << key;
  // The wall time's parts (design, loop, files) are measured in turn inside it.
  const double parts = summary["wall_design_s"].get<double>() + summary["wall_loop_s"].get<double>() +
                       summary["wall_files_s"].get<double>();
  EXPECT_GT(summary["wall_design_s"].get<double>(), 0.0);
  EXPECT_GT(summary["wall_loop_s"].get<double>(), 0.0);
  EXPECT_LE(parts, summary["wall_s"].get<double>());
  EXPECT_GE(parts, 0.5 * summary["wall_s"].get<double>());
  std::filesystem::remove_all(dir);
}

}  // namespace

namespace {

// chaser fdi design prints the design figures and writes the design as JSON; the assigned
// eigenvalues are the paper's (0.85 ... 0.95), which the library reaches to 1e-9.
TEST(Cli, FdiDesignWritesTheDesign) {
  const auto path = chaser::testing::scratch_path("chaser_fdi_design.json");
  for (const char* model : {"position", "attitude"}) {
    const CommandResult r =
        run_chaser(std::string("fdi design scenarios/msr_terminal.yaml --model ") + model + " --out " + path.string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("achieved eigenvalues: 0.8500 0.8700 0.8900 0.9100 0.9300 0.9500"), std::string::npos)
        << r.output;
    std::ifstream in(path);
    const nlohmann::json design = nlohmann::json::parse(in);
    EXPECT_FALSE(design.empty());
  }
  std::filesystem::remove(path);
  EXPECT_EQ(run_chaser("fdi design scenarios/msr_terminal.yaml --model velocity").exit_code, 2);
  EXPECT_EQ(run_chaser("fdi design scenarios/msr_terminal.yaml --set chaser.mass_kg=0").exit_code, 2);
  // COMRADE's 24 thrusters: no design of the published schemes, whose columns are eight thrusters.
  const CommandResult comrade = run_chaser("fdi design scenarios/comrade_envisat.yaml");
  EXPECT_EQ(comrade.exit_code, 2);
  EXPECT_NE(comrade.output.find("watch exactly 8 active thrusters; scenarios/comrade_envisat.yaml starts with 24"),
            std::string::npos)
      << comrade.output;
}

}  // namespace

namespace {

// chaser thrusters on MSR: branch A (the set that flies at the start) and branch B (after a fault
// in group A) are analysed; both push and turn in every direction; neither tolerates every single
// loss (model/thruster_set_analysis tests: T1, T2, T3, T5, T6, T7 each break branch A's span). The
// JSON holds the same figures: +Fx of branch A is 31.3 N (tests/model/thruster_set_analysis_test).
TEST(Cli, ThrustersAnalysesTheStartAndRecoverySets) {
  const auto json = chaser::testing::scratch_path("chaser_thrusters_test.json");
  const CommandResult r = run_chaser("thrusters scenarios/msr_terminal.yaml --json " + json.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("the set that flies at the start (T1, T2, T3, T4, T5, T6, T7, T8)"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("after a fault in group A"), std::string::npos) << r.output;
  std::ifstream in(json);
  const nlohmann::json j = nlohmann::json::parse(in);
  ASSERT_EQ(j["sets"].size(), 2u);
  EXPECT_EQ(j["thrusters"], 16);
  for (const auto& set : j["sets"]) {
    EXPECT_TRUE(set["spans"].get<bool>());
    EXPECT_FALSE(set["tolerates_single_loss"].get<bool>());
    EXPECT_EQ(set["configuration_matrix_columns"].size(), 8u);
  }
  EXPECT_NEAR(j["sets"][0]["attainable"][0].get<double>(), 31.3, 0.05);
  EXPECT_EQ(j["sets"][1]["thrusters"][0], "T9");
  std::filesystem::remove(json);
}

// With fdi.recovery: exclude (COMRADE's 24, which tolerate any single loss) the sets flown are the
// start set's single losses: one report, its "without Tn" rows saying so, not one per thruster.
TEST(Cli, ThrustersUnderExclusionReportTheStartSetOnce) {
  const CommandResult r = run_chaser("thrusters scenarios/comrade_envisat.yaml --set fdi.recovery=exclude");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("the set that flies at the start (fdi.recovery: exclude flies each of its 'without Tn' sets)"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("the set that flies without"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("Tolerates any single thruster loss (every N-1 set spans):  yes"), std::string::npos)
      << r.output;
}

// chaser control design on ENVISAT: six loops, each stable on the true plant, its achieved norm (the
// sweep) at or below the gamma its controller was formed at, and its authority the smaller of the
// +/- pure force of `chaser thrusters` divided by the mass (an independent path to the same LP).
TEST(Cli, ControlDesignChecksSixLoops) {
  const auto json = chaser::testing::scratch_path("chaser_control_design_test.json");
  const auto thrusters = chaser::testing::scratch_path("chaser_control_thrusters.json");
  const CommandResult r = run_chaser("control design scenarios/comrade_envisat.yaml --out " + json.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("rz"), std::string::npos) << r.output;
  ASSERT_EQ(run_chaser("thrusters scenarios/comrade_envisat.yaml --json " + thrusters.string()).exit_code, 0);
  std::ifstream in(json), tin(thrusters);
  const nlohmann::json j = nlohmann::json::parse(in), t = nlohmann::json::parse(tin);
  ASSERT_EQ(j["axes"].size(), 6u);
  EXPECT_TRUE(j["ok"].get<bool>());
  for (const auto& axis : j["axes"]) {
    EXPECT_EQ(axis["status"], "ok") << axis["axis"];
    EXPECT_TRUE(axis["stable"].get<bool>()) << axis["axis"];
    EXPECT_LE(axis["closed_loop_norm"].get<double>(), axis["gamma"].get<double>() * (1.0 + 1e-9)) << axis["axis"];
    // M = 2 and gamma < 1 keep |S| below 2, so PM >= 2 asin(1/4) = 29 deg (S&P eq. 2.41).
    EXPECT_GT(axis["margins"]["phase_margin_deg"].get<double>(), 29.0) << axis["axis"];
    EXPECT_GT(axis["frequency_response"]["omega_radps"].size(), 100u);
  }
  // control.hinf.robustness: 5 points per range; x, y, z see the slosh (5^3 points), the rotations the
  // slosh and the stowed arm (5^4); all stable.
  EXPECT_TRUE(j["robust"].get<bool>());
  EXPECT_EQ(j["axes"][0]["robustness"]["points"], 125);
  EXPECT_EQ(j["axes"][5]["robustness"]["points"], 625);
  for (const auto& axis : j["axes"]) EXPECT_EQ(axis["robustness"]["unstable"], 0) << axis["axis"];
  // AB13MD's mu bound on each loop's gain x delay box: a nominally stable centre, a curve per loop,
  // a complex bound at least the mixed (gain real) one, and a box the grid finds stable with room
  // (docs/control.md, "Structured singular value") guaranteed with room by the bound too.
  EXPECT_NE(r.output.find("AB13MD"), std::string::npos) << r.output;
  for (const auto& axis : j["axes"]) {
    const auto& mu = axis["mu"];
    EXPECT_EQ(mu["status"], "ok") << axis["axis"];
    EXPECT_TRUE(mu["nominal_stable"].get<bool>()) << axis["axis"];
    EXPECT_EQ(mu["mu_complex"].size(), mu["omega_radps"].size());
    EXPECT_GT(mu["omega_radps"].size(), 100u);
    EXPECT_GE(mu["peak_complex"].get<double>(), mu["peak_mixed"].get<double>() * (1.0 - 1e-5)) << axis["axis"];
    EXPECT_GT(mu["margin_complex"].get<double>(), 1.0) << axis["axis"];
  }
  const auto& attainable = t["sets"][0]["attainable"];
  const double fx = std::min(attainable[0].get<double>(), attainable[1].get<double>());
  EXPECT_NEAR(j["axes"][0]["authority"].get<double>(), fx / 1600.0, 1e-9 * fx);
  EXPECT_FALSE(j.contains("stabilisation"));  // no capture.stabilise: no stabilisation loops
  std::filesystem::remove(json);
  std::filesystem::remove(thrusters);
}

// With capture.stabilise, the stabilisation's three loops too (COMRADE 2018 sec. 6.1.4), checked over
// the composite inertia's uncertainty as the six are over theirs: the grid and the mu bound (measured
// margin 4.77 at 20 %). The uncertainty is a scenario key, range-checked.
TEST(Cli, ControlDesignChecksTheStabilisationsLoops) {
  const auto json = chaser::testing::scratch_path("chaser_control_design_capture.json");
  const CommandResult r = run_chaser("control design scenarios/comrade_capture.yaml --out " + json.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("The stabilisation's loops"), std::string::npos) << r.output;
  std::ifstream in(json);
  const nlohmann::json j = nlohmann::json::parse(in);
  ASSERT_EQ(j["stabilisation"].size(), 3u);
  EXPECT_TRUE(j["stabilisation_robust"].get<bool>());
  for (const auto& loop : j["stabilisation"]) {
    EXPECT_EQ(loop["authority_unit"], "N m") << loop["axis"];
    EXPECT_EQ(loop["robustness"]["unstable"], 0) << loop["axis"];
    // The gain's low end: the thrust 1 % low (control.hinf.robustness.thrust_uncertainty) times the
    // inertia 20 % off.
    EXPECT_NEAR(loop["robustness"]["box"]["gain"][0].get<double>(), 0.99 * 0.8, 1e-12) << loop["axis"];
    EXPECT_GT(loop["mu"]["margin_mixed"].get<double>(), 1.0) << loop["axis"];
  }
  const CommandResult bad = run_chaser("control design scenarios/comrade_capture.yaml --set "
                                       "capture.stabilise.inertia_uncertainty=0.95");
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("capture.stabilise.inertia_uncertainty"), std::string::npos) << bad.output;
  std::filesystem::remove(json);
}

// A scenario that flies the LQR loops and has no control.hinf (MSR): their gains and poles, nothing
// else (exit 0); the JSON's poles are the table's. A bandwidth past the period's Nyquist frequency is
// refused by the loader with its key path.
TEST(Cli, ControlDesignShowsTheLqrLoopsAndRefusesWhatItCannotDesign) {
  const auto json = chaser::testing::scratch_path("chaser_lqr_design.json");
  const CommandResult msr = run_chaser("control design scenarios/msr_terminal.yaml --out " + json.string());
  ASSERT_EQ(msr.exit_code, 0) << msr.output;
  EXPECT_NE(msr.output.find("the LQR loops flown"), std::string::npos) << msr.output;
  EXPECT_NE(msr.output.find("position  q_pos 16, q_vel 12000, r_force 1"), std::string::npos) << msr.output;
  EXPECT_EQ(msr.output.find("H-infinity"), std::string::npos) << msr.output;
  const nlohmann::json report = nlohmann::json::parse(std::ifstream(json));
  ASSERT_EQ(report["lqr"]["position"]["poles"].size(), 3u);
  for (const auto& pole : report["lqr"]["position"]["poles"]) {
    EXPECT_NEAR(pole["natural_radps"].get<double>(), 0.04, 0.002);  // docs/gnc.md's design, w_n = 0.04 rad/s
    EXPECT_LT(pole["re"].get<double>(), 0.0);
  }
  EXPECT_TRUE(report["lqr"]["attitude"]["stable"].get<bool>());
  std::filesystem::remove(json);
  const CommandResult fast =
      run_chaser("control design scenarios/comrade_envisat.yaml --set control.hinf.rotation.bandwidth_radps=40");
  EXPECT_EQ(fast.exit_code, 2) << fast.output;
  EXPECT_NE(fast.output.find("control.hinf.rotation.bandwidth_radps"), std::string::npos) << fast.output;
}

// ENVISAT flown with the H-infinity loops (control.law: hinf) and with each allocation norm: every
// combination captures inside the corridor (one seed each; docs/control.md, "Flying the loops",
// and docs/gnc.md, "Thrust allocation", give the campaigns). MSR has no control.hinf: refused.
TEST(Cli, EnvisatFliesEveryLawAndNorm) {
  const auto out = chaser::testing::scratch_path("chaser_law_norm_test");
  for (const char* law : {"lqr", "hinf"}) {
    for (const char* norm : {"1", "2", "inf"}) {
      const std::string what = std::string(law) + ", p = " + norm;
      const CommandResult r = run_chaser("run scenarios/comrade_envisat.yaml --telemetry none --out " + out.string() +
                                         " --set control.law=" + law + " --set control.allocation_norm=" + norm);
      ASSERT_EQ(r.exit_code, 0) << what << "\n" << r.output;
      std::ifstream in(out / "summary.json");
      const nlohmann::json j = nlohmann::json::parse(in);
      EXPECT_TRUE(j["capture_achieved"].get<bool>()) << what;
      EXPECT_TRUE(j["corridor_kept"].get<bool>()) << what;
      EXPECT_FALSE(j["diverged"].get<bool>()) << what;
    }
  }
  std::filesystem::remove_all(out);
  const CommandResult msr = run_chaser("run scenarios/msr_terminal.yaml --set control.law=hinf");
  EXPECT_EQ(msr.exit_code, 2) << msr.output;
  EXPECT_NE(msr.output.find("control.law: hinf needs a control.hinf section"), std::string::npos) << msr.output;
}

// A set that cannot span is refused by the loader before any analysis: exit 2, the key named.
TEST(Cli, ThrustersRefusesABadScenarioWithExitCode2) {
  const CommandResult r = run_chaser(
      "thrusters scenarios/msr_terminal.yaml --set 'thrusters.list.2.direction_body=[1,0.36,-0.36]'");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("thrusters.list"), std::string::npos) << r.output;
}

}  // namespace
