#pragma once
// The on-board FDIR supervisor (Fonod 2015, Fig. 4-5 and section IV): the position-model and the
// attitude-model FDI schemes side by side, the propellant-based event resolution (Remark 2), and
// the confirmation that triggers the recovery. The schemes watch the active thrusters (the watched
// set, flight/fdi/watched_set.hpp); when a recovery changes the active set (model/recovery.hpp,
// applied by step_flight), rearm_fdir points them at the new set and, after a settling time, they
// watch it as they watched the first: a second fault is diagnosed like the first.
//
// Isolation is either each scheme's own (eqs. 42-45, or the signature variant) or, with
// isolation_method deficit, the impulse-deficit bank (flight/fdi/deficit_isolation.hpp): the
// schemes then only detect, and after a scheme's alarm the bank names the thruster for it and
// says which fault it is and how large.
//
// The residual generators are designed in memory from the scenario when a run starts
// (make_fdir_params), so dispersed campaigns never fly a stale design.
#include <array>
#include <vector>

#include "core/types.hpp"
#include "flight/diagnosis_schemes.hpp"
#include "flight/fdi/deficit_detector.hpp"
#include "flight/fdi/deficit_isolation.hpp"
#include "flight/fdi/design/design_inputs.hpp"
#include "flight/fdi/event_resolution.hpp"
#include "flight/fdi/fdi_scheme.hpp"
#include "flight/fdi/impulse_detector.hpp"
#include "flight/fdi/observer_bank.hpp"
#include "flight/fdi/rate_check.hpp"
#include "model/messages.hpp"
#include "model/scenario.hpp"

