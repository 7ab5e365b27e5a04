#include "flight/active_check.hpp"

#include <bit>
#include <limits>

#include <fmt/format.h>

namespace chaser::flight {

ActiveCheckParams make_active_check_params(const model::Scenario& scenario) {
  const model::ActiveCheckParams& s = scenario.fdi.active_check;
  return ActiveCheckParams{
      .enabled = s.enabled,
      .max_unverified_s = s.max_unverified_s,
      .pulse_fraction = s.pulse_s / scenario.control_period_s,
      .informative_fraction = s.informative_on_time_s / scenario.control_period_s,
      .keep_quiet_range_m = s.keep_quiet_range_m,
      .arm_range_m = s.arm_range_m,
      // At 1 the gain of a suspect (above it) has raised the alarm: never a recheck.
      .recheck_gain = s.recheck_fraction * scenario.fdi.deficit.detection_threshold,
  };
}

std::vector<std::string> validate(const ActiveCheckParams& p) {
  std::vector<std::string> problems;
  if (!(p.max_unverified_s > 0))
    problems.push_back(fmt::format("max_unverified_s must be > 0 (got {})", p.max_unverified_s));
  if (!(p.pulse_fraction > 0 && p.pulse_fraction <= 1))
    problems.push_back(fmt::format("pulse_fraction must be in (0, 1] (got {})", p.pulse_fraction));
  if (!(p.informative_fraction > 0 && p.informative_fraction <= p.pulse_fraction))
    problems.push_back(fmt::format("informative_fraction must be in (0, pulse_fraction = {}] (got {})",
                                   p.pulse_fraction, p.informative_fraction));
  if (!(p.keep_quiet_range_m >= 0))
    problems.push_back(fmt::format("keep_quiet_range_m must be >= 0 (got {})", p.keep_quiet_range_m));
  if (!(p.arm_range_m > p.keep_quiet_range_m))
    problems.push_back(fmt::format("arm_range_m must be > keep_quiet_range_m = {} (got {})", p.keep_quiet_range_m,
                                   p.arm_range_m));
  if (!(p.recheck_gain > 0))
    problems.push_back(fmt::format("recheck_gain must be > 0 (got {})", p.recheck_gain));
  return problems;
}

namespace {

// A thruster that joins the active set (at the start, or by a recovery) is unverified from then on.
void follow_active_set(ActiveCheckState& state, model::ThrusterMask active, double t_s) {
  for (model::ThrusterMask joined = active & ~state.active; joined != 0; joined &= joined - 1)
    state.verified_s[static_cast<std::size_t>(std::countr_zero(joined))] = t_s;
  state.active = active;
}

}  // namespace

// One pass over the active set's bits (every period, so no loop over the whole capacity): record
// this period's informative pulses, and find the stalest thruster, the lowest index among equals.
int step_active_check(const ActiveCheckParams& p, ActiveCheckState& state, const ActiveCheckInput& in,
                      const model::ThrusterOnTimes& ton) {
  state.next = model::kNoThruster;
  if (!p.enabled) return state.next;
  if (in.active != state.active) follow_active_set(state, in.active, in.t_s);
  int stalest = model::kNoThruster;
  double stalest_verified_s = 0;
  for (model::ThrusterMask left = state.active; left != 0; left &= left - 1) {
    const auto i = static_cast<std::size_t>(std::countr_zero(left));
    if (ton[i] >= p.informative_fraction) state.verified_s[i] = in.t_s;
    // A suspect is unverified, whatever it fired, and stalest of all.
    if (static_cast<int>(i) == in.suspect) state.verified_s[i] = -std::numeric_limits<double>::infinity();
    if (stalest == model::kNoThruster || state.verified_s[i] < stalest_verified_s) {
      stalest = static_cast<int>(i);
      stalest_verified_s = state.verified_s[i];
    }
  }
  if (!in.fdi_listening) return state.next;                  // nothing a check shows would be read
  if (in.range_m < p.keep_quiet_range_m) return state.next;  // the keep-quiet zone: no check
  if (in.range_m > p.arm_range_m) return state.next;         // not yet armed
  if (stalest != model::kNoThruster && in.t_s - stalest_verified_s >= p.max_unverified_s) state.next = stalest;
  return state.next;
}

}  // namespace chaser::flight
