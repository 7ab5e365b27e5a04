#pragma once
// A run's clock, derived once from a scenario: the control period and the duration in integer
// nanoseconds (core/time.hpp) and the number of periods flown. Every folder asks this rather than
// re-reading control_period_s, so the rounding to the clock happens in one place.
#include <cstdint>
#include <vector>
#include <string>

#include "core/time.hpp"
#include "model/scenario.hpp"

namespace chaser::model {

struct RunTiming {
  TimeNs control_period_ns = 0;  // [ns] T, >= 1
  TimeNs duration_ns = 0;        // [ns] a whole multiple of T
  std::int64_t periods = 0;      // duration / T, >= 1
};

// For a scenario io's validation accepted (a whole, positive number of nanoseconds per period and
// a duration a positive multiple of it).
RunTiming run_timing(const Scenario& scenario);

// The contract of a valid timing, every broken part named (the fuzz harness checks it on every
// scenario the loader accepts).
std::vector<std::string> check(const RunTiming& timing);

}  // namespace chaser::model
