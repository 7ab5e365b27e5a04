#pragma once
// Parameters of the thruster fault detection, isolation and recovery (Fonod 2015, sections IV-V).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "model/thrusters.hpp"

namespace chaser::model {

// One residual-generator scheme: built on the position model (eq. 12) or the attitude model (15).
struct FdiSchemeParams {
  bool enabled = true;
  int residual_dimension = 1;   // [-] n_r (eq. 34); the paper uses 1
  double sigma0 = 1e-3;         // [m or rad] fault-free standard deviation of the residual (eq. 41)
};

// How the faulty thruster is named once the alarm is raised.
enum class IsolationMethod {
  kPaper,      // cross-correlation of the residual with the on-times, eqs. 42-45 (the published one)
  kSignature,  // correlation with each thruster's residual signature (flight/fdi/isolation.hpp)
  kDeficit,    // 6-DOF impulse-deficit hypothesis bank (flight/fdi/deficit_isolation.hpp)
};

// What the deficit detector (the third scheme) alarms on.
enum class DetectionStatistic {
  kGain,     // the hypotheses' GLR gain on a sliding window of torque rows (flight/fdi/deficit_detector.hpp)
  kImpulse,  // the change of the mean torque row as an impulse (flight/fdi/impulse_detector.hpp)
};

// The impulse statistic sums the torque rows in blocks of about a second: this many control periods.
inline int impulse_block_periods(double control_period_s) {
  return std::max(1, static_cast<int>(std::lround(1.0 / control_period_s)));
}
// A window of the impulse statistic in whole blocks (at least one), as the flight software takes it.
inline int impulse_blocks(double seconds, double control_period_s) {
  const double block_s = impulse_block_periods(control_period_s) * control_period_s;
  return std::max(1, static_cast<int>(std::lround(seconds / block_s)));
}
// Longest impulse window plus baseline the on-board ring holds, in blocks.
inline constexpr int kMaxImpulseBlocks = 600;

// Samples the deficit isolation's on-board ring holds: its longest window is one less.
inline constexpr int kMaxDeficitWindowPeriods = 160;

// The bank of unknown-input observers on the body-rate model (COMRADE 2018, sec. 6.3;
// flight/fdi/design/uio_bank.hpp, flight/fdi/observer_bank.hpp): its design weights and, with
// `enabled`, its run as a diagnosis scheme. Needs chaser.slosh (the rate model's tanks).

struct ObserverBankParams {
  bool enabled = false;               // run the bank as the `bank` diagnosis scheme
  double disturbance_torque_Nm = 0.1;  // [N m] 1 sigma per period per axis: the torque the model leaves out
  double gamma_backoff = 1.1;          // [-] the observers' gamma over the smallest admissible, in (1, 10]
  double window_s = 20.0;              // [s] W: the residuals' recent mean ...
  double baseline_s = 100.0;           // [s] L: ... against their mean over the L seconds before
  double threshold_Nm = 1.0;           // [N m] the nominal observer's change, as torque, over the model-error bound, that alarms
  double isolation_ratio = 0.2;        // [-] an observer whose change is below this x the nominal's is blind to the fault
};

// The multi-estimator supervisor (COMRADE 2018, sec. 6.3; flight/fdi/mode_supervisor.hpp): 2N + 1
// modes for the N monitored thrusters (nominal, each one stuck open, each one stuck closed), one
// estimator each on the observer bank's rate model, a switching signal with a dwell time and a
// hysteresis. With `accommodate`, the allocation flies the mode it names (the virtual actuator).
// Needs chaser.slosh.
struct SupervisorParams {
  bool enabled = false;          // run it (its mode and switches go to telemetry and results)
  bool accommodate = false;      // the allocation follows its mode; needs fdi.recovery: none
  ThrusterMask thrusters = 0;    // monitored, by index
  double forgetting_s = 2.0;     // [s] the monitoring signals' memory
  double bias_s = 100.0;         // [s] the residual every estimator shares, low-passed over this
  double settle_s = 100.0;       // [s] no switch before this time into the run
  double dwell_s = 5.0;          // [s] least time between two switches
  double hysteresis = 1.0;       // [-] relative: (1 + h) mu_k + floor^2 < mu_sigma to switch
  double floor_radps = 1e-4;     // [rad/s] absolute
};

// The impulse-deficit isolation (flight/fdi/deficit_isolation.hpp): its window about the alarm and
// its decision thresholds.
struct DeficitParams {
  double window_before_s = 2.0;   // [s] fit window starts this long before the alarm (onsets scanned)
  double window_after_s = 0.5;    // [s] first evaluation this long after the alarm
  double window_max_s = 15.0;     // [s] longest window while the decision is ambiguous
  double pulse_uncertainty = 0.01;  // [-] relative 1-sigma error of a commanded pulse's torque
  double inertia_uncertainty = 0.0; // [-] relative error bound of the nominal inertia (gyroscopic term)
  double com_uncertainty_m = 0.0;   // [m] error bound of the nominal centre of mass per axis
  double min_gain = 50.0;         // [-] log-likelihood gain the best hypothesis must reach
  double min_margin = 25.0;       // [-] its lead over the second best
  // The deficit detector (flight/fdi/deficit_detector.hpp): a third scheme on the gyro's torque rows.
  bool detection = true;            // run it (with isolation_method deficit only)
  double detection_window_s = 10.0; // [s] sliding window N T
  double detection_threshold = 100.0;  // [-] on the gain S_i
  double detection_min_constant = 0.05;      // [-] smallest constant deficit a that counts
  double detection_min_proportional = 0.3;   // [-] smallest command-proportional deficit -b that counts
  DetectionStatistic detection_statistic = DetectionStatistic::kGain;
  // The impulse statistic (flight/fdi/impulse_detector.hpp): the change of the mean torque row over
  // the last impulse_window_s against the impulse_baseline_s before it, as an impulse.
  double impulse_window_s = 20.0;         // [s] W
  double impulse_baseline_s = 100.0;      // [s] L
  double impulse_threshold_Nms = 40.0;    // [N m s] on the change's largest excess over the model-error bound
};

// Longest detector window the on-board sums hold, in periods.
inline constexpr int kMaxDeficitDetectorWindowPeriods = 256;

// The Fonod 2015 schemes (position, attitude) watch exactly this many active thrusters (MSR's
// branch of eight): their isolation kernels are fixed-size (flight/fdi/watched_set.hpp), and
// validate_scenario refuses fdi.position or fdi.attitude on an active set of another size.
// Chaser's deficit bank and detector watch any active set of 1..kMaxThrusters.
inline constexpr int kFdiSchemeThrusters = 8;

// Active checks of dormant thrusters (flight/active_check.hpp): a thruster the approach
// does not command cannot be diagnosed from its effects, so when one has not fired an informative
// pulse for max_unverified_s, the allocation gives it a test pulse that the others cancel.
struct ActiveCheckParams {
  bool enabled = false;
  double max_unverified_s = 25.0;   // [s] longest time an active thruster may go without an informative pulse
  double informative_on_time_s = 0.005;  // [s] a commanded on-time this long or longer is informative
  double pulse_s = 0.0075;          // [s] a check's on-time (at least informative_on_time_s)
  double keep_quiet_range_m = 2.0;  // [m] no check while the estimated range to the target is below this
  // [m] checks only once the estimated range is at most this: a check just before the final phase
  // that needs every thruster, instead of all along the approach (infinity: all along; docs/fdi.md)
  double arm_range_m = std::numeric_limits<double>::infinity();
  // [-] a thruster the deficit detector suspects (its material deficit's gain above this fraction
  // of fdi.deficit.detection_threshold) is unverified whatever it fired: checked again at once, so an
  // inconclusive check is followed by another instead of waiting max_unverified_s (1: never)
  double recheck_fraction = 0.5;
};

// Active checks read from the body rates (flight/fdi/rate_check.hpp): each check pulse's missing
// share, from the gyro over its period against the periods either side; with `enabled`, the
// `rate_check` diagnosis scheme. Needs active_check.enabled (it reads nothing else).
inline constexpr int kMaxRateCheckNeighbours = 10;  // the readings' ring holds 2 x this + 2 periods

struct RateCheckParams {
  bool enabled = false;
  int neighbours = 5;               // [periods] either side of a pulse whose median reading is its baseline
  double threshold = 0.25;          // [-] a reading (the pulse's missing share) from which the thruster is suspect
  int confirmations = 3;            // readings in a row at least the threshold that confirm the fault
  double stuck_closed_from = 0.8;   // [-] mean reading from which the fault reads stuck closed (below: a loss)
  double max_uncertainty = 0.5;     // [-] a reading's bound on a healthy thruster above which it is inconclusive
};

enum class RecoveryPolicy {
  kNone,         // diagnose only
  kSwitchGroup,  // close the faulty thruster's group latch, fly on with the next standby group
  // Fly on without the faulty thruster (the allocation gives it no on-time and, where the diagnosis
  // read it stuck open or leaking, cancels the thrust it keeps giving): any layout whose every N-1
  // set still pushes and turns everywhere; once per run (model/recovery.hpp).
  kExclude,
};

struct FdiParams {
  // Design (eqs. 19-39): assigned observer eigenvalues, Taylor order h of Prop. 2, and the upper
  // bound of the unknown part of the delay that the design decouples (the paper: T).
  std::array<double, 6> eigenvalues{0.85, 0.87, 0.89, 0.91, 0.93, 0.95};  // [-] inside the unit circle
  int taylor_order = 2;             // [-] h
  double design_delay_max_s = 0.1;  // [s] in (0, T]
  // Detection (eqs. 40-41), isolation (42-44) and confirmation (45) windows, in control periods.
  int glr_window = 10;              // [-] N_d
  double glr_threshold = 20.0;      // [-] J_th
  int isolation_window = 10;        // [-] N
  int confirmation_window = 15;     // [-] N_c
  IsolationMethod isolation_method = IsolationMethod::kPaper;
  int isolation_settle = 0;         // [-] periods after the alarm before isolation starts (0: paper)
  bool glr_increase_only = false;   // [-] only a residual increase counts (eq. 41 as printed: false)
  DeficitParams deficit;            // used when isolation_method is kDeficit
  ObserverBankParams observer_bank;
  SupervisorParams supervisor;  // optional section: off
  // Event resolution (Remark 2): over-consumption separating cases 1/3 from 2/4.
  double over_consumption_threshold_kg = 0.005;  // [kg] measured minus expected since the alarm
  // Recovery (flight/recovery.hpp): what a confirmed fault changes in the active set, and how long
  // the diagnosis then waits before it watches the new set (the fault's trace leaves the residual
  // generators' state at the rate of their eigenvalues).
  RecoveryPolicy recovery = RecoveryPolicy::kSwitchGroup;
  double rearm_after_recovery_s = 10.0;  // [s]
  ActiveCheckParams active_check;
  RateCheckParams rate_check;  // optional section: off
  FdiSchemeParams position;
  FdiSchemeParams attitude;
};

// Tank gauging: the propellant used so far, as the flight software reads it.
struct PropellantSensorParams {
  double noise_sigma_kg = 1e-4;  // [kg] 1-sigma white noise per reading
};

}  // namespace chaser::model
