#include <filesystem>
#include <fstream>
#include <iostream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cli/commands.hpp"
#include "cli/output_file.hpp"
#include "cli/scenario_input.hpp"
#include "io/scenario_loader.hpp"
#include "sim/run.hpp"
#include "sim/run_directory.hpp"
#include "sim/run_geometry.hpp"
#include "sim/summary.hpp"
#include "sim/telemetry_channels.hpp"

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
  const std::vector<std::string> unmatched =
      sim::unmatched_patterns(sim::telemetry_channels(sim::telemetry_shape(scenario)), args.channels);
  if (!unmatched.empty()) {
    std::cerr << fmt::format("chaser: --channels: {} match no telemetry channel (names as in telemetry.csv's "
                             "header, e.g. r_lvlh_*, ton_cmd_?, glr_*)\n",
                             fmt::join(unmatched, ", "));
    return kExitBadInput;
  }

  const std::filesystem::path out(args.out_dir);
  if (const std::string problem = sim::prepare_run_directory(out); !problem.empty()) {
    std::cerr << "chaser: " << problem << "\n";
    return kExitFailure;
  }
  const std::filesystem::path telemetry = sim::run_telemetry_path(out, args.telemetry_format);
  const sim::RunResult result =
      sim::run_scenario(scenario, {.telemetry_path = telemetry.string(), .telemetry_channels = args.channels});
  if (!result.telemetry_ok) {
    std::cerr << fmt::format("chaser: cannot write {}\n", telemetry.string());
    return kExitFailure;
  }
  if (!write_output_file(out / "geometry.json", sim::run_geometry(scenario).dump(2) + "\n")) return kExitFailure;
  // summary.json last: where it exists, the run and its telemetry are complete.
  if (!write_output_file(out / "summary.json", sim::run_summary(scenario, loaded->hash, result).dump(2) + "\n"))
    return kExitFailure;
  std::cout << sim::summary_text(scenario, result);
  std::cout << fmt::format("  wrote {}{}\n", telemetry.empty() ? "" : telemetry.string() + " and ",
                           (out / "summary.json").string());
  return kExitOk;
}

}  // namespace chaser::cli
