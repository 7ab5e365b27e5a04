#include "invsim/noise_draws.hpp"

#include <cmath>
#include <utility>

#include "invsim/paper_reading.hpp"

namespace chaser::invsim {

std::uint64_t noise_draws_per_mode(const model::InvSimParams& params) {
  const model::InvSimMeasurementNoise& noise = flight_choices(params).measurement_noise;
  return noise.enabled() ? noise.draws : 1;
}

std::uint64_t noise_draw_seed(const model::InvSimParams& params, std::uint64_t i) {
  return params.pulses.paper.measurement_noise.seed + i;
}

model::InvSimParams noise_draw(const model::InvSimParams& params, std::uint64_t i) {
  model::InvSimParams draw = params;
  draw.pulses.paper.measurement_noise.seed = noise_draw_seed(params, i);
  return draw;
}

std::vector<InvSimResult> fly_noise_draws(const model::InvSimParams& params, const model::InvSimFaultSet& faults) {
  const std::uint64_t draws = noise_draws_per_mode(params);
  if (draws <= 1) return {run_inverse_simulation(params, faults)};
  std::vector<InvSimResult> results;
  results.reserve(draws);
  for (std::uint64_t i = 0; i < draws; ++i) results.push_back(run_inverse_simulation(noise_draw(params, i), faults));
  return results;
}

InvSimResult run_over_noise_draws(const model::InvSimParams& params, const model::InvSimFaultSet& faults) {
  std::vector<InvSimResult> results = fly_noise_draws(params, faults);
  if (results.size() == 1) return std::move(results.front());
  return combine_draws(results, params.pulses.basic_pulse_amount);
}

InvSimResult combine_draws(const std::vector<InvSimResult>& draws, double basic_pulse_amount) {
  InvSimResult out = draws.front();
  const double n = static_cast<double>(draws.size());
  double total = 0.0, propellant = 0.0, attitude_propellant = 0.0;
  std::array<std::array<double, 2>, 3> counts{}, on_time{};
  Vec3 couple_on_time = Vec3::Zero();
  for (const InvSimResult& r : draws) {
    for (int axis = 0; axis < 3; ++axis) {
      for (int d = 0; d < 2; ++d) {
        counts[axis][d] += r.pulses[axis].count[d];
        on_time[axis][d] += r.pulses[axis].on_time_s[d];
      }
    }
    total += r.total_pulses;
    propellant += r.propellant_kg;
    attitude_propellant += r.attitude_propellant_kg;
    couple_on_time += r.attitude_on_time_s;
    out.peak_azimuth_rad = std::max(out.peak_azimuth_rad, r.peak_azimuth_rad);
    out.peak_elevation_rad = std::max(out.peak_elevation_rad, r.peak_elevation_rad);
    out.peak_attitude_rad = out.peak_attitude_rad.cwiseMax(r.peak_attitude_rad);
    out.target_always_in_view = out.target_always_in_view && r.target_always_in_view;
    out.attitude_within_limits = out.attitude_within_limits && r.attitude_within_limits;
    out.docked = out.docked && r.docked;
    out.diverged = out.diverged || r.diverged;
  }
  for (int axis = 0; axis < 3; ++axis) {
    for (int d = 0; d < 2; ++d) {
      out.pulses[axis].count[d] = static_cast<int>(std::lround(counts[axis][d] / n));
      out.pulses[axis].on_time_s[d] = on_time[axis][d] / n;
    }
  }
  out.total_pulses = static_cast<int>(std::lround(total / n));
  out.k_p = total / n / basic_pulse_amount;  // eq. 22 on the mean P
  out.propellant_kg = propellant / n;
  out.attitude_propellant_kg = attitude_propellant / n;
  out.attitude_on_time_s = couple_on_time / n;
  return out;
}

}  // namespace chaser::invsim
