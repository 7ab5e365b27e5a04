#include "flight/active_check.hpp"

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
  return problems;
}

namespace {

// A thruster that joins the active set (at the start, or by a recovery) is unverified from then on.
void follow_active_set(ActiveCheckState& state, model::ThrusterMask active, double t_s) {
  const model::ThrusterMask joined = active & ~state.active;
  for (int i = 0; i < model::kMaxThrusters; ++i)
    if (model::has_thruster(joined, i)) state.verified_s[static_cast<std::size_t>(i)] = t_s;
  state.active = active;
}

// The stalest active thruster past the bound; the lowest index among equals.
int stalest_unverified(const ActiveCheckParams& p, const ActiveCheckState& state, double t_s) {
  int chosen = model::kNoThruster;
  double stalest_s = p.max_unverified_s;
  for (int i = 0; i < model::kMaxThrusters; ++i) {
    if (!model::has_thruster(state.active, i)) continue;
    const double stale_s = t_s - state.verified_s[static_cast<std::size_t>(i)];
    if (stale_s > stalest_s || (chosen == model::kNoThruster && stale_s >= stalest_s)) {
      chosen = i;
      stalest_s = stale_s;
    }
  }
  return chosen;
}

}  // namespace

int step_active_check(const ActiveCheckParams& p, ActiveCheckState& state, const ActiveCheckInput& in,
                      const model::ThrusterOnTimes& ton) {
  state.next = model::kNoThruster;
  if (!p.enabled) return state.next;
  follow_active_set(state, in.active, in.t_s);
  for (int i = 0; i < model::kMaxThrusters; ++i)
    if (model::has_thruster(state.active, i) && ton[static_cast<std::size_t>(i)] >= p.informative_fraction)
      state.verified_s[static_cast<std::size_t>(i)] = in.t_s;
  if (in.range_m < p.keep_quiet_range_m) return state.next;  // the keep-quiet zone: no check
  state.next = stalest_unverified(p, state, in.t_s);
  return state.next;
}

}  // namespace chaser::flight
