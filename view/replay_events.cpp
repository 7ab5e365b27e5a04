#include "view/replay_events.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

#include <fmt/format.h>

namespace chaser::view {

namespace {

int column(const sim::TelemetryRows& rows, const std::string& name) {
  const auto it = std::find(rows.channels.begin(), rows.channels.end(), name);
  return it == rows.channels.end() ? -1 : static_cast<int>(it - rows.channels.begin());
}

double value(const sim::TelemetryRows& rows, std::size_t r, int c) {
  return rows.values[r * rows.channels.size() + static_cast<std::size_t>(c)];
}

// "T3, T5" for the set bits of a mask.
std::string thruster_names(unsigned mask) {
  std::string names;
  for (int i = 0; i < 32; ++i)
    if ((mask >> i) & 1U) names += fmt::format("{}T{}", names.empty() ? "" : ", ", i + 1);
  return names;
}

// Each scheme's alarms (rising edges) and isolations (a thruster newly confirmed).
void scheme_events(const sim::TelemetryRows& rows, std::vector<ReplayEvent>& out) {
  for (const char* scheme : {"position", "attitude", "deficit"}) {
    const int alarm = column(rows, fmt::format("alarm_{}", scheme));
    const int confirmed = column(rows, fmt::format("confirmed_{}", scheme));
    double last_alarm = 0.0, last_confirmed = 0.0;
    for (std::size_t r = 0; r < rows.rows(); ++r) {
      const double t = value(rows, r, 0);
      if (alarm >= 0) {
        const double a = value(rows, r, alarm);
        if (a > 0.5 && last_alarm <= 0.5) out.push_back({t, "alarm", fmt::format("alarm: {} scheme", scheme), -1});
        last_alarm = a;
      }
      if (confirmed >= 0) {
        const double n = value(rows, r, confirmed);
        if (n >= 1.0 && n != last_confirmed)
          out.push_back({t, "isolation", fmt::format("T{} isolated: {} scheme", static_cast<int>(n), scheme), static_cast<int>(n) - 1});
        last_confirmed = n;
      }
    }
  }
}

double number_or(const nlohmann::json& j, const char* key, double fallback) {
  return j.is_object() && j.contains(key) && j[key].is_number() ? j[key].get<double>() : fallback;
}

void summary_events(const nlohmann::json& summary, std::vector<ReplayEvent>& out) {
  if (summary.contains("faults") && summary["faults"].is_array())
    for (const nlohmann::json& f : summary["faults"]) {
      const std::string name = f.value("thruster", "");
      const int index = name.size() > 1 && name[0] == 'T' ? std::atoi(name.c_str() + 1) - 1 : -1;
      out.push_back({number_or(f, "onset_s", 0.0), "fault", fmt::format("{} {} (fault onset)", name, f.value("kind", "fault")), index});
    }
  if (summary.contains("phases_flown") && summary["phases_flown"].is_array())
    for (const nlohmann::json& p : summary["phases_flown"]) out.push_back({number_or(p, "start_s", 0.0), "phase", "phase: " + p.value("name", "?"), -1});
  if (const double at = number_or(summary, "diverged_at_s", -1.0); summary.value("diverged", false) && at >= 0.0)
    out.push_back({at, "diverged", "the truth diverged: run ended", -1});
  const nlohmann::json reach = summary.contains("reach") ? summary["reach"] : nlohmann::json();
  if (!reach.is_object()) return;
  const auto step = [&](const char* section, const char* key, const char* label) {
    if (reach.contains(section) && reach[section].is_object())
      if (const double t = number_or(reach[section], key, -1.0); t >= 0.0) out.push_back({t, "capture", label, -1});
  };
  step("grasp", "closure_s", "capture: jaws closed");
  step("grasp", "lock_s", "capture: gripper locked");
  step("rigidisation", "brakes_s", "rigidisation: brakes engaged");
  step("stabilisation", "below_goal_s", "stabilisation: rate below goal");
  step("berthing", "soft_dock_s", "berthing: soft dock (latches)");
  step("berthing", "hard_dock_s", "berthing: hard dock (pins)");
  if (const double t = number_or(reach, "hold_from_s", -1.0); t >= 0.0) out.push_back({t, "capture", "reach: gripper over the hold", -1});
}

}  // namespace

std::vector<ActiveSetChange> active_set_changes(const sim::TelemetryRows& rows) {
  std::vector<ActiveSetChange> changes;
  const int c = column(rows, "active_thrusters");
  if (c < 0) return changes;
  for (std::size_t r = 0; r < rows.rows(); ++r) {
    const auto mask = static_cast<unsigned>(value(rows, r, c));
    if (changes.empty() || changes.back().mask != mask) changes.push_back({value(rows, r, 0), mask});
  }
  return changes;
}

std::vector<ReplayEvent> replay_events(const sim::TelemetryRows& telemetry, const nlohmann::json& summary) {
  std::vector<ReplayEvent> events;
  scheme_events(telemetry, events);
  const std::vector<ActiveSetChange> active = active_set_changes(telemetry);
  for (std::size_t i = 1; i < active.size(); ++i) {
    const unsigned before = active[i - 1].mask, after = active[i].mask;
    const unsigned in = after & ~before, out = before & ~after;
    const std::string label = fmt::format("recovery:{}{}{}", in ? fmt::format(" {} in", thruster_names(in)) : "",
                                          in && out ? ";" : "", out ? fmt::format(" {} out", thruster_names(out)) : "");
    events.push_back({active[i].t_s, "recovery", label, -1});
  }
  summary_events(summary, events);
  std::stable_sort(events.begin(), events.end(), [](const ReplayEvent& a, const ReplayEvent& b) { return a.t_s < b.t_s; });
  return events;
}

}  // namespace chaser::view
