#pragma once
// The active checks read from the body rates: the `rate_check` diagnosis scheme (docs/fdi.md,
// "Checks read from the rates").
//
// An active check (flight/active_check.hpp) fires one thruster j for a short pulse that the others
// cancel: the commanded wrench is unchanged, so a dead or weakened j shows only in the period of
// its pulse, too small for a statistic over many seconds (22 N x 1.3 m x 7.5 ms = 0.2 N m s against
// a turning hold's slosh and gyroscopic errors). Over one period k the gyro's rate change is Euler's
// equation with the commanded torque tau_k (M ton) held through the period:
//
//   e_k = omega_{k+1} - omega_k - T I^-1 (tau_k - omega_k x I omega_k).
//
// A thruster that gives 1 - m of its commanded on-time f_j leaves e_k = -m u_j plus what the model
// leaves out, u_j = T I^-1 tau_j f_j its pulse's rate change (tau_j its torque at full thrust). What
// the model leaves out (the slosh's torque, the gyroscopic term's inertia error, the gravity
// gradient) changes slowly against one period: the residual's baseline is its median, axis by axis,
// over the n periods either side that carry no check of their own (another check's pulse carries
// its thruster's deficit; a dead thruster checked again and again would fill the window with its
// own). Fewer than n such periods leave the reading inconclusive. The baseline also holds the
// deficit of what j fires in those periods (a dead thruster the controller fires every period is in
// every residual), so f_j is the check period's on-time beyond j's median over them. The reading is
// m's least-squares value on the pulse's direction,
//
//   m_k = -(u_j . (e_k - median e_neighbours)) / (u_j . u_j).
//
// 0 reads a healthy thruster, 1 one that gave nothing.
//
// What the median cannot remove is what changes from one period to the next: the commanded torque's
// change against its neighbours times the inertia's error (delta_I, fdi.deficit.inertia_uncertainty),
// and the impulse a long on-time spills into the next period when the valves open late (at most
// delay_max + rise / 2 after the period's start: a thruster on for f T spills up to
// f T + shift_max - T of its torque, out of period k and into k + 1). Their bound, on the pulse's
// direction,
//
//   B_k = ( delta_I |T I^-1 (tau_k - mean tau_neighbours)| + |I^-1| (S_{k-1} + S_k) ) / |u_j|,
//
// S the spilled torque impulses' bound, plus a step in what the model leaves out inside the window
// (a leak's onset, a slosh strike: the baseline takes one side's level, the pulse may sit on the
// other), the difference between the medians of the quiet neighbours' readings before and after the
// pulse, says how far the reading can be off on a healthy thruster.
// A reading decides only where it is clear of the threshold by its bound: m_k - B_k >= threshold
// reads a deficit, m_k + B_k < threshold a healthy thruster. One that straddles the threshold, whose
// B_k exceeds max_uncertainty (the reading is then no measure of a loss's size), or that lies
// outside [-0.5, 1.5], which no deficit of the pulse gives (the residual then holds more: a fault of
// a thruster the controller keeps firing), is inconclusive: it changes no suspicion, and the
// thruster is checked again at once (in a turning flight's busiest periods a check may take a few
// tries).
//
// Whose deficit: the check's period holds more than its pulse. The allocation cancels the pulse with
// other thrusters, firing some more and cutting what the controller fires against the pulse; a dead
// or weakened one among them leaves its deficit's share of that change in this period only, on a
// direction that may lean on the pulse's. Every other thruster i whose on-time the period changes
// against its neighbours' median is a hypothesis too: its fit m_i = -(u_i . e_k) / (u_i . u_i), u_i
// the change's rate change (negative for a cut), kept when threshold <= m_i <= 1.5 (a deficit, up
// to a stuck-closed reading's spread) and when it explains at least the threshold's share of the
// pulse, |m_i u_i| >= threshold |u_j|. Each leaves the residual
// |e_k + m u| of its fit; a margin of half the threshold's share of the pulse, threshold |u_j| / 2,
// separates two fits:
//   - another thruster that leaves less than the checked one by more than the margin takes the
//     reading: it is checked next (its own check decides; another's reading never confirms);
//   - one within the margin of a suspicious reading is its rival (rates see torques only: two
//     thrusters with the same torque read alike): the rival is checked first, and the reading counts
//     towards the checked thruster's confirmation only once no rival is left unchecked. Two rivals
//     are not checked first: the suspect (another's reading does not displace it: the suspect is
//     checked again), and a rival the period cut, whose deficit is a valve that did not close (a
//     leak, stuck open: it leaves what the cut should have taken away), which its own pulse cannot
//     show as its valve opens: the reading decides nothing, and the checked thruster is checked
//     again.
// The thrusters whose own check has been read since the suspicion began are no hypothesis for
// another's reading, rivals included, but for the suspect itself: the chain of rechecks ends.
//
// Decision: a conclusive reading of at least `threshold` makes j the suspect and asks for its check
// again at once (`recheck`, the active check's suspect; never while a later check of it is still to
// be read, so that one thruster's checks stay n + 2 periods apart); `confirmations` unrivalled
// readings of j in a row at least the threshold confirm the fault, stuck closed where their mean is
// at least stuck_closed_from, else a loss of that size; a reading of the suspect below the threshold
// lets the suspicion go. The alarm is the confirmation: one reading is never an alarm.
//
// A pulse also goes missing when the valve is open already: a leak of size L (or a stuck-open
// valve) gives j's torque L tau_j uncommanded in every period, which the baseline holds. Its share
// on j's full thrust, open = (T I^-1 tau_j) . median / |T I^-1 tau_j|^2, reads L; where the
// confirming readings' mean open share is at least 0.08 (twice the largest a fault-free
// comrade_sync flight gives, 0.038 over 1,526 checks; below the campaigns' smallest leak, 0.1), the
// fault is a leak of that size (stuck open from stuck_closed_from), whose thrust the recovery cancels.
#include <array>
#include <cstdint>
#include <limits>