namespace chaser::flight {

// What depends on which thrusters the FDI watches: isolation signatures, the deficit bank's
// columns, the mass flows of event resolution. The residual generators' gains are designed once,
// for the starting set (make_fdir_params), and kept after a recovery: their delay decoupling
// (eqs. 19-23) lives in input space, the same for every set; only the choice of the residual
// weighting (the weakest DC fault gain) looks at the starting set's fault directions. On MSR the
// choice is the same for branch B (same forces, torques scaled by 0.95).
struct FdiWatchedParams {
  fdi::WatchedSet set;
  fdi::FdiSchemeParams position;
  fdi::FdiSchemeParams attitude;
  fdi::DeficitIsolationParams deficit;
  std::array<double, fdi::kMaxWatchedThrusters> mass_flow_kgps{};  // [kg/s] nominal, per lane (zero past the set)
};

struct FdirParams {
  bool position_enabled = false;
  bool attitude_enabled = false;
  model::RecoveryPolicy recovery = model::RecoveryPolicy::kNone;
  fdi::EventResolutionParams event;
  bool deficit_isolation = false;   // the deficit bank names the thruster for both schemes
  bool deficit_detection = false;   // the deficit detector runs as a third scheme
  fdi::DeficitDetectorParams detector;
  // The detector's statistic: the gain (detector) or, with fdi.deficit.detection_statistic impulse,
  // the impulse (flight/fdi/impulse_detector.hpp).
  bool impulse_detection = false;
  fdi::ImpulseDetectorParams impulse;
  // The observer bank on the body-rate model (fdi.observer_bank.enabled): the `bank` scheme.
  bool bank_enabled = false;
  fdi::ObserverBankFlightParams bank;
  // The active checks read from the rates (fdi.rate_check.enabled): the `rate_check` scheme.
  bool rate_check_enabled = false;
  fdi::RateCheckParams rate_check;
  // [0]: the starting active set; then every set a recovery can switch to (with the FDI's size).
  std::vector<FdiWatchedParams> watched;
  double period_s = 0.1;                 // [s] T
  double rearm_after_recovery_s = 10.0;  // [s] from a recovery to watching the new set
  int schemes = 3;  // rows of diagnosis_schemes() when made: the period reads this, not the table
};

enum class FdiModel { kPosition, kAttitude };

// What the residual generator of one scheme is designed from: the scenario's model (eq. 12 or 15)
// for the starting active set, the fault directions at the attitude flown (target pointing), and
// the fdi keys. `chaser fdi design` and make_fdir_params both use it, so the printed design is the
// flown one.
fdi::DesignInputs scheme_design_inputs(const model::Scenario& scenario, FdiModel model);

// Designs both residual generators for the scenario's starting active set and prepares every set
// a recovery can lead to.
FdirParams make_fdir_params(const model::Scenario& scenario);

// One scheme's figures at the end of a diagnosis (for results; thrusters by index).
struct SchemeSummary {
  bool alarm = false;
  double alarm_s = -1;                    // [s] -1: none
  int confirmed = model::kNoThruster;     // thruster index
  double isolated_s = -1;                 // [s] time it was confirmed, -1: not
  fdi::DeficitDecision diagnosis;         // the deficit bank's reading (thruster: a lane)
  double estimated_onset_s = -1;          // [s] the diagnosis' onset, -1: none
};

// One fault's diagnosis, from the time the FDI was (re)armed on a watched set to the recovery it
// triggered (or the end of the run).
struct FdirEpisode {
  double armed_s = 0;            // [s]
  model::ThrusterMask watched = 0;
  std::array<SchemeSummary, kMaxDiagnosisSchemes> schemes{};  // by slot (flight/diagnosis_schemes.hpp)
  double recovery_s = -1;        // [s] -1: none
  int recovered_thruster = model::kNoThruster;  // index
};

inline constexpr int kMaxFdirEpisodes = 8;

// What step_fdir latches for a registered scheme (one with a `step`): its first alarm and its
// first confirmation in the current watch.
struct SchemeLatch {
  double alarm_s = -1;     // [s] -1: none
  int confirmed = -1;      // lane, -1: none
  double isolated_s = -1;  // [s] -1: none
};

struct FdirState {
  int watched = 0;                  // index into FdirParams::watched
  bool armed = true;                // false from a recovery until rearm_s
  bool lidar_gap = false;           // the LIDAR has lost the target in this watch: the deficit bank has stopped
  double armed_s = 0;               // [s] when the current watch started
  double rearm_s = -1;              // [s]
  double stood_down_s = -1;         // [s] when the diagnosis stood down for good (the capture), -1: not
  std::int64_t bank_first_period = 0;  // control period of the deficit bank's sample 0
  fdi::FdiSchemeState position;
  fdi::FdiSchemeState attitude;
  fdi::EventResolutionState event;
  fdi::DeficitBankState deficit_bank;           // samples of the last periods, with deficit isolation
  fdi::DeficitDecisionState position_deficit;   // the bank's decision after each scheme's alarm
  fdi::DeficitDecisionState attitude_deficit;
  fdi::DeficitDetectorState detector;           // the third scheme (its verdict, whichever statistic)
  fdi::ImpulseDetectorState impulse;            // its impulse statistic, with impulse_detection
  fdi::DeficitDecisionState detector_deficit;
  double detector_isolated_s = -1;
  fdi::ObserverBankState bank;                  // the observer bank, with bank_enabled (sized in its first period)
  fdi::DeficitDecisionState bank_deficit;       // the deficit bank's name after the observer bank's alarm
  fdi::RateCheckState rate_check;               // the checks' readings, with rate_check_enabled
  fdi::DeficitDecision rate_check_decision;     // its confirmation as a reading of the fault (kind, size)
  double position_isolated_s = -1;  // [s] time a thruster was confirmed by each scheme, -1: not
  double attitude_isolated_s = -1;
  std::array<SchemeLatch, kMaxDiagnosisSchemes> latches{};  // registered schemes' slots
  int confirmed_thruster = model::kNoThruster;  // index: the first confirmation of this watch
  double confirmed_s = -1;          // [s]
  std::array<FdirEpisode, kMaxFdirEpisodes> episodes{};  // finished diagnoses (a recovery ended them)
  int episode_count = 0;
};

struct FdirOutput {
  // By slot (flight/diagnosis_schemes.hpp); candidate and confirmed: lanes of the watched set. The
  // deficit detector's glr is its statistic, its candidate its suspect.
  std::array<fdi::FdiSchemeOutput, kMaxDiagnosisSchemes> schemes{};
  bool over_consumption = false;  // event resolution: cases 1/3 (true) or 2/4
  int confirmed_now = model::kNoThruster;  // index of a thruster first confirmed this period
  // [-] The on-time that thruster keeps giving whatever it is commanded, as the deficit bank read its
  // fault: 1 stuck open, a leak's size; 0 for stuck closed or a loss, and where no bank decided (the
  // published isolation names a thruster, not its fault). What fdi.recovery: exclude cancels.
  double confirmed_uncommanded_on_fraction = 0;
};

// Quantities of one period the FDI schemes read besides the measurements (flight-side only:
// estimates, the reference attitude and the command of this period).
struct FdirInput {
  double t_s = 0;                           // [s]
  std::int64_t period = 0;                  // control period k
  Quat q_est_inertial_from_body;           // navigation estimate
  Quat q_ref_inertial_from_body;           // target-pointing reference
  Quat q_inertial_from_lvlh;               // LVLH orientation now
  fdi::WatchedTon ton = fdi::WatchedTon::Zero();  // commanded on-times of the watched lanes
  Vec6 commanded_wrench = Vec6::Zero();    // [N; N m] body axes: M ton, as the TMF computed it
  int checked_thruster = model::kNoThruster;  // index: the thruster an active check pulses this period
  // The awake arm's share of the torque rows (flight/arm_reaction.hpp), body axes; zero without it.
  Vec3 arm_momentum_Nms = Vec3::Zero();  // [N m s]
  Vec3 com_shift_m = Vec3::Zero();       // [m]
};

// Writes the period's output into `out`, value-initialised by the caller (FlightOutput's): its
// scheme slots are a few hundred bytes, which a returned value would copy every period.
void step_fdir(const FdirParams& params, FdirState& state, const model::SensorMeasurements& meas, const FdirInput& in,
               FdirOutput& out);

// The observer bank's period (the `bank` row of flight/diagnosis_schemes.hpp): its observers, its
// alarm and hypotheses, and, when they leave more than one thruster and the deficit bank runs
// (isolation_method deficit), the deficit bank's name if it is one of them.
void step_bank_scheme(const FdirParams& params, FdirState& state, const model::SensorMeasurements& meas,
                      const FdirInput& in, fdi::FdiSchemeOutput& out);

// The rate check's period (the `rate_check` row): reads the active checks' pulses from the gyro,
// confirms a thruster that does not deliver them (flight/fdi/rate_check.hpp).
void step_rate_check_scheme(const FdirParams& params, FdirState& state, const model::SensorMeasurements& meas,
                            const FdirInput& in, fdi::FdiSchemeOutput& out);

// The figures of the current watch (not yet ended by a recovery).
FdirEpisode current_episode(const FdirParams& params, const FdirState& state);

// After a recovery at t_s that made `active` the active set: ends the current episode (recording
// the recovery) and points the schemes at the new set; they watch it from t_s +
// rearm_after_recovery_s. If the FDI has no parameters for that set, it stays disarmed.
void rearm_fdir(const FdirParams& params, FdirState& state, model::ThrusterMask active, double t_s,
                int recovered_thruster);

// The thruster (index) the active checks check again at once (flight/active_check.hpp), kNoThruster
// without one (disarmed, or nothing suspect): the rate check's, a reading that wants another look
// (fdi.rate_check), else the deficit detector's suspect, a material deficit with a gain above
// `deficit_min_gain` before any alarm.
int thruster_to_check_again(const FdirParams& params, const FdirState& state, double deficit_min_gain);

// Whether a check can still show the FDI something: it watches (armed) and has not yet confirmed a
// fault in this watch. After a confirmation the schemes have latched until a recovery rearms them
// on a new set, so a check would only cost propellant and disturb a flight already degraded.
bool fdi_listening(const FdirState& state);

// The lanes the FDI watches now.
const fdi::WatchedSet& watched_set(const FdirParams& params, const FdirState& state);

// The watched lanes' on-times out of a command to every thruster (zero without an FDI).
fdi::WatchedTon watched_on_times(const FdirParams& params, const FdirState& state, const model::ThrusterOnTimes& ton);

// With a watched thruster out of the active set that still fires on its own (excluded stuck open or
// leaking, fdi.recovery: exclude), its lane read at that known on-time: the FDI's rows then hold its
// thrust, as the allocation's books do, and it watches on. A thruster outside the watched set: nothing.
void add_uncommanded_on_time(const FdirParams& params, const FdirState& state, int thruster, double on_fraction,
                             fdi::WatchedTon& lanes);

}  // namespace chaser::flight
