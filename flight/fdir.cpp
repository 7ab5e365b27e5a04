#include "flight/fdir.hpp"

#include <algorithm>
#include <cmath>

#include "core/rotation.hpp"
#include "flight/fdi/design_inputs.hpp"
#include "flight/fdi/residual_design.hpp"
#include "flight/fdi/residual_generator.hpp"
#include "flight/guidance.hpp"
#include "model/thruster_geometry.hpp"

namespace chaser::flight {

namespace {

// thruster_inputs: each thruster's input direction in the model (3 x 8: M_F or M_C).
fdi::FdiSchemeParams scheme_params(const model::Scenario& s, const model::FdiSchemeParams& scheme,
                                   const fdi::DesignInputs& inputs, const fdi::Mat38& thruster_inputs) {
  const fdi::ResidualDesign design = fdi::design_residual_generator(inputs);
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
  if (s.fdi.isolation_method == model::IsolationMethod::kSignature) {
    p.isolation.criterion = fdi::IsolationCriterion::kSignature;
    p.isolation.signature = fdi::make_signature_filter(p.residual, thruster_inputs);
  }
  p.isolate = s.fdi.isolation_method != model::IsolationMethod::kDeficit;
  p.period_s = s.control_period_s;
  return p;
}

int whole_periods(double seconds, double period_s) { return static_cast<int>(std::lround(seconds / period_s)); }

fdi::DeficitIsolationParams deficit_params(const model::Scenario& s, const model::ConfigMatrix& config) {
  const double T = s.control_period_s;
  fdi::DeficitIsolationParams p;
  p.inertia_kgm2 = s.chaser.inertia_kgm2;
  p.mass_kg = s.chaser.mass_kg;
  p.force_body_N = config.topRows<3>();
  p.torque_body_Nm = config.bottomRows<3>();
  p.period_s = T;
  p.before = whole_periods(s.fdi.deficit.window_before_s, T);
  p.after = whole_periods(s.fdi.deficit.window_after_s, T);
  p.max_window = whole_periods(s.fdi.deficit.window_max_s, T);
  // The sensor specifications set the weights; a noiseless sensor gets a small floor so that the
  // weights stay finite.
  p.lidar_sigma_m = std::max(s.sensors.lidar.noise_sigma_m, 1e-6);
  p.gyro_sigma_radps = std::max(s.sensors.gyro.noise_sigma_radps, 1e-9);
  p.pulse_uncertainty = s.fdi.deficit.pulse_uncertainty;
  p.min_gain = s.fdi.deficit.min_gain;
  p.min_margin = s.fdi.deficit.min_margin;
  p.min_a = s.fdi.deficit.detection_min_constant;
  p.min_b = s.fdi.deficit.detection_min_proportional;
  return p;
}

// A scheme's isolation by the deficit bank: once the scheme has alarmed, the bank's decision (made
// a few seconds later) becomes the scheme's confirmed thruster.
void deficit_confirmation(const FdirParams& p, FdirState& state, fdi::DeficitDecisionState& decision,
                          fdi::FdiSchemeState& scheme, fdi::FdiSchemeOutput& out) {
  const fdi::DeficitDecision& d =
      fdi::step_deficit_decision(p.deficit, state.deficit_bank, decision, scheme.alarm ? scheme.alarm_period : -1);
  if (d.decided && d.thruster >= 0 && scheme.confirmed < 0) scheme.confirmed = d.thruster;
  out.confirmed = scheme.confirmed;
}

}  // namespace

fdi::DesignInputs scheme_design_inputs(const model::Scenario& s, FdiModel model) {
  const model::ConfigMatrix config = model::configuration_matrix(s.thrusters, 0, s.chaser.com_body_m);
  fdi::DesignInputs inputs;
  if (model == FdiModel::kPosition) {
    // The position model's input is the force in LVLH (eq. 20): the fault directions are those of
    // the attitude the chaser flies, target pointing, not of body axes aligned with LVLH.
    const Mat3 R_lvlh_from_body = target_pointing_q_lvlh_from_body(s.guidance.approach_axis_lvlh).toRotationMatrix();
    inputs = fdi::position_design_inputs(s, config);
    inputs.fault_inputs = R_lvlh_from_body * config.topRows<3>();
    inputs.E_f = inputs.B * inputs.fault_inputs;
  } else {
    inputs = fdi::attitude_design_inputs(s, config);
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
  p.position_enabled = s.fdi.position.enabled;
  p.attitude_enabled = s.fdi.attitude.enabled;
  if (p.position_enabled) {
    const fdi::DesignInputs inputs = scheme_design_inputs(s, FdiModel::kPosition);
    p.position = scheme_params(s, s.fdi.position, inputs, inputs.fault_inputs);
  }
  if (p.attitude_enabled) {
    const fdi::DesignInputs inputs = scheme_design_inputs(s, FdiModel::kAttitude);
    p.attitude = scheme_params(s, s.fdi.attitude, inputs, inputs.fault_inputs);
  }
  p.event.sensor_sigma_kg = s.sensors.propellant.noise_sigma_kg;
  p.event.absolute_margin_kg = s.fdi.over_consumption_threshold_kg;
  p.mass_flow_kgps = fdi::nominal_mass_flow_kgps(s.thrusters, 0, s.chaser.isp_s);
  p.deficit_isolation = s.fdi.isolation_method == model::IsolationMethod::kDeficit;
  if (p.deficit_isolation)
    p.deficit = deficit_params(s, model::configuration_matrix(s.thrusters, 0, s.chaser.com_body_m));
  p.deficit_detection = p.deficit_isolation && s.fdi.deficit.detection;
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
  return p;
}

FdirOutput step_fdir(const FdirParams& p, FdirState& state, const model::SensorMeasurements& meas,
                     const FdirInput& in) {
  FdirOutput out;
  if (state.recovered) {  // the schemes watch branch A only: report their latched decisions
    out.position.alarm = state.position.alarm, out.position.confirmed = state.position.confirmed;
    out.attitude.alarm = state.attitude.alarm, out.attitude.confirmed = state.attitude.confirmed;
    out.detector.alarm = state.detector.alarm, out.detector.confirmed = state.detector_deficit.decision.thruster;
    out.over_consumption = state.event.over_consumption;
    return out;
  }
  const Vec6& wrench = in.commanded_wrench;

  // Remark 2: over-consumption separates cases 1/3 from 2/4; it runs once either scheme alarms.
  const bool alarm_before = state.position.alarm || state.attitude.alarm;
  // The expected increment is read only while the resolution is active (step_event_resolution).
  const double expected_kg =
      state.event.active ? fdi::expected_propellant_increment_kg(in.ton, p.mass_flow_kgps, p.period_s) : 0.0;
  out.over_consumption =
      fdi::step_event_resolution(p.event, state.event, meas.propellant_used_kg, expected_kg, alarm_before);

  const Quat q_lvlh_from_body = in.q_inertial_from_lvlh.conjugate() * in.q_est_inertial_from_body;
  if (p.deficit_isolation) {
    fdi::DeficitSample& sample = fdi::next_deficit_sample(state.deficit_bank);
    sample.omega_body_radps = meas.omega_body_radps;
    sample.r_lvlh_m = meas.r_lvlh_m;
    sample.q_lvlh_from_body = q_lvlh_from_body;
    sample.ton = in.ton;
    sample.mass_kg = p.deficit.mass_kg - meas.propellant_used_kg;
    fdi::push_deficit_sample(p.deficit, state.deficit_bank);
  }
  if (p.deficit_detection) {
    fdi::step_deficit_detector(p.detector, p.deficit, state.deficit_bank, state.detector);
    const fdi::DeficitDecision& d =
        fdi::step_deficit_decision(p.deficit, state.deficit_bank, state.detector_deficit,
                                   state.detector.alarm ? state.detector.alarm_sample : -1);
    out.detector.glr = fdi::GlrStatistic::of_value(state.detector.statistic);
    out.detector.alarm = state.detector.alarm;
    out.detector.candidate = state.detector.suspect;
    out.detector.confirmed = d.thruster;
    out.detector.alarm_time_s = state.detector.alarm ? state.detector.alarm_sample * p.period_s : -1.0;
    if (d.thruster >= 0 && state.detector_isolated_s < 0) state.detector_isolated_s = in.t_s;
  }

  if (p.position_enabled) {
    // Eq. 20: u_c = R(Q_tgt, Q_chs) M_F T_on, the commanded force rotated into LVLH with the
    // estimated attitude; y is the LIDAR position.
    const Vec3 u_c = q_lvlh_from_body * Vec3(wrench.head<3>());
    fdi::step_fdi_scheme(p.position, state.position, meas.r_lvlh_m, u_c, in.ton, out.over_consumption, out.position);
    if (p.deficit_isolation) deficit_confirmation(p, state, state.position_deficit, state.position, out.position);
    if (out.position.confirmed >= 0 && state.position_isolated_s < 0) state.position_isolated_s = in.t_s;
  }
  if (p.attitude_enabled) {
    // Eq. 16-17: u_c = M_C T_on; y is the measured attitude about the target-pointing reference,
    // the small angles of the linearised model (eq. 15): 2 vec(q), equal to them to first order.
    const Vec3 angles = small_angle_error_body(in.q_ref_inertial_from_body, meas.q_inertial_from_body);
    fdi::step_fdi_scheme(p.attitude, state.attitude, angles, Vec3(wrench.tail<3>()), in.ton, out.over_consumption,
                         out.attitude);
    if (p.deficit_isolation) deficit_confirmation(p, state, state.attitude_deficit, state.attitude, out.attitude);
    if (out.attitude.confirmed >= 0 && state.attitude_isolated_s < 0) state.attitude_isolated_s = in.t_s;
  }

  // The fault-free noise estimate of the deficit bank must not learn from the fault.
  if (state.position.alarm || state.attitude.alarm || state.detector.alarm) state.deficit_bank.frozen = true;

  // Recovery on the first confirmation by either scheme.
  int confirmed = -1;
  for (const fdi::FdiSchemeOutput* scheme : {&out.position, &out.attitude, &out.detector})
    if (confirmed < 0) confirmed = scheme->confirmed;
  if (p.recovery && confirmed >= 0) {
    state.recovered = true;
    state.recovery_s = in.t_s;
    state.isolated_thruster = confirmed;
    out.recover_now = true;
  }
  return out;
}

}  // namespace chaser::flight