#include <Eigen/Core>

#include "core/types.hpp"
#include "flight/fdi/watched_set.hpp"
#include "model/faults.hpp"
#include "model/fdi.hpp"
#include "model/thrusters.hpp"

namespace chaser::flight::fdi {

struct RateCheckParams {
  double period_s = 0.1;                                     // [s] T
  Eigen::Matrix3d inertia_kgm2 = Eigen::Matrix3d::Identity();   // [kg m^2] nominal, body axes
  Eigen::Matrix3d inverse_inertia = Eigen::Matrix3d::Identity();  // [1/(kg m^2)]
  double inverse_inertia_norm = 1;  // [1/(kg m^2)] its largest singular value
  std::array<Vec3, model::kMaxThrusters> torque_Nm{};       // [N m] each thruster's at full thrust, about the CoM
  std::array<double, model::kMaxThrusters> torque_norm_Nm{};  // [N m] their norms
  int neighbours = 5;            // n: periods either side
  double threshold = 0.25;       // [-]
  int confirmations = 3;
  double stuck_closed_from = 0.8;  // [-]
  double max_uncertainty = 0.1;    // [-] B_k above which a reading is inconclusive
  double inertia_uncertainty = 0;  // [-] delta_I
  double shift_max_s = 0;          // [s] latest valve opening after the period's start: delay_max + rise / 2
};

// The parameters for a thruster set (nominal geometry about com_body_m) and the scenario's keys.
RateCheckParams make_rate_check_params(const model::RateCheckParams& keys, const model::ThrusterSetParams& thrusters,
                                       const Vec3& com_body_m, const Eigen::Matrix3d& inertia_kgm2, double period_s,
                                       double inertia_uncertainty);

// S_k: the torque impulse [N m s] the period's on-times can spill into the next, at most.
double spill_bound_Nms(const RateCheckParams& params, const WatchedSet& set, const WatchedTon& ton);

inline constexpr int kRateCheckRing = 2 * model::kMaxRateCheckNeighbours + 2;

// Rechecks come at most one in this many periods: readings left inconclusive in a busy stretch ask
// for more checks, and checks in every period would leave no quiet neighbour for any reading's
// baseline. One in three leaves two thirds of a window quiet, above the n of 2n a reading needs
// (routine checks, one per thruster per active_check.max_unverified_s, are far fewer).
inline constexpr std::int64_t kRecheckSpacing = 3;

struct RateCheckPeriod {
  Vec3 omega_radps = Vec3::Zero();     // measured at the period's start
  Vec3 torque_Nm = Vec3::Zero();       // commanded through it
  Vec3 residual_radps = Vec3::Zero();  // e_k, once the next period's rate is in
  int checked = model::kNoThruster;    // the thruster a check pulsed in it
  double spill_Nms = 0;                // S_k [N m s]
  std::array<double, model::kMaxThrusters> on_fraction_all{};  // [-] every thruster's commanded on-time
};

struct RateCheckState {
  std::array<RateCheckPeriod, kRateCheckRing> ring{};
  std::int64_t periods = 0;             // periods pushed
  double last_reading = std::numeric_limits<double>::quiet_NaN();  // [-] the latest reading, of any thruster
  int suspect = model::kNoThruster;
  int in_a_row = 0;                     // the suspect's readings in a row at least the threshold
  double sum = 0;                       // [-] and their sum
  double open_sum = 0;                  // [-] and the sum of their open shares
  double suspect_pulse_s = -1;          // [s] the first of them's pulse: the latest the fault can have begun
  model::ThrusterMask read_since = 0;   // thrusters whose own check was read since the suspicion began
  int recheck = model::kNoThruster;     // the thruster to check again, until its pulse is fired
  std::int64_t last_any_pulse = -kRecheckSpacing;  // the latest check of any thruster (period)
  // each thruster's latest check (period, -1: none): one check of a thruster in flight at a time
  std::array<std::int64_t, model::kMaxThrusters> last_pulse = [] {
    std::array<std::int64_t, model::kMaxThrusters> none{};
    none.fill(-1);
    return none;
  }();
  int confirmed = model::kNoThruster;   // latched
  double confirmed_s = -1;              // [s] when, -1: not
  // with confirmed: stuck closed or a loss, or where the valve is open already a leak or stuck open
  model::FaultKind kind = model::FaultKind::kStuckClosed;
  double size = 0;  // [-] the confirming readings' mean (a loss), or their open shares' (a leak)
};

struct RateCheckInput {
  double t_s = 0;                        // [s] this period (its start)
  Vec3 omega_body_radps = Vec3::Zero();  // the gyro at the period's start
  Vec3 torque_cmd_body_Nm = Vec3::Zero();  // the period's commanded torque (M ton)
  int checked = model::kNoThruster;      // the thruster whose check this period's command carries
  double spill_Nms = 0;                  // S_k (spill_bound_Nms) [N m s]
  std::array<double, model::kMaxThrusters> on_fraction{};  // [-] every thruster's commanded on-time, the check's included
};

// What a period read: the thruster whose check was read (kNoThruster: none), its reading and the
// reading's bound on a healthy thruster; another thruster commanded in the period that explains the
// residual better (`culprit`, with its fit) or as well (`rival`).
struct RateCheckReading {
  int thruster = model::kNoThruster;
  double missing = 0;      // [-] m_k less the neighbours' median
  double uncertainty = 0;  // [-] B_k
  int culprit = model::kNoThruster;
  double culprit_missing = 0;  // [-] its m_i
  // [-] the checked thruster's on-time the baseline holds uncommanded, on its full thrust's rate
  // change: a leak of size L reads L (the pulse then adds nothing and reads as missing)
  double open_share = 0;
  int rival = model::kNoThruster;
  bool rival_cut = false;  // the rival's on-time was cut in the period (its deficit: a valve that did not close)
};

// The thruster to check in the next period (kNoThruster: none now): `recheck`, once the latest check
// of any thruster is kRecheckSpacing periods back.
int next_recheck(const RateCheckState& state);

// One period: records it, completes the residual of the one before, reads the check n + 1 periods
// back when there was one, and decides.
RateCheckReading step_rate_check(const RateCheckParams& params, RateCheckState& state, const RateCheckInput& in);

// The reading of the check in period k (of the state's count), once the residuals of its n
// neighbours either side are in (k + n + 2 <= state.periods, k >= n); thruster kNoThruster without a
// check in k; missing NaN and uncertainty infinite where the check cannot be read (fewer than n quiet
// neighbours, or a check that fired its thruster no more than the neighbours did).
// Thrusters in `excluded` are no hypothesis for the residual besides the checked one.
RateCheckReading read_check(const RateCheckParams& params, const RateCheckState& state, std::int64_t k,
                            model::ThrusterMask excluded = 0);

}  // namespace chaser::flight::fdi
