#pragma once
// The whole mission judged phase by phase (COMRADE 2018, sec. 4: each phase of the servicing has its
// own requirements): while a phase is flown the run keeps its figures (sim/simulation.cpp), and at
// the end each phase flown is judged against the requirements that apply to it, on the truth:
//   every phase, with a keep-out volume: the chaser's least clearance, >= 0.5 m while it turns with
//     the target and >= 3 m before (COMRADE Table 4; the phase's PhaseRequirements);
//   capture_point_hold: COMRADE Table 1 at its last period (position, speed and attitude within
//     guidance.capture_*_tol, rate within 0.5 deg/s, against the reference);
//   reach: the gripper inside Table 2 over the hold (sim/reach_result.hpp), the joints' torques within
//     the drives' repeated peak;
//   capture: the target captured, the grasp inside Table 2 at the closure;
//   rigidisation: the brakes engaged, the torques within the repeated peak;
//   stabilisation: Table 3 (the rate below 0.5 deg/s at the end, the braked loads within the peak);
//   escape_retreat: the escape's requirements (sim/escape_result.hpp).
// A phase cut short by the run's end is judged on what was flown of it.
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "model/scenario.hpp"
#include "sim/mission_monitor.hpp"
#include "sim/phase_sequence.hpp"

namespace chaser::sim {

struct RunResult;

inline constexpr double kTable1RateDegps = 0.5;  // [deg/s] COMRADE 2018 Table 1's rate at the capture point

// One phase's figures over the periods it was flown.
struct PhaseFigures {
  int periods = 0;
  double min_clearance_m = std::numeric_limits<double>::infinity();  // [m] (infinite without a keep-out volume)
  // At its last period, against the reference (as monitor_final judges the run's end).
  double final_position_error_m = 0.0, final_speed_error_mps = 0.0;
  double final_attitude_error_rad = 0.0, final_rate_error_radps = 0.0;
};

// A period flown in the phase: its clearance (NaN without a keep-out volume) and its errors.
void add_phase_period(PhaseFigures& figures, const MonitorSample& sample, double clearance_m);

struct Requirement {
  std::string name;
  double value = std::numeric_limits<double>::quiet_NaN();  // NaN: a condition, not a figure
  double limit = std::numeric_limits<double>::quiet_NaN();
  bool met = false;
};

struct PhaseVerdict {
  std::string phase;
  double start_s = 0.0, end_s = 0.0;  // [s]
  std::vector<Requirement> requirements;  // empty: nothing applies to it
  bool met() const;
};

// Each phase flown (result.phases) judged; figures by phase index (params' order).
std::vector<PhaseVerdict> phase_verdicts(const model::Scenario& scenario, const PhaseSequenceParams& params,
                                         const RunResult& result);

// Every phase's requirements met.
bool mission_met(const std::vector<PhaseVerdict>& verdicts);

// The mission's phases in flight order (sim/run_phases.hpp's names), for a run's phases not met as
// the bits of one integer (runs.csv's phases_not_met): bit i phase i, bit kMissionPhases.size() any
// other phase.
inline constexpr std::array<const char*, 14> kMissionPhases = {
    "line", "line_end_hold", "fly_around", "axis_approach", "rotation_synchronisation", "transfer",
    "capture_point_hold", "reach", "capture", "rigidisation", "rigidised", "stabilisation", "escape", "escape_retreat"};
std::int64_t phases_not_met_bits(const std::vector<PhaseVerdict>& verdicts);

}  // namespace chaser::sim
