#pragma once
// A whole campaign (or one shard of it) into a directory: campaign.json, runs.csv, glr_runs.csv,
// then summary.csv, summary.md and glr_envelope.csv (docs/campaigns.md).
#include <cstdint>
#include <functional>
#include <string>
#include <utility>

#include "campaign/cases.hpp"
#include "campaign/executor.hpp"
#include "campaign/plan.hpp"
#include "campaign/target.hpp"

namespace chaser::campaign {

struct CampaignOptions {
  std::string out_dir = "campaign-out";
  Shard shard;
  int threads = 1;
  bool resume = false;
  std::int64_t keep_telemetry = 0;  // runs with index < K keep DIR/runs/<run>/telemetry.csv, summary.json
  bool progress = false;           // show progress: the line on stderr, or show_progress
  ProgressCallback show_progress;  // empty: the line on stderr (the Python module shows its own)
  std::function<bool()> stop_requested;  // ExecuteOptions::stop_requested (the Python module's Ctrl-C)
  // --target: judged in summary.md. Not part of what the campaign is (campaign.json): a resume or a
  // merge may ask other questions of the same runs.
  std::vector<Target> targets;
};

// kStopped: stop_requested ended the runs early; the rows written are a prefix that --resume
// finishes, and no summary was written.
enum class CampaignStatus { kOk, kBadInput, kFailure, kStopped };

struct CampaignOutcome {
  CampaignStatus status = CampaignStatus::kOk;
  std::string message;         // what went wrong, naming the option
  std::int64_t shard_runs = 0; // runs of this shard
  std::int64_t resumed = 0;    // runs found done in the directory (--resume)
  ExecuteResult executed;      // runs flown now
  double simulated_s = 0;      // [s] simulated time of the runs flown now (planned)

  static CampaignOutcome bad_input(std::string message) { return with(CampaignStatus::kBadInput, std::move(message)); }
  static CampaignOutcome failure(std::string message) { return with(CampaignStatus::kFailure, std::move(message)); }
  static CampaignOutcome with(CampaignStatus status, std::string message) {
    CampaignOutcome o;
    o.status = status;
    o.message = std::move(message);
    return o;
  }
};

// How the runs still to do are flown and handed to the writer in index order: execute_runs (a
// thread pool) unless given; chaser campaign --mpi gives the MPI coordinator (mpi_runner.hpp).
using RunsExecutor = std::function<ExecuteResult(const CampaignPlan&, const flight::FlightParams&, const RunRange&,
                                                 RowsWriter&, const ExecuteOptions&)>;

CampaignOutcome run_campaign(const CampaignPlan& plan, const CampaignOptions& options,
                             const RunsExecutor& executor = {});

}  // namespace chaser::campaign
