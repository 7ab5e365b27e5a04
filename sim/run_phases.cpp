#include "sim/run_phases.hpp"

#include <algorithm>
#include <utility>

#include "sim/mission_monitor.hpp"

namespace chaser::sim {

namespace {

// Each phase's name and planned start, in order.
std::vector<std::pair<const char*, double>> phase_starts(const model::GuidanceParams& g) {
  if (g.synchronised && g.synchronised->approach) {
    const model::SyncApproachParams& a = *g.synchronised->approach;
    const double axis = a.fly_around_start_s + a.fly_around_duration_s;
    const double rotation = axis + a.axis_approach_duration_s;
    const double transfer = g.synchronised->transfer_start_s;
    return {{"line", 0.0},
            {"line_end_hold", g.approach_duration_s},
            {"fly_around", a.fly_around_start_s},
            {"axis_approach", axis},
            {"rotation_synchronisation", rotation},
            {"axis_hold", a.rotation_sync_end_s()},
            {"transfer", transfer},
            {"capture_point_hold", transfer + g.synchronised->transfer_duration_s}};
  }
  if (g.synchronised)
    return {{"start_point_hold", 0.0},
            {"transfer", g.synchronised->transfer_start_s},
            {"capture_point_hold", g.synchronised->transfer_start_s + g.synchronised->transfer_duration_s}};
  return {{"line", 0.0}, {"capture_point_hold", g.approach_duration_s}};
}

}  // namespace

std::vector<PlannedPhase> planned_phases(const model::Scenario& s) {
  auto starts = phase_starts(s.guidance);
  if (s.capture) {
    starts.emplace_back("reach", s.capture->start_s);  // the arm wakes (sim/simulation.cpp)
    starts.emplace_back("capture", s.capture->approach_start_s());  // onto the fixture, the grasp
  }
  const double synchronised_from = synchronised_from_s(s);
  std::vector<PlannedPhase> out;
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const double start = std::min(starts[i].second, s.duration_s);
    const double end = std::min(i + 1 < starts.size() ? starts[i + 1].second : s.duration_s, s.duration_s);
    if (end > start)
      out.push_back({starts[i].first, start, end - start, {.synchronised = starts[i].second >= synchronised_from},
                     {.arm_awake = s.capture && starts[i].second >= s.capture->start_s}});
  }
  return out;
}

std::vector<ConditionalPhase> conditional_phases(const model::Scenario& s) {
  if (!s.capture) return {};
  std::vector<ConditionalPhase> out;
  if (s.capture->rigidise) {
    const ConditionalPhase phase{.requirements = {.synchronised = true}, .configuration = {.arm_awake = true}};
    ConditionalPhase rigidisation = phase, rigidised = phase;
    rigidisation.name = "rigidisation";
    rigidised.name = s.capture->stabilise ? "stabilisation" : "rigidised";
    out.push_back(rigidisation);
    out.push_back(rigidised);
  }
  if (s.capture->escape) {
    out.push_back({.name = "escape", .requirements = {.synchronised = true}, .configuration = {.arm_awake = true}});
    out.push_back({.name = "escape_retreat", .requirements = {.synchronised = false}, .configuration = {.arm_awake = true}});
  }
  return out;
}

PhaseSequenceParams run_phases(const model::Scenario& scenario) {
  const std::vector<PlannedPhase> plan = planned_phases(scenario);
  PhaseSequenceParams p;
  for (std::size_t i = 0; i < plan.size(); ++i) {
    PhaseSpec phase{.name = plan[i].name, .exits = {}};
    if (i + 1 < plan.size())
      phase.exits.push_back({.condition = at_time(from_seconds(plan[i + 1].start_s)),
                             .to_phase = static_cast<int>(i + 1),
                             .reason = "time"});
    p.phases.push_back(std::move(phase));
  }
  if (conditional_phases(scenario).empty()) return p;
  p.flag_names = {"captured", "braked"};
  // A conditional exit goes first: it wins over a planned one in the same period.
  const auto exit_first = [&p](const char* from, Transition transition) {
    if (const int i = phase_index(p, from); i >= 0) {
      auto& exits = p.phases[static_cast<std::size_t>(i)].exits;
      exits.insert(exits.begin(), std::move(transition));
    }
  };
  if (scenario.capture->rigidise) {
    const int rigidisation = static_cast<int>(p.phases.size());
    exit_first("capture", {.condition = held_for(kCapturedFlag, 0), .to_phase = rigidisation, .reason = "captured"});
    const std::vector<ConditionalPhase> conditional = conditional_phases(scenario);
    p.phases.push_back({.name = conditional[0].name,
                        .exits = {{.condition = held_for(kBrakedFlag, 0), .to_phase = rigidisation + 1, .reason = "brakes engaged"}}});
    p.phases.push_back({.name = conditional[1].name, .exits = {}});
  }
  if (scenario.capture->escape) {
    p.flag_names.insert(p.flag_names.end(), {"escaping", "desynchronised"});
    const int escape = static_cast<int>(p.phases.size());
    for (const char* from : {"reach", "capture"})
      exit_first(from, {.condition = held_for(kEscapingFlag, 0), .to_phase = escape, .reason = "escape"});
    p.phases.push_back({.name = "escape",
                        .exits = {{.condition = held_for(kDesynchronisedFlag, 0), .to_phase = escape + 1,
                                   .reason = "desynchronised"}}});
    p.phases.push_back({.name = "escape_retreat", .exits = {}});
  }
  return p;
}

}  // namespace chaser::sim
