#include <filesystem>
#include <fstream>
#include <iostream>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/scenario_input.hpp"
#include "io/scenario_loader.hpp"
#include "sim/run.hpp"
#include "sim/summary.hpp"

namespace chaser::cli {


int validate_command(const std::string& scenario_path, const std::vector<std::string>& overrides) {
  const auto loaded = load_or_report(scenario_path, overrides);
  if (!loaded) return kExitBadInput;
  std::cout << fmt::format("{}: valid (scenario '{}', hash {})\n", scenario_path, loaded->scenario->name,
                           loaded->hash);
  return kExitOk;
}

int run_command(const RunArgs& args) {
  auto loaded = load_or_report(args.scenario_path, args.overrides);
  if (!loaded) return kExitBadInput;
  model::Scenario scenario = *loaded->scenario;
  if (args.seed) scenario.seed = *args.seed;

  std::error_code ec;
  std::filesystem::create_directories(args.out_dir, ec);
  if (ec) {
    std::cerr << fmt::format("chaser: cannot create output directory {}: {}\n", args.out_dir, ec.message());
    return kExitFailure;
  }
  const std::filesystem::path out(args.out_dir);
  const sim::RunResult result = sim::run_scenario(scenario, {.telemetry_path = (out / "telemetry.csv").string()});
  if (!result.telemetry_ok) {
    std::cerr << fmt::format("chaser: cannot write {}\n", (out / "telemetry.csv").string());
    return kExitFailure;
  }
  std::ofstream summary(out / "summary.json");
  summary << sim::run_summary(scenario, loaded->hash, result).dump(2) << '\n';
  if (!summary) {
    std::cerr << fmt::format("chaser: cannot write {}\n", (out / "summary.json").string());
    return kExitFailure;
  }
  std::cout << sim::summary_text(scenario, result);
  std::cout << fmt::format("  wrote {} and {}\n", (out / "telemetry.csv").string(), (out / "summary.json").string());
  return kExitOk;
}

}  // namespace chaser::cli
