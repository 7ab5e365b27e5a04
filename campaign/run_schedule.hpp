#pragma once
// The in-order reorder buffer shared by every way of flying a campaign's runs (threads in
// executor.cpp, MPI ranks in mpi_runner.cpp): run indices are handed out in increasing order, at
// most `window` ahead of the next row to write, and finished rows are written strictly in index
// order, so runs.csv is the same whatever finishes first and memory stays flat in N.
#include <condition_variable>
#include <cstdint>
#include <map>
#include <mutex>

#include "campaign/executor.hpp"
#include "campaign/progress.hpp"
#include "campaign/rows_files.hpp"
#include "campaign/run_one.hpp"

namespace chaser::campaign {

class RunSchedule {
 public:
  static constexpr std::int64_t kNoMoreRuns = -1;
  static constexpr std::int64_t kWindowFull = -2;

  // Runs [begin, end); at most `window` handed out ahead of the next row to write.
  RunSchedule(std::int64_t begin, std::int64_t end, std::int64_t window);

  // The next run to fly, or kNoMoreRuns; waits while the window is full (worker threads).
  std::int64_t claim();
  // The same without waiting: kWindowFull instead (a coordinator that must keep polling).
  std::int64_t try_claim();
  // Files one finished run and writes every row that is now next in order.
  void deliver(RunOutput out, RowsWriter& writer, Progress& progress);

  // What was written; call once every run is delivered.
  const ExecuteResult& result() const { return result_; }

 private:
  std::mutex mutex_;
  std::condition_variable window_moved_;
  std::int64_t next_claim_, next_write_;
  const std::int64_t end_, window_;
  std::map<std::int64_t, RunOutput> pending_;  // finished, not yet written (at most window_)
  ExecuteResult result_;
};

}  // namespace chaser::campaign
