// The `chaser` command as a user meets it: exit codes, messages, files written.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/support/command.hpp"

namespace {

using chaser::testing::CommandResult;

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

TEST(Cli, MissingFileAndBadArgumentsExitWith2) {
  EXPECT_EQ(run_chaser("validate no/such/file.yaml").exit_code, 2);
  EXPECT_EQ(run_chaser("run").exit_code, 2);
  EXPECT_EQ(run_chaser("fly scenarios/msr_terminal.yaml").exit_code, 2);
  EXPECT_EQ(run_chaser("run scenarios/msr_terminal.yaml --seed notanumber").exit_code, 2);
}

// A short run writes telemetry.csv (a header plus one row per period) and summary.json.
TEST(Cli, RunWritesTelemetryAndSummary) {
  const auto dir = std::filesystem::temp_directory_path() / "chaser_cli_test";
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
  std::filesystem::remove_all(dir);
}

}  // namespace

namespace {

// chaser fdi design prints the design figures and writes the design as JSON; the assigned
// eigenvalues are the paper's (0.85 ... 0.95), which the library reaches to 1e-9.
TEST(Cli, FdiDesignWritesTheDesign) {
  const auto path = std::filesystem::temp_directory_path() / "chaser_fdi_design.json";
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
}

}  // namespace
