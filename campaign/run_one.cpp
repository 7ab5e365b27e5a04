#include "campaign/run_one.hpp"

#include <exception>
#include <filesystem>
#include <fstream>

#include "campaign/glr_envelope.hpp"
#include "campaign/run_row.hpp"
#include "sim/run_geometry.hpp"
#include "sim/summary.hpp"

namespace chaser::campaign {

namespace {

sim::RunResult fly(const RunSetup& setup, const CampaignPlan& plan, const flight::FlightParams& flight,
                   const std::string& telemetry_dir) {
  sim::RunOptions options{.telemetry_path = "", .telemetry_channels = {}, .record_glr_per_second = true};
  if (telemetry_dir.empty()) return sim::run_scenario(setup.truth, flight, options);
  std::filesystem::create_directories(telemetry_dir);
  options.telemetry_path = (std::filesystem::path(telemetry_dir) / "telemetry.csv").string();
  sim::RunResult result = sim::run_scenario(setup.truth, flight, options);
  // The run's shapes, so that `chaser view` replays a kept run as it does `chaser run`'s.
  std::ofstream(std::filesystem::path(telemetry_dir) / "geometry.json") << sim::run_geometry(setup.truth).dump(2) << '\n';
  std::ofstream(std::filesystem::path(telemetry_dir) / "summary.json")
      << sim::run_summary(setup.truth, plan.scenario_hash, result).dump(2) << '\n';
  return result;
}

// The position and attitude columns of the per-second GLR record (the envelope's two schemes).
std::vector<std::array<float, 2>> two_schemes(const sim::RunResult& result) {
  std::vector<std::array<float, 2>> out(result.glr_max_per_s.size());
  for (std::size_t t = 0; t < out.size(); ++t) out[t] = {result.glr_max_per_s[t][0], result.glr_max_per_s[t][1]};
  return out;
}

}  // namespace

RunOutput run_one(const CampaignPlan& plan, const flight::FlightParams& flight, std::int64_t run,
                  const std::string& telemetry_dir) {
  const RunSetup setup = make_run_setup(plan, run);
  RunOutput out;
  out.run = run;
  RunRecord record;
  try {
    const sim::RunResult result = fly(setup, plan, flight, telemetry_dir);
    record = make_record(setup, result, setup.truth.duration_s);
    if (setup.fault_case == FaultCase::kNone) out.glr_line = format_glr_line(run, two_schemes(result));
  } catch (const std::exception&) {
    record = error_record(setup);
    if (setup.fault_case == FaultCase::kNone) out.glr_line = format_glr_line(run, {});
  }
  out.row = format_row(record, run_column_set(plan.nominal));
  out.diverged = record.status != RunStatus::kOk;
  return out;
}

}  // namespace chaser::campaign
