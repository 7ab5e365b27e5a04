#include "campaign/run_schedule.hpp"

#include <utility>

namespace chaser::campaign {

RunSchedule::RunSchedule(std::int64_t begin, std::int64_t end, std::int64_t window)
    : next_claim_(begin), next_write_(begin), end_(end), window_(window) {}

std::int64_t RunSchedule::claim() {
  std::unique_lock lock(mutex_);
  window_moved_.wait(lock, [&] { return next_claim_ >= end_ || next_claim_ < next_write_ + window_; });
  return next_claim_ < end_ ? next_claim_++ : kNoMoreRuns;
}

std::int64_t RunSchedule::try_claim() {
  std::lock_guard lock(mutex_);
  if (next_claim_ >= end_) return kNoMoreRuns;
  return next_claim_ < next_write_ + window_ ? next_claim_++ : kWindowFull;
}

void RunSchedule::deliver(RunOutput out, RowsWriter& writer, Progress& progress) {
  std::lock_guard lock(mutex_);
  pending_.emplace(out.run, std::move(out));
  for (auto it = pending_.find(next_write_); it != pending_.end(); it = pending_.find(next_write_)) {
    result_.io_ok &= writer.append(it->second);
    result_.diverged += it->second.diverged;
    ++result_.runs;
    pending_.erase(it);
    ++next_write_;
  }
  progress.update(result_.runs, result_.diverged);
  window_moved_.notify_all();
}

}  // namespace chaser::campaign
