#include "flight/fdir.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <future>

#include "core/rotation.hpp"
#include "flight/fdi/design/design_inputs.hpp"
#include "flight/fdi/design/residual_design.hpp"
#include "flight/fdi/design/uio_bank.hpp"
#include "flight/fdi/residual_generator.hpp"
#include "flight/guidance.hpp"
#include "model/recovery.hpp"
#include "model/thruster_geometry.hpp"

namespace chaser::flight {

namespace {

// M of a set the Fonod 2015 schemes watch (validate_scenario: kSchemeThrusters of them).
fdi::SchemeConfig scheme_config(const model::Scenario& s, model::ThrusterMask mask) {
  return model::configuration_matrix(s.thrusters, mask, s.chaser.com_body_m).leftCols<fdi::kSchemeThrusters>();
}

// The fault directions of a scheme in its model's input space (3 x lanes: M_F in LVLH or M_C).
fdi::Mat3W thruster_inputs(const model::Scenario& s, FdiModel model, const fdi::SchemeConfig& config) {
  if (model == FdiModel::kAttitude) return config.bottomRows<3>();
  // The position model's input is the force in LVLH (eq. 20): the fault directions are those of
  // the attitude the chaser flies, target pointing, not of body axes aligned with LVLH.
  const Mat3 R_lvlh_from_body = target_pointing_q_lvlh_from_body(s.guidance.approach_axis_lvlh).toRotationMatrix();
  return R_lvlh_from_body * config.topRows<3>();
}

fdi::FdiSchemeParams scheme_params(const model::Scenario& s, const model::FdiSchemeParams& scheme,
                                   const fdi::ResidualDesign& design) {
  fdi::FdiSchemeParams p;
  p.residual = fdi::make_residual_generator(design);
  p.glr.window = s.fdi.glr_window;
  p.glr.threshold = s.fdi.glr_threshold;
  p.glr.sigma0 = scheme.sigma0;
  p.glr.residual_dim = scheme.residual_dimension;
  p.glr.sides = s.fdi.glr_increase_only ? fdi::GlrSides::kIncreaseOnly : fdi::GlrSides::kTwoSided;
  if (scheme.residual_dimension > 1) {  // eq. 41 generalised: whitened by the fault-free covariance
    p.glr.variant = fdi::GlrVariant::kWhitened;
    p.glr.covariance0 = scheme.sigma0 * scheme.sigma0 * Mat3::Identity();
  }
  p.isolation.window = s.fdi.isolation_window;
  p.isolation.confirmation = s.fdi.confirmation_window;
  p.isolation.settle = s.fdi.isolation_settle;
  p.isolate = s.fdi.isolation_method != model::IsolationMethod::kDeficit;
  p.period_s = s.control_period_s;
  return p;
}

// The scheme of the starting set, re-pointed at another set's thrusters (signature isolation).
fdi::FdiSchemeParams for_set(const model::Scenario& s, fdi::FdiSchemeParams p, const fdi::Mat3W& inputs) {
  if (s.fdi.isolation_method == model::IsolationMethod::kSignature) {
    p.isolation.criterion = fdi::IsolationCriterion::kSignature;
    p.isolation.signature = fdi::make_signature_filter(p.residual, inputs);
  }
  return p;
}

int whole_periods(double seconds, double period_s) { return static_cast<int>(std::lround(seconds / period_s)); }

// The bank's lanes: every thruster of the set, however many (1..kMaxThrusters).
fdi::DeficitIsolationParams deficit_params(const model::Scenario& s, model::ThrusterMask mask) {
  const double T = s.control_period_s;
  fdi::DeficitIsolationParams p;
  p.inertia_kgm2 = s.chaser.inertia_kgm2;
  p.mass_kg = s.chaser.mass_kg;
  fdi::set_deficit_columns(p, model::configuration_columns(s.thrusters, mask, s.chaser.com_body_m));
  p.period_s = T;
  p.before = whole_periods(s.fdi.deficit.window_before_s, T);
  p.after = whole_periods(s.fdi.deficit.window_after_s, T);
  p.max_window = whole_periods(s.fdi.deficit.window_max_s, T);
  // The sensor specifications set the weights; a noiseless sensor gets a small floor so that the
  // weights stay finite.
  p.lidar_sigma_m = std::max(s.sensors.lidar.noise_sigma_m, 1e-6);
  p.gyro_sigma_radps = std::max(s.sensors.gyro.noise_sigma_radps, 1e-9);
  p.pulse_uncertainty = s.fdi.deficit.pulse_uncertainty;
  // The rows' model errors the specifications bound (deficit_isolation.hpp, "Weights").
  p.spill_fraction = s.thrusters.delay_max_s / T;
  p.inertia_uncertainty = s.fdi.deficit.inertia_uncertainty;
  p.com_uncertainty_m = s.fdi.deficit.com_uncertainty_m;
  p.min_gain = s.fdi.deficit.min_gain;
  p.min_margin = s.fdi.deficit.min_margin;
  p.min_a = s.fdi.deficit.detection_min_constant;
  p.min_b = s.fdi.deficit.detection_min_proportional;
  return p;
}

// The active sets the FDI may watch: every set the vehicle may fly (model::reachable_configurations),
// of the Fonod 2015 schemes' size when one of them is on (the deficit bank and detector watch any).
std::vector<model::ThrusterMask> watchable_sets(const model::Scenario& s) {
  const bool schemes = s.fdi.position.enabled || s.fdi.attitude.enabled;
  std::vector<model::ThrusterMask> sets;
  for (const model::ReachableConfiguration& r : model::reachable_configurations(s.thrusters, s.fdi.recovery)) {
    const int count = model::thruster_count(r.configuration.active);
    if (schemes ? count == fdi::kSchemeThrusters : count >= 1) sets.push_back(r.configuration.active);
  }
  return sets;
}

// The on-time a confirmed thruster keeps giving uncommanded, from the deficit bank's decision for the
// confirming scheme's slot where it named that lane: a stuck-open valve 1, a leak its size (the
// realised on-time's floor, model/faults.hpp); 0 otherwise.
double uncommanded_on_fraction(const FdirState& state, int slot, int lane) {
  const DiagnosisScheme& scheme = diagnosis_schemes()[static_cast<std::size_t>(slot)];
  const fdi::DeficitDecision* d = scheme.deficit ? scheme.deficit(state) : nullptr;
  if (d == nullptr || !d->decided || d->thruster != lane) return 0.0;
  if (d->kind == model::FaultKind::kStuckOpen) return 1.0;
  if (d->kind == model::FaultKind::kLeak) return std::clamp(d->size, 0.0, 1.0);
  return 0.0;
}

// A scheme's isolation by the deficit bank: once the scheme has alarmed, the bank's decision (made
// a few seconds later) becomes the scheme's confirmed thruster.
void deficit_confirmation(const FdiWatchedParams& w, FdirState& state, fdi::DeficitDecisionState& decision,
                          fdi::FdiSchemeState& scheme, fdi::FdiSchemeOutput& out) {
  const std::int64_t alarm_sample = scheme.alarm ? scheme.alarm_period - state.bank_first_period : -1;
  const fdi::DeficitDecision& d = fdi::step_deficit_decision(w.deficit, state.deficit_bank, decision, alarm_sample);
  if (d.decided && d.thruster >= 0 && scheme.confirmed < 0) scheme.confirmed = d.thruster;
  out.confirmed = scheme.confirmed;
}

// While disarmed (settling after a recovery) a scheme's latches are cleared every period: its
// residual generator and GLR keep running, its decisions do not count.
void clear_latches(fdi::FdiSchemeState& scheme, fdi::FdiSchemeOutput& out) {
  scheme.alarm = false;
  scheme.alarm_period = -1;
  scheme.confirmed = -1;
  scheme.isolation = fdi::IsolationState{};
  out.alarm = false;
  out.candidate = out.confirmed = -1;
  out.alarm_time_s = -1.0;
}

void step_deficit_bank(const FdiWatchedParams& w, FdirState& state, const model::SensorMeasurements& meas,
                       const FdirInput& in, const Quat& q_lvlh_from_body) {
  fdi::DeficitSample& sample = fdi::next_deficit_sample(state.deficit_bank);
  sample.omega_body_radps = meas.omega_body_radps;
  sample.r_lvlh_m = meas.r_lvlh_m;
  sample.q_lvlh_from_body = q_lvlh_from_body;
  // The set's lanes only: the rest of the slot is zero since the watch started (start_watch clears
  // the bank); all kMaxWatchedThrusters lanes would write four cache lines a period where MSR needs one.
  if (w.set.count == fdi::kSchemeThrusters)
    sample.ton.head<fdi::kSchemeThrusters>() = in.ton.head<fdi::kSchemeThrusters>();
  else
    sample.ton.head(w.set.count) = in.ton.head(w.set.count);
  sample.mass_kg = w.deficit.mass_kg - meas.propellant_used_kg;
  sample.arm_momentum_Nms = in.arm_momentum_Nms;
  sample.com_shift_m = in.com_shift_m;
  fdi::push_deficit_sample(w.deficit, state.deficit_bank);
}

void step_detector(const FdirParams& p, const FdiWatchedParams& w, FdirState& state, const FdirInput& in,
                   FdirOutput& out) {
  if (p.impulse_detection) {
    // The impulse statistic's verdict, where the rest of the FDIR reads the detector's. Its
    // material_statistic stays 0: the active checks' recheck of a suspect (thruster_to_check_again) reads
    // the gain statistic's material fits, which this statistic has not.
    fdi::step_impulse_detector(p.impulse, w.deficit, state.deficit_bank, state.impulse);
    state.detector.statistic = state.impulse.statistic;
    state.detector.suspect = state.impulse.suspect;
    state.detector.alarm = state.impulse.alarm;
    state.detector.alarm_sample = state.impulse.alarm_sample;
  } else {
    fdi::step_deficit_detector(p.detector, w.deficit, state.deficit_bank, state.detector);
  }
  const fdi::DeficitDecision& d = fdi::step_deficit_decision(w.deficit, state.deficit_bank, state.detector_deficit,
                                                             state.detector.alarm ? state.detector.alarm_sample : -1);
  fdi::FdiSchemeOutput& detector = out.schemes[kDeficitScheme];
  detector.glr = fdi::GlrStatistic::of_value(state.detector.statistic);
  detector.alarm = state.detector.alarm;
  detector.candidate = state.detector.suspect;
  detector.confirmed = d.thruster;
  detector.alarm_time_s =
      state.detector.alarm ? static_cast<double>(state.detector.alarm_sample + state.bank_first_period) * p.period_s
                           : -1.0;
  if (d.thruster >= 0 && state.detector_isolated_s < 0) state.detector_isolated_s = in.t_s;
}

// Whether the watch has concluded anything: an alarm of a scheme or the detector, or a confirmation.
bool watch_concluded(const FdirState& state) {
  return state.position.alarm || state.attitude.alarm || state.detector.alarm ||
         state.confirmed_thruster != model::kNoThruster;
}

// The watch starts (again) at control period `period`: fresh decisions, bank and detector.
void start_watch(FdirState& state, std::int64_t period, double t_s) {
  state.armed = true;
  state.lidar_gap = false;
  state.armed_s = t_s;
  state.bank_first_period = period;
  state.event = {};
  state.deficit_bank = {};
  state.detector = {};
  state.impulse = {};
  state.position_deficit = state.attitude_deficit = state.detector_deficit = {};
  state.position_isolated_s = state.attitude_isolated_s = state.detector_isolated_s = -1;
  state.latches = {};
  fdi::restart_observer_bank(state.bank);
  state.bank_deficit = {};
  state.rate_check = {};
  state.rate_check_decision = {};
  state.confirmed_thruster = model::kNoThruster;
  state.confirmed_s = -1;
  fdi::FdiSchemeOutput ignored;
  clear_latches(state.position, ignored);
  clear_latches(state.attitude, ignored);
}

// The registered schemes (flight/diagnosis_schemes.hpp), after the three built in: each period's
// output, cleared while disarmed as theirs are, and its first alarm and confirmation latched.
void step_registered_schemes(const FdirParams& p, FdirState& state, const model::SensorMeasurements& meas,
                             const FdirInput& in, FdirOutput& out) {
  const std::vector<DiagnosisScheme>& schemes = diagnosis_schemes();
  for (std::size_t i = kDeficitScheme + 1; i < schemes.size(); ++i) {
    if (!schemes[i].enabled(p)) continue;
    fdi::FdiSchemeOutput& o = out.schemes[i];
    schemes[i].step(p, state, meas, in, o);
    if (!state.armed) {
      o.alarm = false;
      o.candidate = o.confirmed = -1;
      o.alarm_time_s = -1.0;
      continue;
    }
    SchemeLatch& l = state.latches[i];
    if (o.alarm && l.alarm_s < 0) l.alarm_s = in.t_s;
    if (o.confirmed >= 0 && l.confirmed < 0) l.confirmed = o.confirmed, l.isolated_s = in.t_s;
  }
}

SchemeSummary summary_of(const FdiWatchedParams& w, bool alarm, double alarm_s, int confirmed_lane, double isolated_s,
                         const fdi::DeficitDecision& diagnosis, std::int64_t bank_first_period, double period_s) {
  SchemeSummary r;
  r.alarm = alarm;
  r.alarm_s = alarm ? alarm_s : -1.0;
  r.confirmed = confirmed_lane >= 0 ? w.set.index[static_cast<std::size_t>(confirmed_lane)] : model::kNoThruster;
  r.isolated_s = isolated_s;
  r.diagnosis = diagnosis;
  if (diagnosis.decided && diagnosis.thruster >= 0)
    r.estimated_onset_s = static_cast<double>(diagnosis.onset_sample + bank_first_period) * period_s;
  return r;
}

}  // namespace

fdi::DesignInputs scheme_design_inputs(const model::Scenario& s, FdiModel model) {
  const fdi::SchemeConfig config = scheme_config(s, model::initial_active_set(s.thrusters));
  fdi::DesignInputs inputs =
      model == FdiModel::kPosition ? fdi::position_design_inputs(s, config) : fdi::attitude_design_inputs(s, config);
  if (model == FdiModel::kPosition) {
    inputs.fault_inputs = thruster_inputs(s, model, config);
    inputs.E_f = inputs.B * inputs.fault_inputs;
  }
  const model::FdiSchemeParams& scheme = model == FdiModel::kPosition ? s.fdi.position : s.fdi.attitude;
  inputs.eigenvalues.assign(s.fdi.eigenvalues.begin(), s.fdi.eigenvalues.end());
  inputs.taylor_order = s.fdi.taylor_order;
  inputs.delta_max_s = s.fdi.design_delay_max_s;
  inputs.residual_dim = scheme.residual_dimension;
  return inputs;
}

FdirParams make_fdir_params(const model::Scenario& s) {
  FdirParams p;
  p.period_s = s.control_period_s;
  p.recovery = s.fdi.recovery;
  p.rearm_after_recovery_s = s.fdi.rearm_after_recovery_s;
  p.position_enabled = s.fdi.position.enabled;
  p.attitude_enabled = s.fdi.attitude.enabled;
  p.deficit_isolation = s.fdi.isolation_method == model::IsolationMethod::kDeficit;
  p.deficit_detection = p.deficit_isolation && s.fdi.deficit.detection;
  p.schemes = static_cast<int>(diagnosis_schemes().size());
  p.bank_enabled = s.fdi.observer_bank.enabled;
  if (p.bank_enabled) {
    // The bank models the starting active set, its columns in thruster order (configuration_columns').
    const fdi::WatchedSet lanes = fdi::watched_set(model::initial_active_set(s.thrusters));
    const std::vector<int> column_thruster(lanes.index.begin(), lanes.index.begin() + lanes.count);
    const model::ObserverBankParams& b = s.fdi.observer_bank;
    const double T = s.control_period_s;
    p.bank = fdi::make_observer_bank(fdi::design_uio_bank(s, /*figures=*/false), column_thruster, s.chaser.inertia_kgm2,
                                     {.block = model::impulse_block_periods(T),
                                      .window_blocks = model::impulse_blocks(b.window_s, T),
                                      .baseline_blocks = model::impulse_blocks(b.baseline_s, T),
                                      .threshold_Nm = b.threshold_Nm,
                                      .isolation_ratio = b.isolation_ratio,
                                      .period_s = T,
                                      .com_uncertainty_m = s.fdi.deficit.com_uncertainty_m,
                                      .inertia_uncertainty = s.fdi.deficit.inertia_uncertainty});
  }
  p.rate_check_enabled = s.fdi.rate_check.enabled;
  if (p.rate_check_enabled)
    p.rate_check = fdi::make_rate_check_params(s.fdi.rate_check, s.thrusters, s.chaser.com_body_m, s.chaser.inertia_kgm2,
                                               s.control_period_s, s.fdi.deficit.inertia_uncertainty);
  if (!p.position_enabled && !p.attitude_enabled && !p.deficit_detection && !p.bank_enabled && !p.rate_check_enabled)
    return p;
  // Designed once, for the starting set. The two designs are independent pure functions of the
  // scenario: the attitude one runs on a second thread while this one designs the position scheme
  // (the same results; the run waits for max(position, attitude) instead of their sum).
  const auto design = [&s](FdiModel model, const model::FdiSchemeParams& scheme) {
    fdi::DesignInputs inputs = scheme_design_inputs(s, model);
    inputs.compute_figures = false;  // for reports only (chaser fdi design)
    return scheme_params(s, scheme, fdi::design_residual_generator(inputs));
  };
  std::future<fdi::FdiSchemeParams> attitude_design;
  if (p.attitude_enabled)
    attitude_design = std::async(std::launch::async, design, FdiModel::kAttitude, std::cref(s.fdi.attitude));
  fdi::FdiSchemeParams position, attitude;
  if (p.position_enabled) position = design(FdiModel::kPosition, s.fdi.position);
  if (p.attitude_enabled) attitude = attitude_design.get();  // rethrows the design's exception, if any
  for (const model::ThrusterMask mask : watchable_sets(s)) {
    FdiWatchedParams& w = p.watched.emplace_back();
    w.set = fdi::watched_set(mask);
    if (p.position_enabled || p.attitude_enabled) {
      const fdi::SchemeConfig config = scheme_config(s, mask);
      if (p.position_enabled) w.position = for_set(s, position, thruster_inputs(s, FdiModel::kPosition, config));
      if (p.attitude_enabled) w.attitude = for_set(s, attitude, thruster_inputs(s, FdiModel::kAttitude, config));
    }
    w.mass_flow_kgps = fdi::nominal_mass_flow_kgps(s.thrusters, w.set, s.chaser.isp_s);
    if (p.deficit_isolation) w.deficit = deficit_params(s, mask);
  }
  p.event.sensor_sigma_kg = s.sensors.propellant.noise_sigma_kg;
  p.event.absolute_margin_kg = s.fdi.over_consumption_threshold_kg;
  const int detection_window = whole_periods(s.fdi.deficit.detection_window_s, s.control_period_s);
  p.detector = fdi::DeficitDetectorParams{
      .window = detection_window,
      .threshold = s.fdi.deficit.detection_threshold,
      .min_a = s.fdi.deficit.detection_min_constant,
      .min_b = s.fdi.deficit.detection_min_proportional,
      // The gains every second period (half the cost, the alarm at most one period later) when the
      // window is a whole number of such blocks, else every period.
      .evaluate_every = detection_window % 2 == 0 ? 2 : 1,
  };
  p.impulse_detection = s.fdi.deficit.detection_statistic == model::DetectionStatistic::kImpulse;
  p.impulse = fdi::ImpulseDetectorParams{
      .block = model::impulse_block_periods(s.control_period_s),
      .window_blocks = model::impulse_blocks(s.fdi.deficit.impulse_window_s, s.control_period_s),
      .baseline_blocks = model::impulse_blocks(s.fdi.deficit.impulse_baseline_s, s.control_period_s),
      .threshold_Nms = s.fdi.deficit.impulse_threshold_Nms,
  };
  return p;
}

const fdi::WatchedSet& watched_set(const FdirParams& params, const FdirState& state) {
  return params.watched[static_cast<std::size_t>(state.watched)].set;
}

bool fdi_listening(const FdirState& state) { return state.armed && state.confirmed_thruster == model::kNoThruster; }

int thruster_to_check_again(const FdirParams& params, const FdirState& state, double deficit_min_gain) {
  if (!state.armed) return model::kNoThruster;
  if (params.rate_check_enabled && state.rate_check.recheck != model::kNoThruster)
    return fdi::next_recheck(state.rate_check);  // none while the checks keep their spacing
  // deficit_min_gain > 0 (validated), so a material fit leads and `suspect` is its lane. Strictly
  // above, as the alarm is: with it the threshold, the detector alarms first and nothing is suspected.
  const fdi::DeficitDetectorState& d = state.detector;
  if (!params.deficit_detection || d.alarm || !(d.material_statistic > deficit_min_gain)) return model::kNoThruster;
  return watched_set(params, state).index[static_cast<std::size_t>(d.suspect)];
}

fdi::WatchedTon watched_on_times(const FdirParams& params, const FdirState& state, const model::ThrusterOnTimes& ton) {
  fdi::WatchedTon lanes = fdi::WatchedTon::Zero();
  if (params.watched.empty() || state.watched < 0) return lanes;
  const fdi::WatchedSet& w = watched_set(params, state);
  for (int lane = 0; lane < w.count; ++lane) lanes[lane] = ton[static_cast<std::size_t>(w.index[static_cast<std::size_t>(lane)])];
  return lanes;
}

void add_uncommanded_on_time(const FdirParams& params, const FdirState& state, int thruster, double on_fraction,
                             fdi::WatchedTon& lanes) {
  if (thruster == model::kNoThruster || params.watched.empty() || state.watched < 0) return;
  const fdi::WatchedSet& w = watched_set(params, state);
  for (int lane = 0; lane < w.count; ++lane)
    if (w.index[static_cast<std::size_t>(lane)] == thruster) lanes[lane] = on_fraction;
}

void step_fdir(const FdirParams& p, FdirState& state, const model::SensorMeasurements& meas, const FdirInput& in,
               FdirOutput& out) {
  if (p.watched.empty() || state.watched < 0) return;  // no FDI, or no parameters for this set
  const FdiWatchedParams& w = p.watched[static_cast<std::size_t>(state.watched)];
  if (!state.armed && in.t_s >= state.rearm_s) start_watch(state, in.period, in.t_s);
  // A LIDAR gap (the target outside its view): no position row this period. The position scheme
  // pauses (pause_fdi_scheme) and the deficit bank, whose windows need every period's row, stops. At
  // the gap's end a watch that had concluded nothing starts afresh; one that had keeps what it
  // concluded, its bank stopped, until a recovery starts the next watch. Nothing is erased.
  const bool lidar_gap = !meas.lidar_valid;
  if (lidar_gap) {
    state.lidar_gap = true;
  } else if (state.lidar_gap && state.armed && !watch_concluded(state)) {
    start_watch(state, in.period, in.t_s);
  }
  const bool bank_runs = !state.lidar_gap;
  const Vec6& wrench = in.commanded_wrench;
  const Quat q_lvlh_from_body = in.q_inertial_from_lvlh.conjugate() * in.q_est_inertial_from_body;

  if (state.armed) {
    // Remark 2: over-consumption separates cases 1/3 from 2/4; it runs once either scheme alarms.
    const bool alarm_before = state.position.alarm || state.attitude.alarm;
    // The expected increment is read only while the resolution is active (step_event_resolution).
    const double expected_kg =
        state.event.active ? fdi::expected_propellant_increment_kg(in.ton, w.mass_flow_kgps, p.period_s) : 0.0;
    out.over_consumption =
        fdi::step_event_resolution(p.event, state.event, meas.propellant_used_kg, expected_kg, alarm_before);
    if (p.deficit_isolation && bank_runs) step_deficit_bank(w, state, meas, in, q_lvlh_from_body);
    if (p.deficit_detection && bank_runs) step_detector(p, w, state, in, out);
  }

  fdi::FdiSchemeOutput& position = out.schemes[kPositionScheme];
  fdi::FdiSchemeOutput& attitude = out.schemes[kAttitudeScheme];
  if (p.position_enabled && lidar_gap) {
    fdi::pause_fdi_scheme(w.position, state.position, position);
    if (!state.armed) clear_latches(state.position, position);
  } else if (p.position_enabled) {
    // Eq. 20: u_c = R(Q_tgt, Q_chs) M_F T_on, the commanded force rotated into LVLH with the
    // estimated attitude; y is the LIDAR position.
    const Vec3 u_c = q_lvlh_from_body * Vec3(wrench.head<3>());
    fdi::step_fdi_scheme(w.position, state.position, meas.r_lvlh_m, u_c, in.ton.head<fdi::kSchemeThrusters>(),
                         out.over_consumption, position);
    if (!state.armed) clear_latches(state.position, position);
    if (state.armed && p.deficit_isolation && bank_runs)
      deficit_confirmation(w, state, state.position_deficit, state.position, position);
    if (position.confirmed >= 0 && state.position_isolated_s < 0) state.position_isolated_s = in.t_s;
  }
  if (p.attitude_enabled) {
    // Eq. 16-17: u_c = M_C T_on; y is the measured attitude about the target-pointing reference,
    // the small angles of the linearised model (eq. 15): 2 vec(q), equal to them to first order.
    const Vec3 angles = small_angle_error_body(in.q_ref_inertial_from_body, meas.q_inertial_from_body);
    fdi::step_fdi_scheme(w.attitude, state.attitude, angles, Vec3(wrench.tail<3>()),
                         in.ton.head<fdi::kSchemeThrusters>(), out.over_consumption, attitude);
    if (!state.armed) clear_latches(state.attitude, attitude);
    if (state.armed && p.deficit_isolation && bank_runs)
      deficit_confirmation(w, state, state.attitude_deficit, state.attitude, attitude);
    if (attitude.confirmed >= 0 && state.attitude_isolated_s < 0) state.attitude_isolated_s = in.t_s;
  }
  if (p.schemes > kDeficitScheme + 1) step_registered_schemes(p, state, meas, in, out);
  if (!state.armed) return;

  // The fault-free noise estimate of the deficit bank must not learn from the fault.
  if (state.position.alarm || state.attitude.alarm || state.detector.alarm || state.bank.alarm)
    state.deficit_bank.frozen = true;

  // The first confirmation by any scheme, in slot order, is the watch's confirmed thruster.
  if (state.confirmed_thruster == model::kNoThruster) {
    int slot = 0;
    while (slot < p.schemes && out.schemes[static_cast<std::size_t>(slot)].confirmed < 0) ++slot;
    if (slot < p.schemes) {
      const int lane = out.schemes[static_cast<std::size_t>(slot)].confirmed;
      state.confirmed_thruster = w.set.index[static_cast<std::size_t>(lane)];
      state.confirmed_s = in.t_s;
      out.confirmed_now = state.confirmed_thruster;
      out.confirmed_uncommanded_on_fraction = uncommanded_on_fraction(state, slot, lane);
    }
  }
}

void step_bank_scheme(const FdirParams& p, FdirState& state, const model::SensorMeasurements& meas,
                      const FdirInput& in, fdi::FdiSchemeOutput& out) {
  if (state.bank.z.empty()) state.bank = fdi::make_observer_bank_state(p.bank);  // the first period
  const FdiWatchedParams& w = p.watched[static_cast<std::size_t>(state.watched)];
  fdi::ObserverBankState& b = state.bank;
  fdi::step_observer_bank(p.bank, b, meas.omega_body_radps, w.set, in.ton, in.commanded_wrench);
  const auto lane_of = [&](int thruster) { return w.set.lane[static_cast<std::size_t>(thruster)]; };
  const bool deciding = b.filled == p.bank.window_blocks + p.bank.baseline_blocks;
  out.residual = Vec3(b.nominal_change_radps, deciding ? b.smallest_change_radps : 0.0, 0.0);  // [rad/s]
  out.glr = fdi::GlrStatistic::of_value(b.statistic_Nm);
  out.alarm = b.alarm;
  out.alarm_time_s = b.alarm ? static_cast<double>(b.alarm_period + state.bank_first_period) * p.period_s : -1.0;
  out.candidate = b.candidate >= 0 ? lane_of(b.candidate) : -1;
  out.confirmed = b.confirmed >= 0 ? lane_of(b.confirmed) : -1;
  // More than one hypothesis: the deficit bank's forces may name one of them (its decision latches).
  if (out.confirmed < 0 && b.alarm && p.deficit_isolation && !state.lidar_gap && state.armed) {
    const fdi::DeficitDecision& d =
        fdi::step_deficit_decision(w.deficit, state.deficit_bank, state.bank_deficit, b.alarm_period);
    if (d.decided && d.thruster >= 0 &&
        (b.hypotheses & (model::ThrusterMask{1} << w.set.index[static_cast<std::size_t>(d.thruster)])))
      out.confirmed = d.thruster;
  }
}

void step_rate_check_scheme(const FdirParams& p, FdirState& state, const model::SensorMeasurements& meas,
                            const FdirInput& in, fdi::FdiSchemeOutput& out) {
  const FdiWatchedParams& w = p.watched[static_cast<std::size_t>(state.watched)];
  fdi::RateCheckState& r = state.rate_check;
  fdi::RateCheckInput check{.t_s = in.t_s,
                            .omega_body_radps = meas.omega_body_radps,
                            .torque_cmd_body_Nm = in.commanded_wrench.tail<3>(),
                            .checked = in.checked_thruster,
                            .spill_Nms = fdi::spill_bound_Nms(p.rate_check, w.set, in.ton)};
  for (int lane = 0; lane < w.set.count; ++lane)
    check.on_fraction[static_cast<std::size_t>(w.set.index[static_cast<std::size_t>(lane)])] = in.ton[lane];
  fdi::step_rate_check(p.rate_check, r, check);
  const auto lane_of = [&](int thruster) {
    return thruster == model::kNoThruster ? -1 : w.set.lane[static_cast<std::size_t>(thruster)];
  };
  out.residual = Vec3(std::isnan(r.last_reading) ? 0.0 : r.last_reading, 0.0, 0.0);  // [-]
  out.glr = fdi::GlrStatistic::of_value(r.in_a_row > 0 ? r.sum / r.in_a_row : 0.0);   // the suspect's mean reading
  out.alarm = r.confirmed != model::kNoThruster;  // one reading is never an alarm
  out.alarm_time_s = r.confirmed_s;
  out.candidate = lane_of(r.suspect);
  out.confirmed = lane_of(r.confirmed);
  // The confirmation is a reading of the fault (what the recovery and the episode are told): stuck
  // closed or a loss of its size, nothing to cancel; or, where the valve is open already, a leak of
  // its size or stuck open, whose thrust the recovery cancels.
  const bool open_kind = r.kind == model::FaultKind::kLeak || r.kind == model::FaultKind::kStuckOpen;
  if (out.confirmed >= 0 && !state.rate_check_decision.decided)
    state.rate_check_decision = {.decided = true, .thruster = out.confirmed, .kind = r.kind, .size = r.size,
                                 .a = open_kind ? r.size : 0.0, .b = open_kind ? 0.0 : -r.size,
                                 .onset_sample = std::llround(r.suspect_pulse_s / p.period_s) - state.bank_first_period};
}

FdirEpisode current_episode(const FdirParams& p, const FdirState& f) {
  FdirEpisode e;
  e.armed_s = f.armed_s;
  if (p.watched.empty() || f.watched < 0) return e;
  const FdiWatchedParams& w = p.watched[static_cast<std::size_t>(f.watched)];
  e.watched = w.set.mask;
  const double T = p.period_s;
  e.schemes[kPositionScheme] = summary_of(w, p.position_enabled && f.position.alarm, static_cast<double>(f.position.alarm_period) * T,
                          f.position.confirmed, f.position_isolated_s, f.position_deficit.decision, f.bank_first_period, T);
  e.schemes[kAttitudeScheme] = summary_of(w, p.attitude_enabled && f.attitude.alarm, static_cast<double>(f.attitude.alarm_period) * T,
                          f.attitude.confirmed, f.attitude_isolated_s, f.attitude_deficit.decision, f.bank_first_period, T);
  e.schemes[kDeficitScheme] = summary_of(w, p.deficit_detection && f.detector.alarm,
                          static_cast<double>(f.detector.alarm_sample + f.bank_first_period) * T,
                          f.detector_deficit.decision.thruster, f.detector_isolated_s, f.detector_deficit.decision,
                          f.bank_first_period, T);
  const std::vector<DiagnosisScheme>& schemes = diagnosis_schemes();
  for (std::size_t i = kDeficitScheme + 1; i < schemes.size(); ++i) {
    const SchemeLatch& l = f.latches[i];
    // A scheme's name may be the deficit bank's (the observer bank's, step_bank_scheme): then its reading comes along.
    const fdi::DeficitDecision* bank = schemes[i].deficit ? schemes[i].deficit(f) : nullptr;
    const bool named_by_bank = bank && bank->decided && bank->thruster >= 0 && bank->thruster == l.confirmed;
    const fdi::DeficitDecision diagnosis = named_by_bank ? *bank : fdi::DeficitDecision{};
    e.schemes[i] = summary_of(w, schemes[i].enabled(p) && l.alarm_s >= 0, l.alarm_s, l.confirmed, l.isolated_s,
                              diagnosis, f.bank_first_period, T);
  }
  return e;
}

void rearm_fdir(const FdirParams& p, FdirState& state, model::ThrusterMask active, double t_s, int recovered_thruster) {
  if (state.episode_count < kMaxFdirEpisodes) {
    FdirEpisode& e = state.episodes[static_cast<std::size_t>(state.episode_count++)];
    e = current_episode(p, state);
    e.recovery_s = t_s;
    e.recovered_thruster = recovered_thruster;
  }
  state.watched = -1;
  for (std::size_t i = 0; i < p.watched.size(); ++i)
    if (p.watched[i].set.mask == active) state.watched = static_cast<int>(i);
  state.armed = false;
  state.rearm_s = t_s + p.rearm_after_recovery_s;
}

}  // namespace chaser::flight
