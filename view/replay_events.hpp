#pragma once
// The moments a replay lets a person jump to (docs/view.md): each fault's onset, every alarm and
// isolation of each diagnosis scheme and every change of the active thruster set (a recovery), read
// from the telemetry row by row; each phase's start and the capture's steps, from summary.json.
// Never decimated: every one is in the page.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/telemetry.hpp"

namespace chaser::view {

struct ReplayEvent {
  double t_s = 0.0;
  std::string kind;    // "fault", "alarm", "isolation", "recovery", "phase", "capture", "diverged"
  std::string label;   // what a person reads on the timeline
  int thruster = -1;   // the thruster's index for a fault or an isolation, -1 otherwise
};

// In time order (stable for equal times).
std::vector<ReplayEvent> replay_events(const sim::TelemetryRows& telemetry, const nlohmann::json& summary);

// The active set after each change, from the first row: (t_s, mask) pairs, bit i for thruster i.
struct ActiveSetChange {
  double t_s = 0.0;
  unsigned mask = 0;
};
std::vector<ActiveSetChange> active_set_changes(const sim::TelemetryRows& telemetry);

}  // namespace chaser::view
