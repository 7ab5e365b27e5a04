#include "campaign/executor.hpp"

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <thread>
#include <vector>

#include "campaign/progress.hpp"
#include "campaign/run_one.hpp"
#include "campaign/run_schedule.hpp"

namespace chaser::campaign {

std::string telemetry_dir(const std::string& root, std::int64_t keep, std::int64_t run) {
  return run < keep ? (std::filesystem::path(root) / std::to_string(run)).string() : std::string();
}

ExecuteResult execute_runs(const CampaignPlan& plan, const flight::FlightParams& flight, const RunRange& todo,
                           RowsWriter& writer, const ExecuteOptions& options) {
  const int threads = std::max(1, options.threads);
  RunSchedule schedule(todo.begin, todo.end, static_cast<std::int64_t>(threads) * kReorderWindowPerThread);
  Progress progress(todo.size(), options.progress, options.show_progress);
  std::atomic<bool> stopped = false;
  const auto stop = [&] {
    if (!stopped && options.stop_requested && options.stop_requested()) stopped = true;
    return stopped.load();
  };
  const auto worker = [&] {
    for (std::int64_t run = stop() ? -1 : schedule.claim(); run >= 0; run = stop() ? -1 : schedule.claim())
      schedule.deliver(run_one(plan, flight, run, telemetry_dir(options.telemetry_root, options.keep_telemetry, run)),
                       writer, progress);
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  ExecuteResult result = schedule.result();
  result.stopped = result.runs < todo.size();
  progress.finish(result.runs, result.diverged);
  result.wall_s = progress.elapsed_s();
  return result;
}

}  // namespace chaser::campaign
