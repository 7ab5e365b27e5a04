#include "plant/earth_orbit_motion.hpp"

#include <algorithm>

namespace chaser::plant {

namespace {

// The perturbed orbit's environment for the period at t_k: the slow terms of its window (sampled
// when the window begins, at the window's midpoint), the torques at the period's own midpoint.
PeriodEnvironment orbit_period_environment(const OrbitPlantParams& earth, EarthOrbitState& state,
                                           const RigidState& chaser, TimeNs t_k, TimeNs period_ns) {
  const OrbitDynamicsParams& dynamics = earth.dynamics;
  const double period_s = to_seconds(period_ns);
  if (!dynamics.hold_slow_environment) {
    return period_environment(dynamics, ephemeris_at_run_time(earth, to_seconds(t_k) + 0.5 * period_s, state.ephemeris),
                              state.orbit, chaser, period_s);
  }
  const std::int64_t periods = environment_periods(dynamics, period_s);
  const std::int64_t window = t_k / period_ns / periods;
  if (window != state.slow_environment.window) {
    const double mid_s = period_s * (static_cast<double>(window * periods) + 0.5 * static_cast<double>(periods));
    const Ephemeris eph_mid = ephemeris_at_run_time(earth, mid_s, state.ephemeris);
    state.slow_environment = {.window = window,
                              .env = slow_environment(dynamics, eph_mid, state.orbit, mid_s - to_seconds(t_k))};
  }
  return period_environment(dynamics, state.slow_environment.env, state.orbit, chaser, period_s);
}

}  // namespace

EarthOrbitParams make_earth_orbit_params(const model::Scenario& scenario) {
  return {.earth = make_orbit_plant_params(scenario)};
}

EarthOrbitState start_earth_orbit(const model::Scenario& scenario, const EarthOrbitParams& params, RigidState& chaser) {
  EarthOrbitState state;
  state.orbit = initial_orbit_state(scenario, params.earth, chaser.r_lvlh_m, chaser.v_lvlh_mps);
  const OrbitDynamicsParams& dynamics = params.earth.dynamics;
  update_lvlh_view(dynamics,
                   period_environment(dynamics, ephemeris_at_run_time(params.earth, 0.0), state.orbit, chaser, 0.0),
                   state.orbit, chaser);
  return state;
}

void begin_period(const EarthOrbitParams& params, EarthOrbitState& state, const RigidState& chaser, TimeNs t_k,
                  TimeNs period_ns) {
  state.env = orbit_period_environment(params.earth, state, chaser, t_k, period_ns);
}

void advance(const EarthOrbitParams& params, EarthOrbitState& state, RigidState& chaser, const ThrustProfile& profile,
             const PeriodDisturbance& disturbance, TimeNs from_ns, TimeNs to_ns) {
  for (int i = 0; i < profile.count; ++i) {
    const ThrustPiece& piece = profile.pieces[i];
    const TimeNs begin_ns = std::max(piece.t_begin_ns, from_ns), end_ns = std::min(piece.t_end_ns, to_ns);
    if (end_ns <= begin_ns) continue;
    propagate_orbit_piece(params.earth.dynamics, state.env, state.orbit, chaser, to_seconds(end_ns - begin_ns),
                          piece_input(piece, disturbance));
  }
  update_lvlh_view(params.earth.dynamics, state.env, state.orbit, chaser);
}

TargetRotation target_rotation(const EarthOrbitParams&, const EarthOrbitState& state, double) {
  return {state.orbit.q_inertial_from_target, state.orbit.omega_target_body_radps};
}

Quat q_inertial_from_lvlh(const EarthOrbitParams& params, const EarthOrbitState& state, const model::TargetOrbit&,
                          double) {
  return q_inertial_from_lvlh(params.earth.dynamics, state.orbit);
}

std::span<const model::SloshState> slosh_states(const EarthOrbitParams& params, const EarthOrbitState& state) {
  return {state.orbit.slosh.data(), static_cast<std::size_t>(params.earth.dynamics.slosh.count)};
}

}  // namespace chaser::plant
