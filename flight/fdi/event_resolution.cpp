#include "flight/fdi/event_resolution.hpp"

#include <cmath>

#include "core/constants.hpp"

namespace chaser::flight::fdi {

std::vector<std::string> validate(const EventResolutionParams& params) {
  std::vector<std::string> problems;
  if (!(params.sensor_sigma_kg >= 0.0)) problems.push_back("event_resolution.sensor_sigma_kg: must be >= 0");
  if (!(params.k_sigma > 0.0)) problems.push_back("event_resolution.k_sigma: must be > 0");
  if (!(params.relative_margin >= 0.0)) problems.push_back("event_resolution.relative_margin: must be >= 0");
  if (!(params.absolute_margin_kg >= 0.0))
    problems.push_back("event_resolution.absolute_margin_kg: must be >= 0");
  if (params.sensor_sigma_kg == 0.0 && params.absolute_margin_kg == 0.0)
    problems.push_back("event_resolution: sensor_sigma_kg or absolute_margin_kg must be > 0");
  return problems;
}

std::array<double, kMaxWatchedThrusters> nominal_mass_flow_kgps(const model::ThrusterSetParams& thrusters,
                                                             const WatchedSet& watched, double isp_s) {
  std::array<double, kMaxWatchedThrusters> flow{};
  for (int k = 0; k < watched.count; ++k)  // the other lanes stay zero
    flow[k] = thrusters.thrusters[static_cast<std::size_t>(watched.index[k])].max_thrust_N / (isp_s * kStandardGravity);
  return flow;
}

double expected_propellant_increment_kg(const WatchedTon& ton,
                                        const std::array<double, kMaxWatchedThrusters>& mass_flow_kgps,
                                        double period_s) {
  double sum = 0.0;
  // Every lane, in order: the lanes past the set's add exact zeros, so the sum is the set's.
  for (int i = 0; i < kMaxWatchedThrusters; ++i) sum += ton(i) * mass_flow_kgps[i];
  return sum * period_s;
}

bool step_event_resolution(const EventResolutionParams& params, EventResolutionState& state,
                           double measured_used_kg, double expected_increment_kg, bool alarm) {
  if (!state.active) {
    if (!alarm) return false;
    state.active = true;  // the reference reading: nothing is predicted yet
    state.reference_kg = measured_used_kg;
    state.expected_since_alarm_kg = 0.0;
    return state.over_consumption;
  }
  state.expected_since_alarm_kg += expected_increment_kg;
  const double excess = measured_used_kg - state.reference_kg - state.expected_since_alarm_kg;
  const double threshold = params.k_sigma * std::sqrt(2.0) * params.sensor_sigma_kg +
                           params.relative_margin * state.expected_since_alarm_kg +
                           params.absolute_margin_kg;
  if (excess > threshold) state.over_consumption = true;
  return state.over_consumption;
}

}  // namespace chaser::flight::fdi
