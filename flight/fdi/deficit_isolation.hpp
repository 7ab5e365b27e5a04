#pragma once
// Thruster fault isolation by a bank of impulse-deficit hypotheses (Chaser's method; docs/fdi.md,
// "Impulse-deficit isolation"). It replaces eqs. 42-45 where they cannot work in the closed loop:
// the controller stops commanding a stuck-open or leaking thruster and its partner at once, so a
// criterion that correlates the residual with the commands sees nothing (docs/fdi.md, findings 1-5).
//
// Hypothesis i: thruster i realises T_on,i(k) + delta_i(k) instead of the commanded T_on,i(k), with
//   delta_i(k) = (a + b T_on,i(k)) [k >= k_f]
// a constant part a (stuck open: 1, leak: about m_leak) and a part proportional to the command b
// (stuck closed: -1, loss: -m_loss, stuck open: -1 when still commanded), from an onset k_f. On a
// window of N periods around the alarm, weighted least squares over all six axes:
//   torque rows, body axes, from the gyro, k = 0..N-2 (Euler's equation over one period):
//     I (omega(k+1) - omega(k)) / T + omega(k) x I omega(k) - M_C T_on(k) = M_C,i delta_i(k)
//   position rows, LVLH, from the LIDAR, k = 0..N-1 (the double integral of piecewise-constant
//   accelerations; HCW terms below 1e-4 N equivalent here are left out):
//     r(k) - sum_{j<k} T^2 (k - j - 1/2) R(j) M_F T_on(j) / m(j)
//          = r0 + v0 t_k + sum_{j<k} T^2 (k - j - 1/2) R(j) M_F,i delta_i(j) / m(j)
// with R(j) = R_lvlh_from_body from the estimated attitude (valid through a tumble: no small-angle
// model), m(j) the nominal mass less the measured propellant used, r0 and v0 free.
// The gain of hypothesis i is the drop of the weighted residual sum of squares from the no-fault
// fit (r0, v0 only) to the best onset k_f of hypothesis i: a log-likelihood ratio (GLR) for
// Gaussian row errors. Partners (same torque, opposite force) are told apart by the position rows.
// The isolated thruster is the hypothesis with the largest gain, once it is large enough and ahead
// of the second by a margin, and its deficit is material (a or -b large enough); (a, b) then say
// which fault it is and how large (this replaces the
// propellant-based event resolution for the diagnosis).
//
// Weights: position rows 1/sigma_lidar; torque rows per axis 1/sigma with
//   sigma^2 = sigma_0^2 + (epsilon |M_C| T_on(k))^2 + sigma_model(k)^2,
// sigma_0 the RMS of the fault-free torque rows (an exponentially weighted estimate while no alarm,
// never below the gyro noise floor I sqrt(2) sigma_gyro / T), epsilon the relative thrust and
// timing error of a commanded pulse. sigma_model (deficit_model_sigma) bounds what the rows leave
// out and the flight software can size from its specifications, all zero in MSR's approach:
//   the delay spill: a pulse longer than (1 - tau_max / T) of its period ends in the next period by
//     up to T_on + tau_max / T - 1 of a period (the delay is redrawn each period, so the spill into
//     row k from pulse k-1 and out of it from pulse k do not cancel), |M_C| times both;
//   the inertia's uncertainty delta_I in the gyroscopic term, |omega| x |I| |omega| delta_I per axis
//     (COMRADE's chaser turning at 2.5 deg/s: omega x I omega 0.65 N m, 20 % inertia errors ~0.3 N m);
//   the centre of mass's uncertainty delta_c under the commanded force, delta_c (|F_j| + |F_k|).
//
// Computation: the r0, v0 columns are projected out in closed form (per axis, a straight-line fit
// in t), so only 2 x 2 systems remain per hypothesis and onset: lanes x (onsets) of them per
// evaluation, a fraction of a millisecond for MSR's 8 lanes, done only after an alarm.
//
// Lanes: one hypothesis per thruster of the watched set, any set of 1..kMaxWatchedThrusters
// (MSR's 8, COMRADE's 24). The per-thruster arrays are stored at that capacity (no allocation:
// the sizes are compile-time) and every loop runs over the first `lanes`; the lanes are summed in
// the same order whatever the set's size, and a set of eight keeps the fixed-size products it had
// when the bank was eight lanes wide (build_window), so MSR's results keep their bits. The
// per-period cost without an alarm is storing one sample and updating sigma_0.
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "model/faults.hpp"
#include "model/fdi.hpp"
#include "flight/fdi/watched_set.hpp"

