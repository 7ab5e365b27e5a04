// What the thruster set can do, checked before a run: the set that flies at the start, and every
// set a recovery can lead to, must push and turn in every direction (its configuration matrix's
// columns positively span R^6); the Fonod 2015 schemes' fixed-size kernels must fit the active set
// (the deficit bank and detector watch any set); a scenario
// may require that every single-thruster loss leaves a spanning set; faults must name thrusters
// that exist.
#include <algorithm>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <string>
#include <vector>

#include "io/scenario_sections.hpp"
#include "model/positive_span.hpp"
#include "model/recovery.hpp"
#include "model/thruster_geometry.hpp"

namespace chaser::io {
namespace {

// "T1..T8" for a contiguous run, else "T1, T3, T9".
std::string list_thrusters(model::ThrusterMask mask) {
  const model::ThrusterList list = model::thruster_list(mask);
  if (list.count == 0) return "no thruster";
  const bool contiguous = list.index[list.count - 1] - list.index[0] == list.count - 1;
  if (contiguous && list.count > 2)
    return fmt::format("{}..{}", model::thruster_name(list.index[0]), model::thruster_name(list.index[list.count - 1]));
  std::string out;
  for (int k = 0; k < list.count; ++k) out += (k ? ", " : "") + model::thruster_name(list.index[k]);
  return out;
}

// "group B (T9..T16)" when the set is exactly some groups, else its thrusters.
std::string describe_set(const model::ThrusterSetParams& set, model::ThrusterMask mask) {
  std::vector<std::string> names;
  model::ThrusterMask covered = 0;
  for (int g = 0; g < static_cast<int>(set.groups.size()); ++g) {
    const model::ThrusterMask members = model::group_thrusters(set, g);
    if (members != 0 && (members & ~mask) == 0) {
      names.push_back(set.groups[static_cast<std::size_t>(g)].name);
      covered |= members;
    }
  }
  if (covered != mask || names.empty()) return list_thrusters(mask);
  return fmt::format("{} {} ({})", names.size() == 1 ? "group" : "groups", fmt::join(names, ", "), list_thrusters(mask));
}

// An empty string when the set spans, else why not.
std::string span_problem(const model::Scenario& s, model::ThrusterMask mask) {
  if (model::thruster_count(mask) == 0) return "is empty";
  const model::PositiveSpanResult span =
      model::positive_span(model::configuration_columns(s.thrusters, mask, s.chaser.com_body_m));
  if (span.spans) return {};
  return fmt::format("cannot produce force and torque in every direction: no on-times >= 0 give a wrench "
                     "along [{:.3f}] (force; torque about the centre of mass; M has rank {} of 6; "
                     "positive-span tolerance {})",
                     fmt::join(span.blocked_direction, ", "), span.rank, format_number(model::kPositiveSpanTolerance));
}

bool fdi_watches(const model::FdiParams& f) {
  return f.position.enabled || f.attitude.enabled ||
         (f.isolation_method == model::IsolationMethod::kDeficit && f.deficit.detection) || f.rate_check.enabled;
}

// Every set the vehicle may fly (model::reachable_configurations: the start, then each set the
// recovery policy can switch to, fault after fault), checked for span and, with a Fonod 2015
// scheme on, for its set size.
void check_configurations(const model::Scenario& s, Diagnostics& d) {
  const bool fdi = fdi_watches(s.fdi);
  const bool schemes = s.fdi.position.enabled || s.fdi.attitude.enabled;
  for (const model::ReachableConfiguration& r : model::reachable_configurations(s.thrusters, s.fdi.recovery)) {
    const model::ThrusterMask active = r.configuration.active;
    const std::string flies = model::when_it_flies(s.thrusters, r);
    const std::string set = describe_set(s.thrusters, active);
    if (const std::string problem = span_problem(s, active); !problem.empty())
      d.add("thrusters.list", fmt::format("{}, {}, {}", flies, set, problem));
    if (schemes && model::thruster_count(active) != model::kFdiSchemeThrusters)
      d.add("fdi", fmt::format("fdi.position and fdi.attitude (the Fonod 2015 schemes) watch exactly {} active "
                               "thrusters; {}, {}, has {}: disable fdi.position and fdi.attitude (the deficit "
                               "detector, fdi.deficit.detection, watches any set), or fly {} at a time "
                               "(thrusters.standby_groups)",
                               model::kFdiSchemeThrusters, flies, set, model::thruster_count(active),
                               model::kFdiSchemeThrusters));
  }
  // A check only costs propellant unless a scheme watches the pulse it fires.
  if (s.fdi.active_check.enabled && !fdi)
    d.add("fdi.active_check.enabled", "is true, but no FDI scheme watches the checks: enable fdi.position, "
                                      "fdi.attitude, fdi.deficit.detection or fdi.rate_check, or set it false");
  if (s.fdi.recovery == model::RecoveryPolicy::kSwitchGroup &&
      std::none_of(s.thrusters.groups.begin(), s.thrusters.groups.end(), [](const auto& g) { return g.standby; }))
    d.add("fdi.recovery", "switch_group needs a standby group to switch to (thrusters.standby_groups), "
                          "or set fdi.recovery: none");
}

// tolerates_single_loss: every thruster of the starting set may be lost alone.
void check_single_losses(const model::Scenario& s, Diagnostics& d) {
  if (!s.thrusters.tolerates_single_loss) return;
  const model::ThrusterMask start = model::initial_active_set(s.thrusters);
  const model::ThrusterList list = model::thruster_list(start);
  for (int k = 0; k < list.count; ++k) {
    const model::ThrusterMask without = start & ~model::thruster_bit(list.index[k]);
    if (const std::string problem = span_problem(s, without); !problem.empty())
      d.add("thrusters.tolerates_single_loss",
            fmt::format("is true, but without {} the set that flies at the start {}", model::thruster_name(list.index[k]),
                        problem));
  }
}

// fdi.supervisor.accommodate: each monitored thruster's modes fly the starting set without it.
void check_supervised_sets(const model::Scenario& s, Diagnostics& d) {
  const model::SupervisorParams& v = s.fdi.supervisor;
  if (!v.enabled || !v.accommodate || !d.clean("fdi.supervisor.thrusters")) return;
  const model::ThrusterMask start = model::initial_active_set(s.thrusters);
  for (int t = 0; t < model::kMaxThrusters; ++t) {
    if (!(v.thrusters >> t & 1U) || !(start >> t & 1U)) continue;
    if (const std::string problem = span_problem(s, start & ~model::thruster_bit(t)); !problem.empty())
      d.add("fdi.supervisor.thrusters",
            fmt::format("{}'s modes fly the set that flies at the start without it, which {}", model::thruster_name(t),
                        problem));
  }
}

void check_fault_thrusters(const model::Scenario& s, Diagnostics& d) {
  for (std::size_t i = 0; i < s.faults.size(); ++i) {
    const std::string path = fmt::format("faults.{}.thruster", i);
    if (d.clean(path) && s.faults[i].thruster >= s.thrusters.count)
      d.add(path, fmt::format("must name one of T1..{} (thrusters.list has {}) (got {})",
                              model::thruster_name(s.thrusters.count - 1), s.thrusters.count,
                              model::thruster_name(s.faults[i].thruster)));
  }
}

}  // namespace

void validate_thruster_set(const model::Scenario& s, Diagnostics& d) {
  if (s.thrusters.count > 0) check_fault_thrusters(s, d);  // the list's length is known even if an entry is wrong
  if (!d.clean("thrusters.list")) return;
  if (!d.clean("chaser.com_body_m") || !d.clean("thrusters.standby_groups")) return;
  check_configurations(s, d);
  check_single_losses(s, d);
  check_supervised_sets(s, d);
}

}  // namespace chaser::io
