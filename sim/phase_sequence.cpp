#include "sim/phase_sequence.hpp"

#include <algorithm>

#include "core/plain_name.hpp"

namespace chaser::sim {

namespace {

// A phase, flag or event name becomes a key and a telemetry label (core/plain_name.hpp).
const std::string kNotPlain = " is not a plain name (" + std::string(kPlainNameRule) + ")";

std::string range_text(std::size_t count) {
  return count == 0 ? std::string("none defined") : "0.." + std::to_string(count - 1);
}

void check_names(const std::vector<std::string>& names, const std::string& field,
                 std::vector<std::string>& problems) {
  if (names.size() > static_cast<std::size_t>(kMaxPhaseFlags))
    problems.push_back(field + ": at most " + std::to_string(kMaxPhaseFlags) + " (bits of a 64-bit word)");
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string at = field + "[" + std::to_string(i) + "]";
    if (!is_plain_name(names[i]))
      problems.push_back(at + ": '" + names[i] + "'" + kNotPlain);
    for (std::size_t j = 0; j < i; ++j)
      if (names[j] == names[i])
        problems.push_back(at + ": '" + names[i] + "' repeats " + field + "[" + std::to_string(j) + "]");
  }
}

void check_condition(const Condition& c, const PhaseSequenceParams& params, const std::string& at,
                     std::vector<std::string>& problems) {
  switch (c.kind) {
    case ConditionKind::kAtTime:
      if (c.at_ns < 0) problems.push_back(at + ".at_ns: must be >= 0");
      break;
    case ConditionKind::kAfter:
      if (c.duration_ns < 0) problems.push_back(at + ".duration_ns: must be >= 0");
      break;
    case ConditionKind::kHeldFor:
      if (c.dwell_ns < 0) problems.push_back(at + ".dwell_ns: must be >= 0");
      if (c.index < 0 || static_cast<std::size_t>(c.index) >= params.flag_names.size())
        problems.push_back(at + ".index: flag " + std::to_string(c.index) + " is not in flag_names (" +
                           range_text(params.flag_names.size()) + ")");
      break;
    case ConditionKind::kEvent:
      if (c.index < 0 || static_cast<std::size_t>(c.index) >= params.event_names.size())
        problems.push_back(at + ".index: event " + std::to_string(c.index) + " is not in event_names (" +
                           range_text(params.event_names.size()) + ")");
      break;
  }
}

void check_phase(const PhaseSequenceParams& params, std::size_t p, std::vector<std::string>& problems) {
  const PhaseSpec& phase = params.phases[p];
  const std::string at = "phases[" + std::to_string(p) + "] (" + phase.name + ")";
  if (!is_plain_name(phase.name))
    problems.push_back(at + ".name: '" + phase.name + "'" + kNotPlain);
  for (std::size_t q = 0; q < p; ++q)
    if (params.phases[q].name == phase.name)
      problems.push_back(at + ".name: repeats phases[" + std::to_string(q) + "]");
  for (std::size_t e = 0; e < phase.exits.size(); ++e) {
    const Transition& exit = phase.exits[e];
    const std::string exit_at = at + ".exits[" + std::to_string(e) + "]";
    if (exit.to_phase < 0 || static_cast<std::size_t>(exit.to_phase) >= params.phases.size())
      problems.push_back(exit_at + ".to_phase: unknown phase " + std::to_string(exit.to_phase) + " (" +
                         range_text(params.phases.size()) + ")");
    if (exit.reason.empty())
      problems.push_back(exit_at + ".reason: must not be empty (it is the end reason recorded)");
    check_condition(exit.condition, params, exit_at + ".condition", problems);
  }
}

// The dwell counts from the later of the flag's rise and the phase's start: the flags are mostly the
// phase's own requirements, which change at the transition, so a flag held before the phase says
// nothing about it. A kHeldFor exit thus also keeps its phase for at least dwell_ns.
bool condition_holds(const Condition& c, const PhaseSequenceState& state, TimeNs t, std::uint64_t events) {
  switch (c.kind) {
    case ConditionKind::kAtTime: return t >= c.at_ns;
    case ConditionKind::kAfter: return t - state.phase_start_ns >= c.duration_ns;
    case ConditionKind::kHeldFor: {
      const TimeNs since = state.flag_true_since_ns[static_cast<std::size_t>(c.index)];
      return since != kNotHeld && t - std::max(since, state.phase_start_ns) >= c.dwell_ns;
    }
    case ConditionKind::kEvent: return ((events >> c.index) & 1U) != 0;
  }
  return false;
}

void update_flags(const PhaseSequenceParams& params, PhaseSequenceState& state, TimeNs t, std::uint64_t flags) {
  for (std::size_t i = 0; i < params.flag_names.size(); ++i) {
    TimeNs& since = state.flag_true_since_ns[i];
    if (((flags >> i) & 1U) == 0)
      since = kNotHeld;
    else if (since == kNotHeld)
      since = t;
  }
}

// After the log fills, the current phase has no entry to close.
bool current_phase_logged(const PhaseSequenceState& state) { return state.log_size > 0 && state.unlogged_phases == 0; }

void enter_phase(PhaseSequenceState& state, int phase, TimeNs t) {
  state.phase = phase;
  state.phase_start_ns = t;
  if (state.log_size < kMaxPhaseLog && state.unlogged_phases == 0)
    state.log[static_cast<std::size_t>(state.log_size++)] = {.phase = phase, .start_ns = t};
  else
    ++state.unlogged_phases;
}

}  // namespace

