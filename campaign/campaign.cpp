#include "campaign/campaign.hpp"

#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "campaign/campaign_json.hpp"
#include "campaign/dir_lock.hpp"
#include "campaign/rows_files.hpp"
#include "campaign/summary.hpp"
#include "flight/flight_software.hpp"

namespace chaser::campaign {

namespace {

namespace fs = std::filesystem;

CampaignOutcome bad_input(std::string message) { return CampaignOutcome::bad_input(std::move(message)); }
CampaignOutcome failure(std::string message) { return CampaignOutcome::failure(std::move(message)); }

// --resume: the directory must hold this very campaign (same scenario after overrides, cases,
// seed, shard). Without --resume it must not hold a campaign at all: nothing is overwritten.
std::string check_directory(const CampaignOptions& o, const nlohmann::ordered_json& expected) {
  const fs::path json_path = fs::path(o.out_dir) / "campaign.json";
  if (!o.resume) {
    if (fs::exists(json_path) || fs::exists(fs::path(o.out_dir) / "runs.csv"))
      return fmt::format("--out: {} already holds a campaign; add --resume to finish it, or choose another --out",
                         o.out_dir);
    return "";
  }
  std::string error;
  const auto found = read_campaign_json(o.out_dir, error);
  if (!found) return fmt::format("--resume: {}", error);
  const std::string differ = differing_keys(*found, expected);
  if (!differ.empty())
    return fmt::format("--resume: {} was made by a different campaign (differs in: {}); resume it with the same "
                       "scenario, --set, --seed, --runs, --cases, --preset and --shard", o.out_dir, differ);
  return "";
}

}  // namespace

CampaignOutcome run_campaign(const CampaignPlan& plan, const CampaignOptions& options, const RunsExecutor& executor) {
  const nlohmann::ordered_json json = campaign_json(plan, options.shard);
  if (std::string e = check_directory(options, json); !e.empty()) return bad_input(e);
  std::error_code ec;
  fs::create_directories(options.out_dir, ec);
  if (ec) return failure(fmt::format("cannot create --out directory {}: {}", options.out_dir, ec.message()));
  const DirLock lock(options.out_dir);
  if (!lock.held())
    return bad_input(fmt::format("--out: another chaser process is writing {} (or it cannot be locked)", options.out_dir));
  std::ofstream(fs::path(options.out_dir) / "campaign.json", std::ios::binary) << campaign_json_text(json);

  const RunRange range = shard_range(options.shard, plan.layout.total_runs());
  RowsScan scan;
  if (options.resume) {
    scan = scan_rows(options.out_dir, range, plan.layout, plan.nominal.campaign.seed, run_column_set(plan.nominal));
    if (!scan.error.empty()) return bad_input("--resume: " + scan.error);
  }
  std::string error;
  const auto writer =
      RowsWriter::open(options.out_dir, options.resume ? &scan : nullptr, run_column_set(plan.nominal), error);
  if (!writer) return failure(error);

  CampaignOutcome outcome;
  outcome.shard_runs = range.size();
  outcome.resumed = scan.runs_done;
  const RunRange todo{range.begin + scan.runs_done, range.end};
  const flight::FlightParams flight = flight::make_flight_params(plan.nominal);  // designed once, shared
  const ExecuteOptions execute{.threads = options.threads,
                               .keep_telemetry = options.keep_telemetry,
                               .telemetry_root = (fs::path(options.out_dir) / "runs").string(),
                               .progress = options.progress,
                               .show_progress = options.show_progress,
                               .stop_requested = options.stop_requested};
  outcome.executed = executor ? executor(plan, flight, todo, *writer, execute)
                              : execute_runs(plan, flight, todo, *writer, execute);
  outcome.simulated_s = static_cast<double>(outcome.executed.runs) * run_duration_s(plan.nominal);
  if (!outcome.executed.io_ok) return failure(fmt::format("cannot write the rows files in {}", options.out_dir));
  if (outcome.executed.stopped) {
    outcome.status = CampaignStatus::kStopped;
    outcome.message = fmt::format("stopped after {} of {} runs; resume finishes it", outcome.executed.runs, todo.size());
    return outcome;
  }
  std::vector<FaultCase> cases;
  for (const CaseRuns& c : plan.layout.cases()) cases.push_back(c.fault_case);
  const std::string summary_error =
      write_summaries(options.out_dir, cases,
                      {plan.nominal.name, plan.nominal.campaign.threshold_margin, plan.nominal.fdi.glr_threshold,
                       options.targets});
  if (!summary_error.empty()) {
    CampaignOutcome failed = failure(summary_error);
    failed.executed = outcome.executed;
    return failed;
  }
  return outcome;
}

}  // namespace chaser::campaign
