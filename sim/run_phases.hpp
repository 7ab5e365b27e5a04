#pragma once
// The phases a scenario's run flies, as its guidance plans them, in one list for summary.json's
// plan ("phases") and for the run's phase sequence (sim/phase_sequence.hpp, "phases_flown"):
//   the line (MSR, ASSIST's approach): "line", then "capture_point_hold";
//   the synchronised transfer: "start_point_hold", "transfer", "capture_point_hold";
//   COMRADE's synchronisation with its approach steps (flight/sync_approach.hpp): "line",
//   "line_end_hold", "fly_around", "axis_approach", "rotation_synchronisation", "axis_hold",
//   "transfer", "capture_point_hold"; with a capture section, "reach" from capture.start_s (the
//   arm wakes on the multibody plant) and "capture" from capture.approach_start_s() (the tool onto
//   the fixture, the grasp: flight/grasp.hpp), then on conditions "rigidisation" and "rigidised"
//   or "stabilisation", or "escape" and "escape_retreat" (conditional_phases below).
// Each starts at its planned time, the first period at or after it on the integer clock; a phase
// of no length (its successor starts when it does) or past the run's end is left out. The flight
// software's guidance switches its own steps at the same periods (tests/sim/run_phases_test.cpp).
// Each phase carries the requirements judged while it is flown and the plant's configuration it
// flies in (the reach's: the arm awake). The flight software keeps its own schedule of the same
// times (it never sees the run's phases: plant and flight meet only through messages).
#include <vector>

#include "model/scenario.hpp"
#include "sim/phase_sequence.hpp"

namespace chaser::sim {

// The requirements judged while a phase is flown (the mission monitor, sim/mission_monitor.hpp).
struct PhaseRequirements {
  // The chaser turns with the target: COMRADE 2018 Table 1's errors at the capture point and the
  // 0.5 m clearance of Table 4 apply (before it, the 3 m unsynchronised clearance). From the phase
  // that starts at sim::synchronised_from_s on; always the start of a phase (run_phases_test).
  bool synchronised = false;
};

// The plant's configuration while a phase is flown: which the run sets up when the phase begins.
struct PhaseConfiguration {
  // The arm awake on the multibody plant (the capture's phases): entering such a phase wakes it
  // (sim/simulation.cpp, plant/arm_joints.hpp); before, the arm is folded in the rigid chaser.
  bool arm_awake = false;
};

struct PlannedPhase {
  const char* name = "";
  double start_s = 0;     // [s]
  double duration_s = 0;  // [s] > 0
  PhaseRequirements requirements{};
  PhaseConfiguration configuration{};
};

std::vector<PlannedPhase> planned_phases(const model::Scenario& scenario);

// The phases entered on a condition, not at a planned time: with capture.rigidise, "rigidisation"
// from the "capture" phase once the capture is confirmed (flag kCapturedFlag: the gripper reported
// locked, flight/grasp.hpp) and "rigidised" once the brakes are commanded (kBrakedFlag; with
// capture.stabilise "stabilisation": the thrusters detumble the composite, flight/stabilise.hpp). They
// follow the planned phases in the sequence's list; the run raises the flags from the flight
// software's state (sim/simulation.cpp). Synchronised, with the arm awake.
// With capture.escape, "escape" from the "reach" or "capture" phase once it is triggered (kEscapingFlag:
// flight/escape.hpp), synchronised, then "escape_retreat" from its desynchronisation on
// (kDesynchronisedFlag), not synchronised: Table 4's 3 m clearance applies again.
inline constexpr int kCapturedFlag = 0;
inline constexpr int kBrakedFlag = 1;
inline constexpr int kEscapingFlag = 2;
inline constexpr int kDesynchronisedFlag = 3;
struct ConditionalPhase {
  const char* name = "";
  PhaseRequirements requirements{};
  PhaseConfiguration configuration{};
};
std::vector<ConditionalPhase> conditional_phases(const model::Scenario& scenario);

PhaseSequenceParams run_phases(const model::Scenario& scenario);

}  // namespace chaser::sim
