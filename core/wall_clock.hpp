#pragma once
// Wall-clock time, for reports of how long a run or a campaign took (never for simulation time,
// which is core/time.hpp's integer nanoseconds).
#include <chrono>

namespace chaser {

// [s] of wall time since `start` (std::chrono::steady_clock: never steps backwards).
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace chaser
