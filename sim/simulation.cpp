#include "sim/simulation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "core/rotation.hpp"
#include "core/wall_clock.hpp"
#include "plant/arm_joints.hpp"
#include "plant/target.hpp"
#include "model/keep_out.hpp"
#include "model/run_timing.hpp"
#include "sim/initial_truth.hpp"
#include "sim/run_phases.hpp"

namespace chaser::sim {

namespace {

MonitorSample monitor_sample(double t_s, const Quat& q_inertial_from_lvlh, const plant::RigidState& x,
                             const flight::GuidanceRef& ref, const Quat& q_inertial_from_target = Quat::Identity()) {
  return MonitorSample{
      .t_s = t_s,
      .r_lvlh_m = x.r_lvlh_m,
      .v_lvlh_mps = x.v_lvlh_mps,
      .q_inertial_from_body = x.q_inertial_from_body,
      .r_ref_lvlh_m = ref.r_lvlh_m,
      .v_ref_lvlh_mps = ref.v_lvlh_mps,
      .q_ref_inertial_from_body = ref.q_inertial_from_body,
      .q_inertial_from_lvlh = q_inertial_from_lvlh,
      .q_inertial_from_target = q_inertial_from_target,
      .omega_body_radps = x.omega_body_radps,
      .omega_ref_body_radps = ref.omega_body_radps,
  };
}

SchemeResult result_of(bool enabled, const flight::SchemeSummary& s) {
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
  FdirResult r;
  r.recovery_s = e.recovery_s;
  r.recovered_thruster = e.recovered_thruster;
  const std::vector<flight::DiagnosisScheme>& schemes = flight::diagnosis_schemes();
  for (std::size_t i = 0; i < schemes.size(); ++i) r.schemes.push_back(result_of(schemes[i].enabled(p.fdir), e.schemes[i]));
  for (const SchemeResult& scheme : r.schemes) {
    if (scheme.alarm_s >= 0 && (r.detection_s < 0 || scheme.alarm_s < r.detection_s)) r.detection_s = scheme.alarm_s;
    if (scheme.isolated_s >= 0 && (r.isolation_s < 0 || scheme.isolated_s < r.isolation_s))
      r.isolation_s = scheme.isolated_s, r.isolated_thruster = scheme.isolated_thruster;
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
  r.stood_down_s = f.stood_down_s;
  return r;
}

}  // namespace

Simulation::Simulation(const model::Scenario& truth, const flight::FlightParams& flight_params,
                       const RunOptions& options)
    : wall_start_(std::chrono::steady_clock::now()),
      scenario_(truth),
      flight_params_(flight_params),
      options_(options),
      orbit_(truth.orbit),
      period_ns_(model::run_timing(truth).control_period_ns),
      periods_(model::run_timing(truth).periods),
      shape_(telemetry_shape(truth)),
      phase_params_(run_phases(truth)),
      phase_state_(init_phases(phase_params_, 0)),
      plant_(plant::make_plant(truth, initial_truth(truth, orbit_), truth.seed)),
      memory_(options.telemetry_rows),
      every_channel_(options.telemetry_channels.empty()) {  // the whole table, record_every_channel
  if (!options_.telemetry_path.empty() || memory_) {
    channels_ = select_channels(telemetry_channels(shape_), options_.telemetry_channels);
    if (!options_.telemetry_path.empty())
      telemetry_ = std::make_unique<TelemetryWriter>(options_.telemetry_path, channel_names(channels_));
    if (memory_) {  // room for every row now: the loop allocates nothing
      *memory_ = TelemetryRows{.channels = channel_names(channels_), .values = {}};
      memory_->values.reserve(static_cast<std::size_t>(periods_) * channels_.size());
    }
  }
  recording_ = telemetry_ || memory_;
  keep_out_ = checks_keep_out(scenario_);
  if (scenario_.capture) {
    joint_period_ns_ = static_cast<TimeNs>(std::llround(1e9 / scenario_.capture->joint_rate_hz));
    if (scenario_.capture->escape)
      braked_step_ns_ = static_cast<TimeNs>(std::llround(scenario_.capture->escape->braked_step_s * 1e9));
    if (flight_params_.reach) {  // the truth judges the gripper against the pose the reach aims at
      reach_goal_target_m_ = flight_params_.reach->pre_grasp_target_m;
      q_target_from_reach_goal_ = flight_params_.reach->q_target_from_tool;
    }
    result_.reach.hold_from_s = scenario_.capture->start_s + scenario_.capture->path_duration_s + kReachSettleS;
    result_.reach.hold_to_s = scenario_.capture->approach_start_s();
  }
  for (const PlannedPhase& phase : planned_phases(scenario_)) {
    phase_requirements_.push_back(phase.requirements);
    phase_configuration_.push_back(phase.configuration);
  }
  for (const ConditionalPhase& phase : conditional_phases(scenario_)) {
    phase_requirements_.push_back(phase.requirements);
    phase_configuration_.push_back(phase.configuration);
  }
  result_.phase_figures.assign(phase_params_.phases.size(), PhaseFigures{});  // before the loop: it allocates nothing
  loop_start_ = std::chrono::steady_clock::now();
  if (options_.record_glr_per_second)
    result_.glr_max_per_s.assign(static_cast<std::size_t>(std::ceil(truth.duration_s)), {});
  done_ = periods_ <= 0;
  step_phases(phase_params_, phase_state_, 0, 0, 0);
}

Simulation::Simulation(const Simulation& from, std::int64_t periods)
    : wall_start_(std::chrono::steady_clock::now()),
      scenario_(from.scenario_),
      flight_params_(from.flight_params_),
      options_([&from] {  // no telemetry
        RunOptions options;
        options.record_glr_per_second = from.options_.record_glr_per_second;
        return options;
      }()),
      orbit_(from.orbit_),
      period_ns_(from.period_ns_),
      periods_(periods),
      shape_(from.shape_),
      phase_params_(from.phase_params_),
      phase_state_(from.phase_state_),
      schedule_(from.schedule_),
      schedule_state_(from.schedule_state_),
      block_names_(from.block_names_),
      blocks_(from.blocks_),
      plant_(from.plant_),
      flight_state_(from.flight_state_),
      last_reference_(from.last_reference_),
      keep_out_(from.keep_out_),
      reach_goal_target_m_(from.reach_goal_target_m_),
      q_target_from_reach_goal_(from.q_target_from_reach_goal_),
      joint_period_ns_(from.joint_period_ns_),
      braked_step_ns_(from.braked_step_ns_),
      arm_awake_(from.arm_awake_),
      phase_requirements_(from.phase_requirements_),
      phase_configuration_(from.phase_configuration_),
      result_(from.result_),
      loop_start_(std::chrono::steady_clock::now()),
      k_(from.k_),
      done_(from.done_ || from.k_ >= periods) {
  if (from.begun_) throw std::invalid_argument("Simulation fork: in the middle of a period");
  if (periods > from.periods_)
    throw std::invalid_argument(fmt::format("Simulation fork: {} periods, past the run's {}", periods, from.periods_));
}

void Simulation::set_closed_chain_joint_rates(const std::array<double, model::kArmJoints>& rates_radps) {
  if (begun_) throw std::logic_error("set_closed_chain_joint_rates: in the middle of a period");
  plant::set_closed_chain_joint_rates(plant_, rates_radps);
}

Simulation::~Simulation() = default;

const model::SensorMeasurements& Simulation::begin_period() {
  if (begun_) return measurements_;
  begun_ = true;
  if (!arm_awake_ && phase_configuration_[static_cast<std::size_t>(phase_state_.phase)].arm_awake) {
    // A phase with the arm awake begins (the reach): the arm wakes on the multibody plant.
    if (const auto problem = plant::wake_arm(plant_, scenario_))
      throw std::runtime_error(fmt::format("capture.start_s: the arm cannot wake: {}", *problem));
    arm_awake_ = true;
  }
  truth_ = plant::chaser_state(plant_);
  measurements_ = plant::sense_plant(plant_.params, plant_.state, k_ * period_ns_,
                                     plant::q_inertial_from_lvlh(plant_, orbit_, to_seconds(k_ * period_ns_)));
  // The FDI's lanes of this period (before a recovery in it changes them), for telemetry only.
  watched_ = recording_ && !flight_params_.fdir.watched.empty() && flight_state_.fdir.watched >= 0
                 ? flight::watched_set(flight_params_.fdir, flight_state_.fdir)
                 : flight::fdi::WatchedSet{};
  return measurements_;
}

// A period's end as named stages: what the truth was at t_k (sampled before the plant steps past
// it), the mission's judgement of it, the plant propagated under the command, the run's tallies,
// and the telemetry row.
void Simulation::end_period(const flight::FlightOutput& out) {
  const TimeNs t_k = k_ * period_ns_;
  const double t_s = to_seconds(t_k);
  const PeriodTruth truth = sample_truth(out, t_s);
  begun_ = false;
  if (flight_params_.approach || flight_state_.reach.escape.started()) last_reference_ = out.reference;
  if (!judge(truth.sample)) {
    done_ = true;
    return;
  }
  add_phase_period(result_.phase_figures[static_cast<std::size_t>(phase_state_.phase)], truth.sample,
                   keep_out_ ? keep_out_clearance_m(scenario_, truth.sample) : std::numeric_limits<double>::quiet_NaN());
  propagate(out.command, t_k);
  tally(out, t_s);
  if (memory_ || (telemetry_ && telemetry_->ok())) record(out, truth, t_s);
  done_ = ++k_ >= periods_;
  if (!done_) step_phases(phase_params_, phase_state_, k_ * period_ns_, phase_flags(), 0);  // the next period's phase
}

// The target's attitude and rate and the slosh at t_k are needed for telemetry and the keep-out
// check only; the monitor's sample is the truth at t_k against the flight software's reference.
Simulation::PeriodTruth Simulation::sample_truth(const flight::FlightOutput& out, double t_s) {
  PeriodTruth truth;
  if (arm_awake_) {  // judged every period (sim/reach_result.hpp), recorded or not
    truth.arm = plant::sense_arm(plant_);
    // The gripper against the pre-grasp pose over the reach, against the fixture from the approach on.
    constexpr double kTimeTolS = 1e-9;
    const bool approaching = t_s + kTimeTolS >= result_.reach.hold_to_s;
    const Vec3& goal_m = approaching ? scenario_.target.body->grasp_point_target_m : reach_goal_target_m_;
    truth.gripper = plant::gripper_truth(plant_, goal_m, q_target_from_reach_goal_);
    // The tool point against the target's keep-out volume, in target axes (NaN without one).
    const double clearance_m =
        keep_out_ ? model::keep_out_distance_m(scenario_.target.body->keep_out,
                                               goal_m + q_target_from_reach_goal_ * truth.gripper->r_m)
                  : std::numeric_limits<double>::quiet_NaN();
    add_reach_period(result_.reach, *truth.gripper, t_s, clearance_m);
    if (recording_) truth.figure = plant::arm_figure(plant_);
    result_.reach.camera_samples = flight_state_.reach.camera_samples;
    add_rigidise_period(result_.reach.rigidise, flight_state_.reach.rigidise, truth.arm);
    if (scenario_.capture->berthing)
      add_berth_period(result_.reach.berthing, *plant::berth_truth(plant_), *scenario_.capture->berthing);
  } else if (shape_.arm && recording_) {  // stowed
    truth.arm.joints = model::kArmJoints;
    for (int j = 0; j < model::kArmJoints; ++j)
      truth.arm.q_rad[static_cast<std::size_t>(j)] = scenario_.chaser.arm->stowed_rad[static_cast<std::size_t>(j)];
  }
  const bool stabilising = arm_awake_ && flight_state_.reach.stabilise.started();
  if (recording_ || keep_out_ || stabilising) truth.target = plant::target_rotation(plant_, t_s);
  if (stabilising)
    add_stabilise_period(result_.reach.stabilise, flight_state_.reach.stabilise, truth.target.omega_body_radps,
                         truth_.mass_kg, scenario_.chaser.arm->torque_repeated_peak_Nm, t_s);
  truth.sample = monitor_sample(t_s, plant::q_inertial_from_lvlh(plant_, orbit_, t_s), truth_, out.reference,
                                truth.target.q_inertial_from_target);
  truth.sample.synchronised = phase_requirements_[static_cast<std::size_t>(phase_state_.phase)].synchronised;
  if (arm_awake_ && flight_params_.reach)
    add_grasp_period(result_.reach.grasp, flight_state_.reach.grasp, *truth.gripper, truth.sample);
  if (arm_awake_ && flight_params_.reach && flight_params_.reach->escape)
    add_escape_period(result_.escape, *flight_params_.reach->escape, flight_state_.reach.escape,
                      escape_sample(truth.sample, *truth.gripper, t_s));
  if (shape_.slosh_tanks > 0 && recording_) std::ranges::copy(plant::slosh_states(plant_), truth.slosh.begin());
  return truth;
}

// The escape's figures at t_s (sim/escape_result.hpp) from the truth: the chaser's CoM and the tool
// (the gripper's truth is taken against the reach's goal) in the target's axes.
EscapeSample Simulation::escape_sample(const MonitorSample& sample, const plant::GripperTruth& gripper, double t_s) const {
  EscapeSample out{.t_s = t_s, .distance_m = sample.r_lvlh_m.norm()};
  if (!flight_state_.reach.escape.started()) return out;
  constexpr double kTimeTolS = 1e-9;
  const bool approaching = t_s + kTimeTolS >= result_.reach.hold_to_s;
  const Vec3& goal_m = approaching ? scenario_.target.body->grasp_point_target_m : reach_goal_target_m_;
  const Vec3 tool_m = goal_m + q_target_from_reach_goal_ * gripper.r_m;
  const Quat q_target_from_tool = q_target_from_reach_goal_ * quat_from_rotation_vector(gripper.attitude_rad);
  if (keep_out_) {
    out.chaser_clearance_m = keep_out_clearance_m(scenario_, sample);
    out.tool_clearance_m = model::keep_out_distance_m(scenario_.target.body->keep_out, tool_m);
  }
  if (scenario_.sensors.arm_camera)
    out.camera_angle_rad = camera_angle_rad(tool_m, q_target_from_tool, scenario_.sensors.arm_camera->setback_m);
  return out;
}

// The conditions the run's phases change on (sim/run_phases.hpp's flags), from the flight
// software's state after the period: the capture confirmed, the brakes engaged, the escape
// triggered and its desynchronisation begun.
std::uint64_t Simulation::phase_flags() const {
  std::uint64_t flags = 0;
  if (flight_state_.reach.grasp.step == flight::GraspStep::kCaptured) flags |= std::uint64_t{1} << kCapturedFlag;
  if (flight_state_.reach.rigidise.brakes_s >= 0.0) flags |= std::uint64_t{1} << kBrakedFlag;
  if (const flight::EscapeState& escape = flight_state_.reach.escape; escape.started()) {
    flags |= std::uint64_t{1} << kEscapingFlag;
    constexpr double kTimeTolS = 1e-9;  // the plan's times in seconds against the periods' integer clock
    if (t_s() + kTimeTolS >= flight::escape_desynchronise_s(*flight_params_.reach->escape, escape))
      flags |= std::uint64_t{1} << kDesynchronisedFlag;
  }
  return flags;
}

bool Simulation::judge(const MonitorSample& sample) { return monitor_period(scenario_, sample, result_.figures); }

void Simulation::propagate(const model::ThrusterCommand& command, TimeNs t_k) {
  if (arm_awake_) {
    propagate_with_arm(command, t_k);
    return;
  }
  if (blocks_.empty()) {
    plant::step_plant(plant_.params, plant_.state, command, t_k);
    return;
  }
  // Block 0 (the flight software) ran at t_k; the others run at their activations in [t_k, t_k + T),
  // the plant carried to each.
  plant::begin_plant_period(plant_.params, plant_.state, command, t_k);
  const TimeNs t_end = t_k + period_ns_;
  TimeNs t = t_k;
  std::array<int, kMaxScheduledBlocks> due{};
  for (TimeNs next = next_event_ns(schedule_, schedule_state_); next < t_end;
       next = next_event_ns(schedule_, schedule_state_)) {
    if (next > t) plant::advance_plant(plant_.params, plant_.state, t, next), t = next;
    const int n = due_blocks(schedule_, schedule_state_, next, due);
    for (int i = 0; i < n; ++i)
      if (due[static_cast<std::size_t>(i)] > 0) blocks_[static_cast<std::size_t>(due[static_cast<std::size_t>(i)] - 1)](next, plant_);
  }
  plant::advance_plant(plant_.params, plant_.state, t, t_end);
}

// The reach's joint loop inside the period: at each joint step the arm's sensors are read, the
// flight software's combined law commands the joints (flight::step_reach) and the plant is carried
// to the next step. The blocks added by add_block do not run while the arm is awake. The escape's
// stowed arm braked for a control period or more, no joint law runs and the chaser moves as one
// body, the target free: the loop and MuJoCo step at capture.escape.braked_step_s. The brakes'
// catch of the joints' last motion is over by then (their constraint's time constant is 2 ms) and
// was flown at the joint step. Not the stabilisation's braked composite: its brakes' loads under
// the thrusters grow with the step (model/capture.hpp).
void Simulation::propagate_with_arm(const model::ThrusterCommand& command, TimeNs t_k) {
  plant::begin_plant_period(plant_.params, plant_.state, command, t_k);
  const TimeNs t_end = t_k + period_ns_;
  const double braked_s = flight_state_.reach.escape.brakes_s;
  constexpr double kTimeTolS = 1e-9;  // the joint steps' times are sums of the period
  const bool braked = braked_s >= 0.0 && to_seconds(t_k) + kTimeTolS >= braked_s + to_seconds(period_ns_);
  TimeNs step_ns = joint_period_ns_;
  if (braked && braked_step_ns_ > joint_period_ns_) {
    step_ns = braked_step_ns_;
    plant::set_braked_step(plant_, to_seconds(step_ns));
  }
  for (TimeNs t = t_k; t < t_end; t += step_ns) {
    if (flight_params_.reach) {
      const model::ArmCommand command_now =
          flight::step_reach(*flight_params_.reach, flight_state_.reach, plant::sense_arm(plant_), to_seconds(t));
      auto& peak = flight_state_.reach.rigidise.started() ? result_.reach.rigidise.peak_torque_Nm
                                                         : result_.reach.peak_joint_torque_Nm;
      for (std::size_t j = 0; j < peak.size(); ++j) peak[j] = std::max(peak[j], std::abs(command_now.torque_Nm[j]));
      plant::command_arm(plant_, command_now);
    }
    plant::advance_plant(plant_.params, plant_.state, t, std::min(t + step_ns, t_end));
    if (flight_state_.reach.rigidise.brakes_s >= 0.0) {  // braked: the joints' loads, every joint step
      const auto load = plant::brake_loads_Nm(plant_);
      auto& peak = result_.reach.rigidise.peak_brake_load_Nm;
      for (std::size_t j = 0; j < peak.size(); ++j) peak[j] = std::max(peak[j], std::abs(load[j]));
    } else if (flight_state_.reach.escape.braked()) {  // the escape's stowed arm braked: its peak
      double& peak = result_.escape.peak_brake_load_Nm;
      if (std::isnan(peak)) peak = 0.0;
      for (const double load : plant::brake_loads_Nm(plant_)) peak = std::max(peak, std::abs(load));
    }
  }
}

void Simulation::add_block(const std::string& name, const Rate& rate, Block block) {
  if (k_ > 0 || begun_) throw std::invalid_argument("add_block: before the first period");
  if (schedule_.count >= kMaxScheduledBlocks)
    throw std::invalid_argument(fmt::format("add_block: at most {} blocks", kMaxScheduledBlocks - 1));
  const std::vector<std::string> problems = validate(rate);
  if (!problems.empty()) throw std::invalid_argument(fmt::format("add_block {}: rate.{}", name, problems.front()));
  if (schedule_.count == 0) {  // the flight software's period, first at every time it shares
    schedule_.rates[0] = rate_of_period(period_ns_);
    schedule_.names[0] = "flight_software";
    schedule_.count = 1;
  }
  block_names_.push_back(name);
  blocks_.push_back(std::move(block));
  schedule_.rates[static_cast<std::size_t>(schedule_.count)] = rate;
  ++schedule_.count;
  schedule_state_ = start_schedule(schedule_);
}

void Simulation::tally(const flight::FlightOutput& out, double t_s) {
  result_.infeasible_allocations += !out.allocation_feasible;
  result_.active_checks += out.checked_thruster != model::kNoThruster;
  const double largest =  // Eigen's packet reduction: a fraction of a scalar loop's cost over 16-24 thrusters
      Eigen::Map<const Eigen::ArrayXd>(out.command.ton.data(), shape_.thrusters).maxCoeff();
  result_.max_on_fraction = std::max(result_.max_on_fraction, largest);
  result_.saturated_periods += largest >= 1.0;
  if (options_.record_glr_per_second) {
    auto& second = result_.glr_max_per_s[static_cast<std::size_t>(t_s)];
    for (std::size_t i = 0; i < second.size(); ++i)  // every slot: an unused one's statistic is 0
      second[i] = std::max(second[i], static_cast<float>(out.fdir.schemes[i].glr.value()));
  }
}

void Simulation::record(const flight::FlightOutput& out, const PeriodTruth& truth, double t_s) {
  const PeriodRecord record{
      .t_s = t_s,
      .truth = &truth_,
      .plant = &plant_.state,
      .flight = &out,
      .flight_state = &flight_state_,
      .watched = &watched_,
      .attitude_error_body_rad = attitude_error_body(out.reference.q_inertial_from_body, truth_.q_inertial_from_body),
      .q_inertial_from_target = truth.target.q_inertial_from_target,
      .omega_target_body_radps = truth.target.omega_body_radps,
      .slosh = std::span<const model::SloshState>(truth.slosh.data(), static_cast<std::size_t>(shape_.slosh_tanks)),
      .phase = phase_state_.phase,
      .arm = shape_.arm ? &truth.arm : nullptr,
      .gripper = truth.gripper ? &*truth.gripper : nullptr,
      .figure = truth.figure ? &*truth.figure : nullptr};
  double* const row = memory_ ? memory_->new_row().data() : telemetry_->new_row().data();
  if (every_channel_) record_every_channel(record, shape_, row);
  else record_period(channels_, record, row);
  if (memory_ && telemetry_ && telemetry_->ok()) std::copy_n(row, channels_.size(), telemetry_->new_row().data());
}

// What the end is judged against: the line's capture point, or the synchronised reference from the
// truth (with the approach steps, from the start point the flight software fixed, once the rotation
// is synchronised; before that the flight software's own last reference: the run ended early).
flight::GuidanceRef Simulation::final_reference(double t_end_s) const {
  if (!scenario_.guidance.synchronised) return flight::guidance_reference(scenario_.guidance, orbit_, t_end_s);
  if (flight_state_.reach.escape.started()) return last_reference_;  // the escape's plan
  const plant::TargetRotation target = plant::target_rotation(plant_, t_end_s);
  if (!flight_params_.approach) return true_sync_reference(scenario_, orbit_, target, t_end_s);
  const auto& start = flight_state_.sync_latch.start_target_m;
  if (start && flight::sync_step(*flight_params_.approach, t_end_s) == flight::SyncStep::kTransfer)
    return true_sync_reference(scenario_, orbit_, target, t_end_s, start);
  return last_reference_;
}

RunResult Simulation::finish() {
  const double t_end_s = t_s();
  monitor_final(scenario_,
                monitor_sample(t_end_s, plant::q_inertial_from_lvlh(plant_, orbit_, t_end_s), plant::chaser_state(plant_),
                               final_reference(t_end_s)),
                result_.figures);
  if (result_.escape.flown) result_.figures.capture_achieved = false;  // the final errors are the escape's
  RunResult result = std::move(result_);
  result.fdir = fdir_result(flight_params_, flight_state_);
  if (const auto& supervisor = flight_params_.supervisor) {
    const flight::fdi::SupervisorState& st = flight_state_.supervisor;
    const flight::fdi::SupervisorMode& last = supervisor->modes[static_cast<std::size_t>(st.mode)];
    result.supervisor = {.enabled = true, .switches = st.switches, .thruster = last.thruster, .fault = last.fault,
                         .log = {st.log.begin(), st.log.begin() + std::min(st.switches, flight::fdi::kMaxSupervisorSwitches)}};
  }
  finish_phases(phase_params_, phase_state_, k_ * period_ns_);
  result.phases = flown_phases(phase_params_, phase_state_);
  result.propellant_used_kg = plant_.state.propellant_used_kg;
  result.simulated_s = t_end_s;
  result.periods = k_;
  result.wall_loop_s = seconds_since(loop_start_);
  const auto files_start = std::chrono::steady_clock::now();
  result.telemetry_ok = !telemetry_ || telemetry_->finish();  // before wall_s: the user waits for the file
  result.wall_files_s = seconds_since(files_start);
  result.wall_s = seconds_since(wall_start_);
  return result;
}

}  // namespace chaser::sim