std::vector<std::string> validate(const PhaseSequenceParams& params) {
  std::vector<std::string> problems;
  if (params.phases.empty()) problems.push_back("phases: must list at least one phase");
  if (params.initial < 0 || static_cast<std::size_t>(params.initial) >= params.phases.size())
    problems.push_back("initial: unknown phase " + std::to_string(params.initial) + " (" +
                       range_text(params.phases.size()) + ")");
  check_names(params.flag_names, "flag_names", problems);
  check_names(params.event_names, "event_names", problems);
  for (std::size_t p = 0; p < params.phases.size(); ++p) check_phase(params, p, problems);
  return problems;
}

int phase_index(const PhaseSequenceParams& params, std::string_view name) {
  for (std::size_t p = 0; p < params.phases.size(); ++p)
    if (params.phases[p].name == name) return static_cast<int>(p);
  return -1;
}

PhaseSequenceState init_phases(const PhaseSequenceParams& params, TimeNs t_start) {
  PhaseSequenceState state;
  enter_phase(state, params.initial, t_start);
  return state;
}

std::optional<PhaseChange> step_phases(const PhaseSequenceParams& params, PhaseSequenceState& state, TimeNs t,
                                       std::uint64_t flags, std::uint64_t events) {
  if (state.finished) return std::nullopt;
  update_flags(params, state, t, flags);
  const std::vector<Transition>& exits = params.phases[static_cast<std::size_t>(state.phase)].exits;
  for (std::size_t e = 0; e < exits.size(); ++e) {
    if (!condition_holds(exits[e].condition, state, t, events)) continue;
    const PhaseChange change{
        .from_phase = state.phase, .to_phase = exits[e].to_phase, .exit = static_cast<int>(e), .t_ns = t};
    if (current_phase_logged(state)) {
      PhaseLogEntry& entry = state.log[static_cast<std::size_t>(state.log_size - 1)];
      entry.end_ns = t;
      entry.exit = change.exit;
    }
    enter_phase(state, change.to_phase, t);
    return change;
  }
  return std::nullopt;
}

void finish_phases(const PhaseSequenceParams& /*params*/, PhaseSequenceState& state, TimeNs t_end) {
  if (state.finished) return;
  if (current_phase_logged(state)) state.log[static_cast<std::size_t>(state.log_size - 1)].end_ns = t_end;
  state.finished = true;
}

std::vector<FlownPhase> flown_phases(const PhaseSequenceParams& params, const PhaseSequenceState& state) {
  // Divided, not multiplied by 1e-9 (to_seconds): the quotient is correctly rounded, so a phase
  // starting at 1000 s is written as 1000 in summary.json, not 1000.0000000000001.
  const auto seconds = [](TimeNs t) { return static_cast<double>(t) / static_cast<double>(kNsPerSecond); };
  std::vector<FlownPhase> flown;
  flown.reserve(static_cast<std::size_t>(state.log_size));
  for (int i = 0; i < state.log_size; ++i) {
    const PhaseLogEntry& entry = state.log[static_cast<std::size_t>(i)];
    const PhaseSpec& phase = params.phases[static_cast<std::size_t>(entry.phase)];
    std::string reason;
    if (entry.exit >= 0)
      reason = phase.exits[static_cast<std::size_t>(entry.exit)].reason;
    else if (entry.end_ns >= 0)
      reason = kRunEndReason;
    flown.push_back({.name = phase.name,
                     .start_s = seconds(entry.start_ns),
                     .end_s = entry.end_ns >= 0 ? seconds(entry.end_ns) : -1.0,
                     .end_reason = std::move(reason)});
  }
  return flown;
}

}  // namespace chaser::sim
