#include "plant/plant.hpp"

#include "plant/target.hpp"

namespace chaser::plant {

PlantStreams::PlantStreams(std::uint64_t seed)
    : delay(seed, "thrusters/delay"),
      force_noise(seed, "environment/force"),
      torque_noise(seed, "environment/torque"),
      propellant_gauge(seed, "sensors/propellant"),
      target_pose(seed, "sensors/target_pose"),
      sensors(make_sensor_noise(seed)) {}

Plant make_plant(const model::Scenario& scenario, const RigidState& initial, std::uint64_t seed) {
  const TimeNs period_ns = from_seconds(scenario.control_period_s);
  RandomStream dispersion(seed, "thrusters/dispersion");
  PlantParams params{
      .dynamics = make_dynamics_params(scenario),
      .earth = std::nullopt,
      .target = scenario.target,
      .thrusters = make_thruster_hardware(scenario.thrusters, scenario.chaser.com_body_m, scenario.chaser.isp_s,
                                          period_ns, dispersion),
      .faults = scenario.faults,
      .sensors = scenario.sensors,
      .environment = scenario.environment,
      .period_ns = period_ns,
      .delay_max_ns = from_seconds(scenario.thrusters.delay_max_s),
  };
  PlantState state{
      .rigid = initial,
      .orbit = OrbitState{},
      .ephemeris = EphemerisSamples{},
      .slow_environment = SlowEnvironmentSample{},
      .thrusters = ThrusterState{},
      .sensors = make_sensor_state(scenario.sensors, period_ns),
      .streams = PlantStreams(seed),
      .last_profile = ThrustProfile{},
  };
  if (scenario.orbit.earth) {
    params.earth = make_orbit_plant_params(scenario);
    state.orbit = initial_orbit_state(scenario, *params.earth, initial.r_lvlh_m, initial.v_lvlh_mps);
    const OrbitDynamicsParams& dynamics = params.earth->dynamics;
    update_lvlh_view(dynamics,
                     period_environment(dynamics, ephemeris_at_run_time(*params.earth, 0.0), state.orbit, state.rigid, 0.0),
                     state.orbit, state.rigid);
  }
  return Plant{std::move(params), std::move(state)};
}

TargetRotation target_rotation(const Plant& plant, double t_s) {
  if (plant.params.earth) return {plant.state.orbit.q_inertial_from_target, plant.state.orbit.omega_target_body_radps};
  return target_rotation(plant.params.target, t_s);
}

Quat q_inertial_from_lvlh(const Plant& plant, const model::TargetOrbit& circle, double t_s) {
  if (!plant.params.earth) return circle.q_inertial_from_lvlh(t_s);
  return q_inertial_from_lvlh(plant.params.earth->dynamics, plant.state.orbit);
}

model::SensorMeasurements sense_plant(const PlantParams& params, PlantState& state, TimeNs t) {
  model::SensorMeasurements meas =
      sample_sensors(params.sensors, state.sensors, t, state.rigid.r_lvlh_m, state.rigid.q_inertial_from_body,
                     state.rigid.omega_body_radps, state.streams.sensors);
  meas.propellant_used_kg = state.propellant_used_kg + state.streams.propellant_gauge.normal(
                                                           0.0, params.sensors.propellant.noise_sigma_kg);
  if (params.sensors.target_pose) {
    const double t_s = to_seconds(t);
    const Quat q_inertial_from_target = params.earth ? state.orbit.q_inertial_from_target
                                                     : target_rotation(params.target, t_s).q_inertial_from_target;
    meas.target_pose = sample_target_pose(*params.sensors.target_pose, state.sensors, t_s,
                                          state.rigid.q_inertial_from_body, q_inertial_from_target,
                                          state.streams.target_pose);
  }
  return meas;
}

namespace {

Vec3 draw_vector(RandomStream& stream, double sigma) {
  if (sigma == 0.0) return Vec3::Zero();
  const double x = stream.normal(), y = stream.normal(), z = stream.normal();
  return sigma * Vec3(x, y, z);
}

// One thrust piece with the period's disturbances added.
PieceInput piece_input(const ThrustPiece& piece, const Vec3& torque_dist_body_Nm, const Vec3& force_dist_lvlh_N) {
  return PieceInput{
      .force_body_N = piece.force_body_N,
      .torque_body_Nm = piece.torque_body_Nm + torque_dist_body_Nm,
      .force_lvlh_N = force_dist_lvlh_N,
      .mass_flow_kgps = piece.mass_flow_kgps,
  };
}

// The perturbed orbit's environment for the period at t_k: the slow terms of its window (sampled
// when the window begins, at the window's midpoint), the torques at the period's own midpoint.
PeriodEnvironment orbit_period_environment(const OrbitPlantParams& earth, PlantState& state, TimeNs t_k,
                                           TimeNs period_ns) {
  const OrbitDynamicsParams& dynamics = earth.dynamics;
  const double period_s = to_seconds(period_ns);
  if (!dynamics.hold_slow_environment) {
    return period_environment(dynamics, ephemeris_at_run_time(earth, to_seconds(t_k) + 0.5 * period_s, state.ephemeris),
                              state.orbit, state.rigid, period_s);
  }
  const std::int64_t periods = environment_periods(dynamics, period_s);
  const std::int64_t window = t_k / period_ns / periods;
  if (window != state.slow_environment.window) {
    const double mid_s = period_s * (static_cast<double>(window * periods) + 0.5 * static_cast<double>(periods));
    const Ephemeris eph_mid = ephemeris_at_run_time(earth, mid_s, state.ephemeris);
    state.slow_environment = {.window = window,
                              .env = slow_environment(dynamics, eph_mid, state.orbit, mid_s - to_seconds(t_k))};
  }
  return period_environment(dynamics, state.slow_environment.env, state.orbit, state.rigid, period_s);
}

// The perturbed orbit's period: the environment (orbit_period_environment), each piece
// propagated, then the LVLH view of the relative state refreshed for the sensors.
void step_orbit_plant(const OrbitPlantParams& earth, PlantState& state, const ThrustProfile& profile,
                      const Vec3& torque_dist_body_Nm, const Vec3& force_dist_lvlh_N, TimeNs t_k, TimeNs period_ns) {
  const PeriodEnvironment env = orbit_period_environment(earth, state, t_k, period_ns);
  for (int i = 0; i < profile.count; ++i) {
    const ThrustPiece& piece = profile.pieces[i];
    const PieceInput input = piece_input(piece, torque_dist_body_Nm, force_dist_lvlh_N);
    propagate_orbit_piece(earth.dynamics, env, state.orbit, state.rigid, to_seconds(piece.t_end_ns - piece.t_begin_ns),
                          input);
  }
  update_lvlh_view(earth.dynamics, env, state.orbit, state.rigid);
}

}  // namespace

void step_plant(const PlantParams& params, PlantState& state, const model::ThrusterCommand& command, TimeNs t_k) {
  state.thrusters.latch_closed_groups = command.latch_closed_groups;  // the latches act from this period
  // tau(k): one delay for all thrusters, redrawn each period (Fonod 2015, eq. 1 and below).
  state.last_delay_ns = static_cast<TimeNs>(state.streams.delay.uniform() * static_cast<double>(params.delay_max_ns));
  schedule_period(params.thrusters, params.faults, state.thrusters, command, t_k, state.last_delay_ns,
                  state.last_profile);

  // Disturbances: bias plus white noise held over the period.
  const auto& env = params.environment;
  const Vec3 force_dist_lvlh_N = env.force_bias_lvlh_N + draw_vector(state.streams.force_noise, env.force_noise_sigma_N);
  const Vec3 torque_dist_body_Nm =
      env.torque_bias_body_Nm + draw_vector(state.streams.torque_noise, env.torque_noise_sigma_Nm);

  const ThrustProfile& profile = state.last_profile;
  state.propellant_used_kg += profile.propellant_kg;
  if (params.earth) {
    step_orbit_plant(*params.earth, state, profile, torque_dist_body_Nm, force_dist_lvlh_N, t_k, params.period_ns);
    return;
  }
  for (int i = 0; i < profile.count; ++i) {
    const ThrustPiece& piece = profile.pieces[i];
    const PieceInput input = piece_input(piece, torque_dist_body_Nm, force_dist_lvlh_N);
    propagate_piece(params.dynamics, state.rigid, to_seconds(piece.t_begin_ns),
                    to_seconds(piece.t_end_ns - piece.t_begin_ns), input);
  }
}

}  // namespace chaser::plant