namespace chaser::flight::fdi {

inline constexpr int kMaxDeficitWindow = model::kMaxDeficitWindowPeriods;  // periods the sample ring holds

using DeficitMat3W = Eigen::Matrix<double, 3, kMaxWatchedThrusters>;  // columns [lanes, capacity) zero
using DeficitVecW = Eigen::Matrix<double, kMaxWatchedThrusters, 1>;

struct DeficitIsolationParams {
  Mat3 inertia_kgm2 = Mat3::Identity();        // [kg m^2] nominal, about the CoM, body axes
  double mass_kg = 1.0;                        // [kg] nominal wet mass at the start
  int lanes = 0;                               // [-] thrusters watched, 1..kMaxWatchedThrusters
  DeficitMat3W force_body_N = DeficitMat3W::Zero();    // [N] M_F, force per unit on-time, watched lanes
  DeficitMat3W torque_body_Nm = DeficitMat3W::Zero();  // [N m] M_C
  double period_s = 0.1;                       // [s] T
  int before = 20;        // [periods] the window starts this long before the alarm; onsets scanned there
  int after = 30;         // [periods] first decision this long after the alarm
  int max_window = 150;   // [periods] longest window while the decision is ambiguous
  int reevaluate_every = 2;   // [periods] between evaluations while ambiguous
  double lidar_sigma_m = 1e-3;           // [m] 1-sigma LIDAR noise per axis
  double gyro_sigma_radps = 1e-6;        // [rad/s] 1-sigma gyro noise: floor of sigma_0
  double pulse_uncertainty = 0.01;       // [-] epsilon
  double spill_fraction = 0.0;           // [-] tau_max / T, the longest drive delay in periods (sigma_model)
  double inertia_uncertainty = 0.0;      // [-] delta_I, relative error bound of the nominal inertia
  double com_uncertainty_m = 0.0;        // [m] delta_c, error bound of the nominal centre of mass per axis
  double noise_time_constant_s = 20.0;   // [s] of the sigma_0 estimate
  int noise_snapshot_periods = 100;      // [periods] between snapshots of it (the lag is 1-2 of these)
  double min_gain = 50.0;     // [-] gain the best hypothesis must reach to be named
  double min_margin = 25.0;   // [-] gain of the best over the second best
  // Materiality: the best hypothesis is named only if its deficit is a fault's, not a model error's
  // (a 20 % inertia error reads as b = -0.2 on the torque rows): a >= min_a or b <= -min_b.
  double min_a = 0.05, min_b = 0.3;
  double misfit_rescale_above = 3.0;  // [-] torque rows' chi-square per row at the best fit above which
                                      //     their weights are divided by it (evaluate_deficit_hypotheses)
  double prior_sigma = 10.0;  // [-] weak Gaussian prior on a and b: keeps b defined for a
                              //     thruster that is never commanded in the window
  // Reading (a, b) as a fault case: a above open_a: stuck open; a above leak_a: leak; otherwise
  // b below closed_b: stuck closed; otherwise thrust loss.
  double open_a = 0.6, leak_a = 0.05, closed_b = -0.95;
};

// Problems with the parameters (empty when valid), each naming the field.
std::vector<std::string> validate(const DeficitIsolationParams& params);

// Sets lanes, M_F and M_C from the watched set's configuration matrix (6 x lanes: force rows, then
// torque rows; 1..kMaxWatchedThrusters columns).
void set_deficit_columns(DeficitIsolationParams& params, const Eigen::Ref<const Eigen::Matrix<double, 6, Eigen::Dynamic>>& config);

// What the on-board software has in one period, stored for the fit.
struct DeficitSample {
  Vec3 omega_body_radps = Vec3::Zero();  // gyro
  Vec3 r_lvlh_m = Vec3::Zero();          // LIDAR
  Quat q_lvlh_from_body = Quat::Identity();  // estimated attitude
  double mass_kg = 1.0;                  // [kg] nominal mass less the measured propellant used
  // What the awake arm adds to the torque rows (flight/arm_reaction.hpp), zero without one: the
  // momentum it exchanged with the hub and its centre of mass's shift, body axes.
  Vec3 arm_momentum_Nms = Vec3::Zero();  // [N m s]
  Vec3 com_shift_m = Vec3::Zero();       // [m]
  // Last, so that a small set's lanes share cache lines with the fields above (MSR: a sample
  // written each period touches three lines, as when the ring held eight lanes).
  WatchedTon ton = WatchedTon::Zero(); // commanded on-times of the watched lanes, applied over this period
};

struct DeficitBankState {
  std::array<DeficitSample, kMaxDeficitWindow> ring{};
  std::int64_t count = 0;               // samples pushed; sample p lives in ring[p % size]
  int snapshot_phase = 0;               // count % noise_snapshot_periods (kept, not divided per period)
  Vec3 torque_mean_square = Vec3::Zero();  // [N^2 m^2] EW mean square of the fault-free torque rows
  // The same estimate as it was 1-2 snapshot intervals ago (infinite until then). The weights use
  // the smaller of the two, so the rows of a fault that has not yet raised an alarm (and so has
  // not frozen the estimate) cannot inflate sigma_0 and hide themselves for a whole window.
  Vec3 torque_mean_square_lagged = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 torque_mean_square_snapshot = Vec3::Constant(std::numeric_limits<double>::infinity());
  bool frozen = false;                  // sigma_0 stops adapting once an alarm is raised
  Vec3 noise_floor_sq = Vec3::Zero();   // [N^2 m^2] the gyro floor of sigma_0^2, set at the first sample
  Vec3 last_torque_row = Vec3::Zero();  // [N m] torque row of sample count - 2 (valid from count >= 2)
};

// This period's sample is written in place, into the slot next_deficit_sample gives, then
// push_deficit_sample stores it and, until frozen, updates the sigma_0 estimate with the torque row
// of the previous period. (In place: a sample built on the stack by field copies and read back by
// wider loads stalled on store forwarding.)
inline DeficitSample& next_deficit_sample(DeficitBankState& bank) {
  return bank.ring[static_cast<std::size_t>(bank.count % kMaxDeficitWindow)];
}
void push_deficit_sample(const DeficitIsolationParams& params, DeficitBankState& bank);
inline void push_deficit_sample(const DeficitIsolationParams& params, DeficitBankState& bank,
                                const DeficitSample& sample) {
  next_deficit_sample(bank) = sample;
  push_deficit_sample(params, bank);
}

// Every hypothesis fitted on samples [first, bank.count), onsets scanned over [first, last_onset].
struct DeficitHypotheses {
  DeficitVecW gain = DeficitVecW::Zero();   // [-] drop of the weighted RSS from the no-fault fit
  DeficitVecW a = DeficitVecW::Zero();      // [-] constant deficit at the best onset
  DeficitVecW b = DeficitVecW::Zero();      // [-] command-proportional deficit
  std::array<std::int64_t, kMaxWatchedThrusters> onset{};  // sample index of the best onset
  double rss_no_fault = 0;                  // [-] weighted RSS of the no-fault fit
  int rows = 0;                             // scalar rows in the fit
  double torque_scale = 1.0;                // [-] 1, or 1 / the torque rows' misfit when it was rescaled
};
DeficitHypotheses evaluate_deficit_hypotheses(const DeficitIsolationParams& params, const DeficitBankState& bank,
                                              std::int64_t first, std::int64_t last_onset);

struct DeficitDecision {
  bool decided = false;
  int thruster = -1;                       // lane of the watched set, -1: no hypothesis explains the alarm
  model::FaultKind kind = model::FaultKind::kStuckOpen;  // read from (a, b), valid with thruster >= 0
  double size = 0;                         // [-] leak a, loss -b (1 for stuck open / closed)
  double a = 0, b = 0;                     // [-]
  std::int64_t onset_sample = -1;          // estimated onset, sample index
  double gain = 0, margin = 0;             // [-] best gain and its lead over the second
};

// One scheme's use of the bank: triggered by that scheme's alarm.
struct DeficitDecisionState {
  std::int64_t alarm_sample = -1;   // sample index of the alarm that triggered it
  std::int64_t next_evaluation = -1;
  DeficitDecision decision;         // latched once decided
};

// Call after push_deficit_sample each period. alarm_sample: the sample index of the scheme's first
// alarm (-1 while none). Returns the decision (decided = false until made; latched after).
const DeficitDecision& step_deficit_decision(const DeficitIsolationParams& params, const DeficitBankState& bank,
                                             DeficitDecisionState& state, std::int64_t alarm_sample);

// Building blocks shared with the deficit detector (deficit_detector.hpp).
// The torque row of sample `now` (Euler's equation over the period to `next`, less the commanded torque).
Vec3 deficit_torque_row(const DeficitIsolationParams& params, const DeficitSample& now, const DeficitSample& next);
// sigma_0^2 per axis: the smaller of the live and the lagged estimate, never below the gyro floor.
Vec3 deficit_sigma0_sq(const DeficitBankState& bank);
// The on-times of the sample before `sample` while the ring holds it, else none (zeros): the
// previous command a row's delay spill reads.
const WatchedTon& deficit_commands_before(const DeficitBankState& bank, std::int64_t sample);
// sigma_model of the row of sample `now` (header, "Weights"), whose previous sample commanded
// `previous_ton`: zero when spill_fraction, inertia_uncertainty and com_uncertainty_m leave nothing.
Vec3 deficit_model_sigma(const DeficitIsolationParams& params, const DeficitSample& now, const WatchedTon& previous_ton);
// The row's weights per axis, 1 / ((sigma_0^2 + (epsilon |M_C| T_on)^2) + sigma_model^2) (header,
// "Weights"); where sigma_model is zero (MSR's approach) the same bits as without its term.
Vec3 deficit_torque_weights(const DeficitIsolationParams& params, const DeficitBankState& bank, const DeficitSample& now,
                            const WatchedTon& previous_ton);

// The normal equations of (a, b) for one hypothesis, and their solution with a >= 0, b <= 0.
struct DeficitNormal {
  double haa = 0, hab = 0, hbb = 0, ga = 0, gb = 0;
};
struct DeficitFit {
  double a = 0, b = 0, gain = 0;  // gain: 2 g'x - x'Hx at the optimum x = (a, b) (= g'x there), >= 0
};
DeficitFit fit_deficit(const DeficitNormal& normal);

// The normal equations of the hypotheses, row i for thruster i: [haa, hab, hbb, ga, gb].
// Column-major: each quantity of the lanes is contiguous, so they are fitted as whole columns.
using DeficitNormalsW = Eigen::Matrix<double, kMaxWatchedThrusters, 5>;
struct DeficitFits {
  DeficitVecW a = DeficitVecW::Zero(), b = DeficitVecW::Zero(), gain = DeficitVecW::Zero();
};
// fit_deficit of rows [0, lanes), in a loop the compiler vectorises (the same lane arithmetic, so
// the same answer bit for bit; tested). Entries from `lanes` on are not written.
DeficitFits fit_deficits(const DeficitNormalsW& normals, int lanes);

// The fault case and size (a, b) describe.
void classify_deficit(const DeficitIsolationParams& params, DeficitDecision& decision);

}  // namespace chaser::flight::fdi
