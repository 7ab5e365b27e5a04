#include "campaign/executor.hpp"

#include <algorithm>
#include <condition_variable>
#include <filesystem>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

#include "campaign/progress.hpp"
#include "campaign/run_one.hpp"

namespace chaser::campaign {

namespace {

// Shared by the workers, guarded by `mutex`.
struct Schedule {
  std::mutex mutex;
  std::condition_variable window_moved;
  std::int64_t next_claim = 0;   // next run index to hand out
  std::int64_t next_write = 0;   // next run index the writer waits for
  std::int64_t window = 1;
  std::map<std::int64_t, RunOutput> pending;  // finished, not yet written (at most `window`)
  ExecuteResult result;
};

// The next run to fly, or -1 when every run is handed out. Blocks while the window is full.
std::int64_t claim(Schedule& s, std::int64_t end) {
  std::unique_lock lock(s.mutex);
  s.window_moved.wait(lock, [&] { return s.next_claim >= end || s.next_claim < s.next_write + s.window; });
  return s.next_claim < end ? s.next_claim++ : -1;
}

// Files one finished run and writes every row that is now next in order.
void deliver(Schedule& s, RunOutput out, RowsWriter& writer, Progress& progress) {
  std::lock_guard lock(s.mutex);
  s.pending.emplace(out.run, std::move(out));
  for (auto it = s.pending.find(s.next_write); it != s.pending.end(); it = s.pending.find(s.next_write)) {
    s.result.io_ok &= writer.append(it->second);
    s.result.diverged += it->second.diverged;
    ++s.result.runs;
    s.pending.erase(it);
    ++s.next_write;
  }
  progress.update(s.result.runs, s.result.diverged);
  s.window_moved.notify_all();
}

}  // namespace

ExecuteResult execute_runs(const CampaignPlan& plan, const flight::FlightParams& flight, const RunRange& todo,
                           RowsWriter& writer, const ExecuteOptions& options) {
  const int threads = std::max(1, options.threads);
  Schedule schedule;
  schedule.next_claim = schedule.next_write = todo.begin;
  schedule.window = static_cast<std::int64_t>(threads) * kReorderWindowPerThread;
  Progress progress(todo.size(), options.progress);
  const auto worker = [&] {
    for (std::int64_t run = claim(schedule, todo.end); run >= 0; run = claim(schedule, todo.end)) {
      const std::string telemetry = run < options.keep_telemetry
                                        ? (std::filesystem::path(options.telemetry_root) / std::to_string(run)).string()
                                        : std::string();
      deliver(schedule, run_one(plan, flight, run, telemetry), writer, progress);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  progress.finish(schedule.result.runs, schedule.result.diverged);
  schedule.result.wall_s = progress.elapsed_s();
  return schedule.result;
}

}  // namespace chaser::campaign
