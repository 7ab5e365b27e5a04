#pragma once
// The on-board FDIR supervisor (Fonod 2015, Fig. 4-5 and section IV): the position-model and the
// attitude-model FDI schemes side by side, the propellant-based event resolution (Remark 2), and
// the recovery: once a scheme confirms a faulty thruster, close branch A's latch valve (which also
// stops a stuck-open thruster) and fly on with the redundant branch B.
//
// Isolation is either each scheme's own (eqs. 42-45, or the signature variant) or, with
// isolation_method deficit, the impulse-deficit bank (flight/fdi/deficit_isolation.hpp): the
// schemes then only detect, and after a scheme's alarm the bank names the thruster for it and
// says which fault it is and how large.
//
// The residual generators are designed in memory from the scenario when a run starts
// (make_fdir_params), so dispersed campaigns never fly a stale design.
#include "core/types.hpp"
#include "flight/fdi/deficit_detector.hpp"
#include "flight/fdi/deficit_isolation.hpp"
#include "flight/fdi/design_inputs.hpp"
#include "flight/fdi/event_resolution.hpp"
#include "flight/fdi/fdi_scheme.hpp"
#include "model/messages.hpp"
#include "model/scenario.hpp"

namespace chaser::flight {

struct FdirParams {
  bool position_enabled = false;
  bool attitude_enabled = false;
  bool recovery = false;
  fdi::FdiSchemeParams position;
  fdi::FdiSchemeParams attitude;
  fdi::EventResolutionParams event;
  bool deficit_isolation = false;   // the deficit bank names the thruster for both schemes
  fdi::DeficitIsolationParams deficit;
  bool deficit_detection = false;   // the deficit detector runs as a third scheme
  fdi::DeficitDetectorParams detector;
  std::array<double, model::kThrustersPerBranch> mass_flow_kgps{};  // [kg/s] branch A, nominal
  double period_s = 0.1;                                            // [s] T
};

enum class FdiModel { kPosition, kAttitude };

// What the residual generator of one scheme is designed from: the scenario's model (eq. 12 or 15)
// for branch A, the fault directions at the attitude flown (target pointing), and the fdi keys.
// `chaser fdi design` and make_fdir_params both use it, so the printed design is the flown one.
fdi::DesignInputs scheme_design_inputs(const model::Scenario& scenario, FdiModel model);

// Designs both residual generators (flight/fdi/residual_design) for the scenario's branch A.
FdirParams make_fdir_params(const model::Scenario& scenario);

struct FdirState {
  fdi::FdiSchemeState position;
  fdi::FdiSchemeState attitude;
  fdi::EventResolutionState event;
  fdi::DeficitBankState deficit_bank;           // samples of the last periods, with deficit isolation
  fdi::DeficitDecisionState position_deficit;   // the bank's decision after each scheme's alarm
  fdi::DeficitDecisionState attitude_deficit;
  fdi::DeficitDetectorState detector;           // the third scheme
  fdi::DeficitDecisionState detector_deficit;
  double detector_isolated_s = -1;
  double position_isolated_s = -1;  // [s] time a thruster was confirmed by each scheme, -1: not
  double attitude_isolated_s = -1;
  bool recovered = false;           // branch A closed, flying on branch B
  double recovery_s = -1;           // [s]
  int isolated_thruster = -1;       // 0..7 of branch A: the thruster recovery acted on
};

struct FdirOutput {
  fdi::FdiSchemeOutput position;
  fdi::FdiSchemeOutput attitude;
  fdi::FdiSchemeOutput detector;  // the deficit detector: glr = its statistic, candidate = its suspect
  bool over_consumption = false;  // event resolution: cases 1/3 (true) or 2/4
  bool recover_now = false;       // this period's confirmation triggers the switch to branch B
};

// Quantities of one period the FDI schemes read besides the measurements (flight-side only:
// estimates, the reference attitude and the command of this period).
struct FdirInput {
  double t_s = 0;                           // [s]
  Quat q_est_inertial_from_body;           // navigation estimate
  Quat q_ref_inertial_from_body;           // target-pointing reference
  Quat q_inertial_from_lvlh;               // LVLH orientation now
  model::Ton8 ton = model::Ton8::Zero();   // commanded on-times of branch A this period
  Vec6 commanded_wrench = Vec6::Zero();    // [N; N m] body axes: M ton, as the TMF computed it
};

FdirOutput step_fdir(const FdirParams& params, FdirState& state, const model::SensorMeasurements& meas,
                     const FdirInput& in);

}  // namespace chaser::flight
