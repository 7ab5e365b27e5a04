#pragma once
// A run as a sequence of named mission phases with transitions on conditions (COMRADE 2018, sec. 4:
// synchronisation, reach, capture, rigidisation, stabilisation, escape; the synchronised approach:
// fly-around, axis approach, rotation synchronisation, transfer, hold). Capture changes the control
// law, the actuators allowed, the plant's configuration and the requirements from phase to phase, so
// the run must say which phase holds in each period and record when and why each ended. Only the
// sequencing lives here: what a phase carries is attached by its owner by phase index.
//
// Called once per control period, at the period's start and before the flight software runs, so a
// new phase applies to that whole period. Stepping allocates nothing (the log has a fixed capacity).
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/time.hpp"

namespace chaser::sim {

inline constexpr int kMaxPhaseFlags = 64;   // flags and events are the bits of a std::uint64_t
inline constexpr int kMaxPhaseLog = 64;     // phases recorded per run; later ones are only counted
inline constexpr TimeNs kNotHeld = std::numeric_limits<TimeNs>::max();
inline constexpr std::string_view kRunEndReason = "run end";

enum class ConditionKind {
  kAtTime,   // run time t >= at_ns
  kAfter,    // time in the phase >= duration_ns
  kHeldFor,  // flag `index` true without a break, within this phase, for >= dwell_ns (0: true now)
  kEvent,    // event `index` raised in this step
};

struct Condition {
  ConditionKind kind = ConditionKind::kAtTime;
  TimeNs at_ns = 0;        // [ns] kAtTime
  TimeNs duration_ns = 0;  // [ns] kAfter
  TimeNs dwell_ns = 0;     // [ns] kHeldFor
  int index = 0;           // kHeldFor: into flag_names; kEvent: into event_names
};

constexpr Condition at_time(TimeNs at_ns) { return {.kind = ConditionKind::kAtTime, .at_ns = at_ns}; }
constexpr Condition after(TimeNs duration_ns) { return {.kind = ConditionKind::kAfter, .duration_ns = duration_ns}; }
constexpr Condition held_for(int flag, TimeNs dwell_ns) {
  return {.kind = ConditionKind::kHeldFor, .dwell_ns = dwell_ns, .index = flag};
}
constexpr Condition on_event(int event) { return {.kind = ConditionKind::kEvent, .index = event}; }

struct Transition {
  Condition condition{};
  int to_phase = 0;
  std::string reason{};  // recorded as the phase's end reason: "time", "grasp closed", ...
};

struct PhaseSpec {
  std::string name{};
  std::vector<Transition> exits{};  // in priority order; none: terminal, lasts to the run's end
};

struct PhaseSequenceParams {
  std::vector<PhaseSpec> phases{};
  int initial = 0;
  std::vector<std::string> flag_names{};   // bit i of step_phases' flags
  std::vector<std::string> event_names{}; // bit i of step_phases' events
};

// Every problem, each naming the phase and field: "phases[2] (capture).exits[0].to_phase: ...".
std::vector<std::string> validate(const PhaseSequenceParams& params);

// Index of the phase called `name`, or -1.
int phase_index(const PhaseSequenceParams& params, std::string_view name);

struct PhaseLogEntry {
  int phase = -1;
  TimeNs start_ns = 0;  // [ns]
  TimeNs end_ns = -1;   // [ns] -1 while the phase is flown
  int exit = -1;        // index into the phase's exits; -1: still flown, or ended with the run
  bool operator==(const PhaseLogEntry&) const = default;
};

struct PhaseSequenceState {
  int phase = 0;
  TimeNs phase_start_ns = 0;  // [ns]
  // [ns] when each flag last rose; kNotHeld while it is false.
  std::array<TimeNs, kMaxPhaseFlags> flag_true_since_ns = [] {
    std::array<TimeNs, kMaxPhaseFlags> since{};
    since.fill(kNotHeld);
    return since;
  }();
  std::array<PhaseLogEntry, kMaxPhaseLog> log{};
  int log_size = 0;
  int unlogged_phases = 0;  // phases entered after the log filled (a cycle of phases)
  bool finished = false;
};

// The initial phase, started at t_start.
PhaseSequenceState init_phases(const PhaseSequenceParams& params, TimeNs t_start);

struct PhaseChange {
  int from_phase = 0, to_phase = 0;
  int exit = 0;  // index into from_phase's exits
  TimeNs t_ns = 0;
};

// At the start of the period beginning at t (not before the previous call's t): updates the flags'
// dwell, then takes the current phase's first exit whose condition holds. At most one transition per
// call, so every phase entered is flown for at least one period: its flight software runs and its
// entry shows in the telemetry. Evaluating the new phase's exits in the same call would let a chain
// of phases whose exits hold at once pass through phases that never ran. A consequence: an event
// raised in the step of a transition is not seen by the new phase (events are not latched; the owner
// latches one as a flag when it must outlive its step). Does nothing once finished. Expects params
// that validate() accepts: nothing is checked in the loop.
std::optional<PhaseChange> step_phases(const PhaseSequenceParams& params, PhaseSequenceState& state, TimeNs t,
                                       std::uint64_t flags, std::uint64_t events);

// Ends the current phase at the run's end (reason kRunEndReason); later steps do nothing.
void finish_phases(const PhaseSequenceParams& params, PhaseSequenceState& state, TimeNs t_end);

// The phases flown, for summary.json. A phase still flown has end_s = -1 and an empty reason.
struct FlownPhase {
  std::string name{};
  double start_s = 0, end_s = -1;  // [s]
  std::string end_reason{};
  bool operator==(const FlownPhase&) const = default;
};
std::vector<FlownPhase> flown_phases(const PhaseSequenceParams& params, const PhaseSequenceState& state);

}  // namespace chaser::sim
