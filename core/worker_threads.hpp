#pragma once
// The worker count of a parallel command (chaser fmea, chaser campaign, their Python calls) when its
// user names none.
#include <algorithm>
#include <thread>

namespace chaser {

// One worker per hardware thread, and at least one: hardware_concurrency() is 0 where the count
// cannot be told.
inline int default_worker_threads() {
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

}  // namespace chaser
