#pragma once
// Runs a block of campaign runs on a pool of std::thread workers. Workers take the next run index
// from a shared counter and fly it with run_one; finished rows go through a small reorder buffer
// and are appended to the rows files strictly in index order. A worker may only start a run within
// a window of the next row to write, so memory stays flat in N whatever the completion order.
#include <cstdint>
#include <functional>
#include <string>

#include "campaign/cases.hpp"
#include "campaign/plan.hpp"
#include "campaign/progress.hpp"
#include "campaign/rows_files.hpp"
#include "flight/flight_software.hpp"

namespace chaser::campaign {

// Runs a worker may be ahead of the next row to write, per thread.
inline constexpr int kReorderWindowPerThread = 4;

struct ExecuteOptions {
  int threads = 1;
  std::int64_t keep_telemetry = 0;  // runs with index < keep_telemetry write telemetry_root/<run>/
  std::string telemetry_root;       // DIR/runs
  bool progress = false;            // show progress: the line on stderr, or show_progress
  ProgressCallback show_progress;   // empty: the line on stderr
  // Asked by each worker before it takes another run (empty: never). Once true, no run starts;
  // the runs already started finish and are written, so the rows stay a prefix --resume finishes.
  std::function<bool()> stop_requested;
};

struct ExecuteResult {
  std::int64_t runs = 0;       // rows written
  std::int64_t diverged = 0;   // of which status diverged or error
  bool io_ok = true;
  bool stopped = false;        // stop_requested ended it before every run was flown
  double wall_s = 0;           // [s]
};

// Where run `run` keeps its telemetry: root/<run> for run < keep, empty (none) otherwise.
std::string telemetry_dir(const std::string& root, std::int64_t keep, std::int64_t run);

ExecuteResult execute_runs(const CampaignPlan& plan, const flight::FlightParams& flight, const RunRange& todo,
                           RowsWriter& writer, const ExecuteOptions& options);

}  // namespace chaser::campaign
