#include "plant/plant.hpp"

#include "model/run_timing.hpp"
#include "plant/arm_joints.hpp"
#include "plant/target.hpp"

namespace chaser::plant {

PlantStreams::PlantStreams(std::uint64_t seed)
    : delay(seed, "thrusters/delay"),
      force_noise(seed, "environment/force"),
      torque_noise(seed, "environment/torque"),
      propellant_gauge(seed, "sensors/propellant"),
      target_pose(seed, "sensors/target_pose"),
      arm_camera(seed, "sensors/arm_camera"),
      sensors(make_sensor_noise(seed)) {}

Plant make_plant(const model::Scenario& scenario, const RigidState& initial, std::uint64_t seed) {
  const TimeNs period_ns = model::run_timing(scenario).control_period_ns;
  RandomStream dispersion(seed, "thrusters/dispersion");
  PlantParams params{
      .motion = make_circular_orbit_params(scenario),
      .thrusters = make_thruster_hardware(scenario.thrusters, scenario.chaser.com_body_m, scenario.chaser.isp_s,
                                          period_ns, dispersion),
      .sensors = scenario.sensors,
      .environment = scenario.environment,
      .period_ns = period_ns,
      .delay_max_ns = from_seconds(scenario.thrusters.delay_max_s),
  };
  if (scenario.target.body) params.fixture_target_m = scenario.target.body->grasp_point_target_m;
  if (scenario.guidance.synchronised) params.q_target_from_fixture = scenario.guidance.synchronised->q_target_from_body.normalized();
  PlantState state{
      .motion = CircularOrbitState{},
      .chaser = initial,
      .thrusters = ThrusterState{},
      .faults = scenario.faults,
      .sensors = make_sensor_state(scenario.sensors, period_ns),
      .streams = PlantStreams(seed),
      .last_profile = ThrustProfile{},
      .disturbance = PeriodDisturbance{},
  };
  if (scenario.orbit.earth) {
    const EarthOrbitParams earth = make_earth_orbit_params(scenario);
    state.motion = start_earth_orbit(scenario, earth, state.chaser);
    params.motion = earth;
  }
  return Plant{std::move(params), std::move(state)};
}

TargetRotation target_rotation(const Plant& plant, double t_s) {
  return visit_motion(plant.params, plant.state, [&](const auto& p, const auto& s) { return target_rotation(p, s, t_s); });
}

Quat q_inertial_from_lvlh(const Plant& plant, const model::TargetOrbit& circle, double t_s) {
  return visit_motion(plant.params, plant.state,
                      [&](const auto& p, const auto& s) { return q_inertial_from_lvlh(p, s, circle, t_s); });
}

std::span<const model::SloshState> slosh_states(const Plant& plant) {
  return visit_motion(plant.params, plant.state, [](const auto& p, const auto& s) { return slosh_states(p, s); });
}

void inject_fault(Plant& plant, const model::FaultParams& fault) { plant.state.faults.push_back(fault); }

model::SensorMeasurements sense_plant(const PlantParams& params, PlantState& state, TimeNs t,
                                      const Quat& q_inertial_from_lvlh) {
  const RigidState& chaser = state.chaser;
  const Vec3 line_of_sight_m = line_of_sight_body_m(chaser.r_lvlh_m, q_inertial_from_lvlh, chaser.q_inertial_from_body);
  const model::LidarParams& lidar = params.sensors.lidar;
  const bool lidar_sees = sees_target(lidar.fov_half_angle_rad, lidar.range_max_m, line_of_sight_m);
  model::SensorMeasurements meas = sample_sensors(params.sensors, state.sensors, t, chaser.r_lvlh_m,
                                                  chaser.q_inertial_from_body, chaser.omega_body_radps, state.streams.sensors,
                                                  lidar_sees);
  meas.propellant_used_kg = state.propellant_used_kg + state.streams.propellant_gauge.normal(
                                                           0.0, params.sensors.propellant.noise_sigma_kg);
  if (params.sensors.arm_camera) meas.arm = sense_arm_with_camera(params, state, to_seconds(t));
  if (params.sensors.target_pose) {
    const double t_s = to_seconds(t);
    const Quat q_inertial_from_target =
        visit_motion(params, state, [&](const auto& p, const auto& s) { return target_rotation(p, s, t_s); })
            .q_inertial_from_target;
    const bool pose_sees = lidar_sees && line_of_sight_m.norm() <= params.sensors.target_pose->range_max_m;
    meas.target_pose = sample_target_pose(*params.sensors.target_pose, state.sensors, t_s, chaser.q_inertial_from_body,
                                          q_inertial_from_target, state.streams.target_pose, pose_sees);
  }
  return meas;
}

namespace {

Vec3 draw_vector(RandomStream& stream, double sigma) {
  if (sigma == 0.0) return Vec3::Zero();
  const double x = stream.normal(), y = stream.normal(), z = stream.normal();
  return sigma * Vec3(x, y, z);
}

}  // namespace

namespace {

// The period's start that does not depend on the motion model.
void begin_hardware_period(const PlantParams& params, PlantState& state, const model::ThrusterCommand& command,
                           TimeNs t_k) {
  state.thrusters.latch_closed_groups = command.latch_closed_groups;  // the latches act from this period
  // tau(k): one delay for all thrusters, redrawn each period (Fonod 2015, eq. 1 and below).
  state.last_delay_ns = static_cast<TimeNs>(state.streams.delay.uniform() * static_cast<double>(params.delay_max_ns));
  schedule_period(params.thrusters, state.faults, state.thrusters, command, t_k, state.last_delay_ns, state.last_profile);

  // Disturbances: bias plus white noise held over the period.
  const auto& env = params.environment;
  state.disturbance.force_lvlh_N = env.force_bias_lvlh_N + draw_vector(state.streams.force_noise, env.force_noise_sigma_N);
  state.disturbance.torque_body_Nm =
      env.torque_bias_body_Nm + draw_vector(state.streams.torque_noise, env.torque_noise_sigma_Nm);

  state.propellant_used_kg += state.last_profile.propellant_kg;
}

}  // namespace

void begin_plant_period(const PlantParams& params, PlantState& state, const model::ThrusterCommand& command,
                        TimeNs t_k) {
  begin_hardware_period(params, state, command, t_k);
  std::visit(
      [&](const auto& p) {
        using State = typename std::decay_t<decltype(p)>::State;
        begin_period(p, std::get<State>(state.motion), state.chaser, t_k, params.period_ns);
      },
      params.motion);
}

void advance_plant(const PlantParams& params, PlantState& state, TimeNs from_ns, TimeNs to_ns) {
  std::visit(
      [&](const auto& p) {
        using State = typename std::decay_t<decltype(p)>::State;
        advance(p, std::get<State>(state.motion), state.chaser, state.last_profile, state.disturbance, from_ns, to_ns);
      },
      params.motion);
}

// Both halves in one visit of the motion model: the period of every shipped scenario.
void step_plant(const PlantParams& params, PlantState& state, const model::ThrusterCommand& command, TimeNs t_k) {
  begin_hardware_period(params, state, command, t_k);
  std::visit(
      [&](const auto& p) {
        using State = typename std::decay_t<decltype(p)>::State;
        State& motion = std::get<State>(state.motion);
        begin_period(p, motion, state.chaser, t_k, params.period_ns);
        advance(p, motion, state.chaser, state.last_profile, state.disturbance, t_k, t_k + params.period_ns);
      },
      params.motion);
}

}  // namespace chaser::plant
