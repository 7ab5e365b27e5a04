#include "sim/run.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <memory>

#include "core/rotation.hpp"
#include "flight/flight_software.hpp"
#include "plant/plant.hpp"
#include "plant/target.hpp"
#include "sim/telemetry_channels.hpp"

namespace chaser::sim {

namespace {

// The chaser's truth at t = 0: on the approach axis at the start distance, at rest and pointing at
// the target, unless the scenario gives the state explicitly.
plant::RigidState initial_truth(const model::Scenario& s, const model::TargetOrbit& orbit) {
  const model::InitialState& init = s.initial;
  plant::RigidState x{};
  x.mass_kg = s.chaser.mass_kg;
  if (init.use_guidance_start) {
    const flight::GuidanceRef ref = flight::guidance_reference(s.guidance, orbit, 0.0);
    x.r_lvlh_m = ref.r_lvlh_m;
    x.v_lvlh_mps = ref.v_lvlh_mps;
    x.q_inertial_from_body = ref.q_inertial_from_body;
    x.omega_body_radps = ref.omega_body_radps;
  } else {
    x.r_lvlh_m = init.r_lvlh_m;
    x.v_lvlh_mps = init.v_lvlh_mps;
    x.q_inertial_from_body = orbit.q_inertial_from_lvlh(0.0) * init.q_lvlh_from_body;
    x.omega_body_radps = init.omega_body_radps;
  }
  return x;
}

MonitorSample monitor_sample(double t_s, const Quat& q_inertial_from_lvlh, const plant::RigidState& x,
                             const flight::GuidanceRef& ref) {
  return MonitorSample{
      .t_s = t_s,
      .r_lvlh_m = x.r_lvlh_m,
      .v_lvlh_mps = x.v_lvlh_mps,
      .q_inertial_from_body = x.q_inertial_from_body,
      .r_ref_lvlh_m = ref.r_lvlh_m,
      .v_ref_lvlh_mps = ref.v_lvlh_mps,
      .q_ref_inertial_from_body = ref.q_inertial_from_body,
      .q_inertial_from_lvlh = q_inertial_from_lvlh,
  };
}

SchemeResult scheme_result(bool enabled, const flight::SchemeSummary& s) {
  SchemeResult r;
  r.enabled = enabled;
  r.alarm_s = s.alarm_s;
  r.isolated_s = s.isolated_s;
  r.isolated_thruster = s.confirmed;
  if (s.diagnosis.decided && s.diagnosis.thruster >= 0) {
    r.diagnosed_kind = s.diagnosis.kind;
    r.diagnosed_size = s.diagnosis.size;
    r.estimated_onset_s = s.estimated_onset_s;
  }
  return r;
}

FdirResult episode_result(const flight::FlightParams& p, const flight::FdirEpisode& e) {
  FdirResult r{
      .position = scheme_result(p.fdir.position_enabled, e.position),
      .attitude = scheme_result(p.fdir.attitude_enabled, e.attitude),
      .deficit = scheme_result(p.fdir.deficit_detection, e.detector),
      .recovery_s = e.recovery_s,
      .recovered_thruster = e.recovered_thruster,
      .episodes = {},
  };
  for (const SchemeResult* scheme : {&r.position, &r.attitude, &r.deficit}) {
    if (scheme->alarm_s >= 0 && (r.detection_s < 0 || scheme->alarm_s < r.detection_s)) r.detection_s = scheme->alarm_s;
    if (scheme->isolated_s >= 0 && (r.isolation_s < 0 || scheme->isolated_s < r.isolation_s))
      r.isolation_s = scheme->isolated_s, r.isolated_thruster = scheme->isolated_thruster;
  }
  return r;
}

// The first diagnosis (ended by a recovery, or still running) as the run's FDIR result, and every
// diagnosis in order as its episodes.
FdirResult fdir_result(const flight::FlightParams& p, const flight::FlightState& s) {
  const flight::FdirState& f = s.fdir;
  std::vector<FdirResult> episodes;
  for (int i = 0; i < f.episode_count; ++i) episodes.push_back(episode_result(p, f.episodes[static_cast<std::size_t>(i)]));
  if (f.armed) episodes.push_back(episode_result(p, flight::current_episode(p.fdir, f)));
  FdirResult r = episodes.empty() ? episode_result(p, flight::current_episode(p.fdir, f)) : episodes.front();
  r.episodes = std::move(episodes);
  return r;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

RunResult run_scenario(const model::Scenario& scenario, const RunOptions& options) {
  const auto wall_start = std::chrono::steady_clock::now();
  const flight::FlightParams flight_params = flight::make_flight_params(scenario);
  const double design_s = seconds_since(wall_start);
  RunResult result = run_scenario(scenario, flight_params, options);
  result.wall_design_s = design_s;
  result.wall_s = seconds_since(wall_start);
  return result;
}

RunResult run_scenario(const model::Scenario& scenario, const flight::FlightParams& flight_params,
                       const RunOptions& options) {
  const auto wall_start = std::chrono::steady_clock::now();
  const model::TargetOrbit orbit(scenario.orbit);  // the truth's, for the initial state and the monitor
  const TimeNs period_ns = from_seconds(scenario.control_period_s);
  const std::int64_t periods = from_seconds(scenario.duration_s) / period_ns;

  plant::Plant plant = plant::make_plant(scenario, initial_truth(scenario, orbit), scenario.seed);
  flight::FlightState flight_state;

  std::unique_ptr<TelemetryWriter> telemetry;
  TelemetryRows* const memory = options.telemetry_rows;
  std::vector<TelemetryChannel> channels;
  const bool every_channel = options.telemetry_channels.empty();  // the whole table, record_every_channel
  const TelemetryShape shape = telemetry_shape(scenario);
  if (!options.telemetry_path.empty() || memory) {
    channels = select_channels(telemetry_channels(shape), options.telemetry_channels);
    if (!options.telemetry_path.empty())
      telemetry = std::make_unique<TelemetryWriter>(options.telemetry_path, channel_names(channels));
    if (memory) {  // room for every row now: the loop allocates nothing
      *memory = TelemetryRows{.channels = channel_names(channels), .values = {}};
      memory->values.reserve(static_cast<std::size_t>(periods) * channels.size());
    }
  }
  const bool recording = telemetry || memory;

  RunResult result;
  const auto loop_start = std::chrono::steady_clock::now();
  if (options.record_glr_per_second)
    result.glr_max_per_s.assign(static_cast<std::size_t>(std::ceil(scenario.duration_s)), {0.0f, 0.0f, 0.0f});
  std::int64_t k = 0;
  for (; k < periods; ++k) {
    const TimeNs t_k = k * period_ns;
    const double t_s = to_seconds(t_k);
    const plant::RigidState truth = plant.state.rigid;

    const model::SensorMeasurements meas = plant::sense_plant(plant.params, plant.state, t_k);
    // The FDI's lanes of this period (before a recovery in it changes them), for telemetry only.
    const flight::fdi::WatchedSet watched = recording && !flight_params.fdir.watched.empty() && flight_state.fdir.watched >= 0
                                                ? flight::watched_set(flight_params.fdir, flight_state.fdir)
                                                : flight::fdi::WatchedSet{};
    const flight::FlightOutput out = flight::step_flight(flight_params, flight_state, meas);
    const MonitorSample sample =
        monitor_sample(t_s, plant::q_inertial_from_lvlh(plant, orbit, t_s), truth, out.reference);
    // The target's attitude and rate and the slosh at t_k, for telemetry, before the plant steps past them.
    const plant::TargetRotation target = recording ? plant::target_rotation(plant, t_s) : plant::TargetRotation{};
    std::array<plant::SloshState, plant::kMaxSloshTanks> slosh;
    if (shape.slosh_tanks > 0 && recording) slosh = plant.state.orbit.slosh;
    if (!monitor_period(scenario, sample, result.figures)) break;
    plant::step_plant(plant.params, plant.state, out.command, t_k);

    result.infeasible_allocations += !out.allocation_feasible;
    result.active_checks += out.checked_thruster != model::kNoThruster;
    if (options.record_glr_per_second) {
      std::array<float, 3>& second = result.glr_max_per_s[static_cast<std::size_t>(t_s)];
      second[0] = std::max(second[0], static_cast<float>(out.fdir.position.glr.value()));
      second[1] = std::max(second[1], static_cast<float>(out.fdir.attitude.glr.value()));
      second[2] = std::max(second[2], static_cast<float>(out.fdir.detector.glr.value()));
    }
    if (memory || (telemetry && telemetry->ok())) {
      const PeriodRecord record{
          .t_s = t_s,
          .truth = &truth,
          .plant = &plant.state,
          .flight = &out,
          .flight_state = &flight_state,
          .watched = &watched,
          .attitude_error_body_rad = attitude_error_body(out.reference.q_inertial_from_body, truth.q_inertial_from_body),
          .q_inertial_from_target = target.q_inertial_from_target,
          .omega_target_body_radps = target.omega_body_radps,
          .slosh = std::span<const plant::SloshState>(slosh.data(), static_cast<std::size_t>(shape.slosh_tanks))};
      double* const row = memory ? memory->new_row().data() : telemetry->new_row().data();
      if (every_channel) record_every_channel(record, shape, row);
      else record_period(channels, record, row);
      if (memory && telemetry && telemetry->ok()) std::copy_n(row, channels.size(), telemetry->new_row().data());
    }
  }

  const double t_end_s = to_seconds(k * period_ns);
  const flight::GuidanceRef final_ref = flight::guidance_reference(scenario.guidance, orbit, t_end_s);
  monitor_final(scenario,
                monitor_sample(t_end_s, plant::q_inertial_from_lvlh(plant, orbit, t_end_s), plant.state.rigid, final_ref),
                result.figures);

  result.fdir = fdir_result(flight_params, flight_state);
  result.propellant_used_kg = plant.state.propellant_used_kg;
  result.simulated_s = t_end_s;
  result.periods = k;
  result.wall_loop_s = seconds_since(loop_start);
  const auto files_start = std::chrono::steady_clock::now();
  result.telemetry_ok = !telemetry || telemetry->finish();  // before wall_s: the user waits for the file
  result.wall_files_s = seconds_since(files_start);
  result.wall_s = seconds_since(wall_start);
  return result;
}

}  // namespace chaser::sim
