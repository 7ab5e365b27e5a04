#pragma once
// One closed-loop run: the fixed-order schedule of plant and flight blocks, period after period.
#include <cstdint>
#include <string>

#include "model/scenario.hpp"
#include "sim/mission_monitor.hpp"

namespace chaser::sim {

struct RunOptions {
  std::string telemetry_path;  // empty: no telemetry (campaigns, benchmarks)
};

// What one FDI scheme concluded over the run (times from the start of the run).
struct SchemeResult {
  bool enabled = false;
  double alarm_s = -1;        // [s] first GLR alarm, -1: none
  double isolated_s = -1;     // [s] thruster confirmed, -1: none
  int isolated_thruster = -1; // 1-based thruster number (T1..T8 of branch A), -1: none
};

struct FdirResult {
  SchemeResult position, attitude;
  double recovery_s = -1;        // [s] branch A closed, branch B flying; -1: no recovery
  int recovered_thruster = -1;   // 1-based thruster the recovery acted on
};

struct RunResult {
  MissionFigures figures;
  double propellant_used_kg = 0;  // [kg]
  double simulated_s = 0;         // [s] simulated time actually flown (less than duration if diverged)
  double wall_s = 0;              // [s] wall-clock time of the run loop
  std::int64_t periods = 0;
  std::int64_t infeasible_allocations = 0;  // periods where the TMF could not reach the demand exactly
  bool telemetry_ok = true;
  FdirResult fdir;
};

RunResult run_scenario(const model::Scenario& scenario, const RunOptions& options = {});

}  // namespace chaser::sim
