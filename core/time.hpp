#pragma once
// Simulation time is an integer count of nanoseconds, so every rate divides exactly and no block
// infers its step from when it was called (docs/architecture.md, "Rules that keep it simple").
#include <cmath>
#include <cstdint>

namespace chaser {

using TimeNs = std::int64_t;
inline constexpr TimeNs kNsPerSecond = 1'000'000'000;

constexpr double to_seconds(TimeNs t) { return static_cast<double>(t) * 1e-9; }

// Rounds to the nearest nanosecond; the scenario checks that periods are whole nanoseconds.
inline TimeNs from_seconds(double seconds) { return static_cast<TimeNs>(std::llround(seconds * 1e9)); }

}  // namespace chaser
