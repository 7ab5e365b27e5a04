#pragma once
// The observer bank in flight (COMRADE 2018, sec. 6.3; the design: flight/fdi/design/uio_bank.hpp):
// every period each observer takes the gyro's rates, the thrusters' commanded on-times and the
// gyroscopic torque it can compute from the rates, and gives its residual. The residuals are summed
// in blocks of about a second, and every block each one's statistic is the change of its mean over
// the last W seconds against the L seconds before (the impulse statistic's change, impulse_detector.hpp):
//   d = mean over the last W of r  -  mean over the L before of r.
// A fault's residual is a step that lasts; what is steady cancels. That matters in the turning hold:
// the chaser thrusts ~20 N without pause to circle the target, and under that acceleration the
// liquid sits far from where the rate model, linearised at rest, puts it (its spring-mass holds
// the liquid at g_eff = 0.005 m/s^2; the hold's specific force is about three times that). The
// nominal observer's mean residual then settles at ~3e-4 rad/s, as much as a weak fault's, while
// its change stays near 1e-5.
//
// Detection: the nominal observer (blind to no thruster) alarms when its d, as the torque that makes
// it (tau = I d / T, body axes), exceeds what the model's errors can make of the commanded wrench's
// change by more than the threshold on some axis: per axis a (j, k the other two)
//   bound_a = delta_c (|dF_j| + |dF_k|) + delta_I |dtau_a|,
// dF and dtau the same change of the commanded force and of the torque the bank knows (commanded
// plus gyroscopic), delta_c and delta_I the centre of mass's and the inertia's error bounds
// (fdi.deficit.com_uncertainty_m, inertia_uncertainty): the impulse statistic's bound. Without it
// the transfer into the hold, 40 N of force change on a centre of mass up to 3 cm off, read 2 N m.
// The alarm latches.
//
// Isolation, after the alarm (the paper's rule, with what the rates alone can say): an observer
// whose |d| stays below isolation_ratio x the nominal's is blind to the fault, so its
// thruster, or one whose torque is parallel to it, is the faulty one. Each blind thruster is a
// hypothesis with a sign: the nominal's d along its torque direction says whether it
// gives too much (stuck open, leak) or too little (stuck closed, loss); too little needs the
// thruster to have been commanded in the window. The hypotheses left form the bank's verdict.
// The rates cannot tell apart two thrusters with the same torque and different forces (on a box
// layout, every thruster and the one at the diagonally opposite corner on its axis): when two or
// more hypotheses remain, the bank names no thruster by itself (fdir.cpp then asks the deficit
// bank, which reads the forces too, and accepts its name only if it is one of the hypotheses).
// A single hypothesis held for confirm_blocks blocks is confirmed.
//
// Allocation: the parameters are sized when made (make_observer_bank), the state once, in the
// bank's first period (make_observer_bank_state); a period allocates nothing after that. Cost per
// period: n^2 + 8 n + 6 multiply-adds per observer (n = 9: 159; the nominal's a few more) plus the
// commands' n x m product once.
#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/types.hpp"
#include "flight/fdi/watched_set.hpp"
#include "model/thrusters.hpp"

namespace chaser::flight::fdi {

struct UioBank;

// z(k+1) = N z + T (Bd u + Ed tau) + L y, x_hat = z + H y, r = Q (y - C x_hat); T = I - H C. In
// flight, rearranged into one product each with v = [z; y; C known]:
//   r = [-Q C, Q (I - C H)] v_(n+3),   z(k+1) = [N, L, -H] v + known,   known = Bd u + Ed tau.
struct ObserverBankObserver {
  Eigen::MatrixXd update;    // n x (n + 6): [N, L, -H]
  Eigen::MatrixXd residual;  // q x (n + 3): [-Q C, Q (I - C H)] (q = 3 for the nominal, 2 for the others)
  Eigen::Vector3d torque_direction = Eigen::Vector3d::Zero();  // unit C F: its thruster's rate direction
};

struct ObserverBankFlightParams {
  int n = 0;        // model order
  int columns = 0;  // thrusters the model has (the scenario's starting active set)
  std::array<int, model::kMaxThrusters> column_of{};  // thruster index -> column, -1: not in the model
  std::vector<int> thruster_of;                       // column -> thruster index
  Eigen::MatrixXd Bd, Ed, C;                          // the discretised model's inputs and output
  ObserverBankObserver nominal;
  std::vector<ObserverBankObserver> observers;        // by column
  Eigen::Matrix3d inertia_kgm2 = Eigen::Matrix3d::Identity();  // for the gyroscopic torque -omega x I omega
  int block = 10;                 // [periods] per block
  int window_blocks = 20;         // [blocks] W
  int baseline_blocks = 100;      // [blocks] L
  double threshold_Nm = 1.0;      // [N m] on the nominal's largest excess over the bound
  double period_s = 0.1;          // [s] T
  double com_uncertainty_m = 0.0;     // [m] delta_c
  double inertia_uncertainty = 0.0;   // [-] delta_I
  double isolation_ratio = 0.2;   // [-]
  int confirm_blocks = 3;         // [blocks]
  double min_commanded = 1e-3;    // [-] mean on-time over W below which a thruster was not commanded
};

struct ObserverBankState {
  bool started = false;
  std::vector<Eigen::VectorXd> z;  // [0] nominal, [1 + column]
  // Rows, per period: the nominal's residual (3), each observer's (2), each column's on-time, the
  // commanded force (3) and the known torque (3); summed
  // into `block` and then into the ring of the last W + L blocks (oldest first from `head`).
  Eigen::MatrixXd ring;
  Eigen::VectorXd row, block, window_sum, baseline_sum;
  Eigen::VectorXd u, known, v;  // scratch, sized once: u, Bd u + Ed tau, [z; y; C known]
  int in_block = 0;          // periods in `block`
  int head = 0, filled = 0;  // the ring's oldest block and how many it holds
  std::int64_t period = 0;   // periods stepped in this watch
  // Verdict.
  bool alarm = false;
  std::int64_t alarm_period = -1;  // in this watch's periods
  double statistic_Nm = 0;           // [N m] the nominal's largest excess over the bound at the last block
  double nominal_change_radps = 0;   // [rad/s] the nominal's |d| at the last block
  double smallest_change_radps = 0;  // [rad/s] the smallest observer's
  model::ThrusterMask hypotheses = 0;  // thruster indices the rates leave possible
  int candidate = -1;              // thruster index, -1: none
  int streak = 0;
  int confirmed = -1;              // thruster index, latched
};

// The flight parameters from a design; column_thruster: the thruster index of each model column.
// Throws std::invalid_argument when a block count is < 1, the threshold <= 0, the ratio outside
// (0, 1) or an uncertainty negative.
struct ObserverBankWindows {
  int block = 10, window_blocks = 20, baseline_blocks = 100;  // [periods], [blocks], [blocks]
  double threshold_Nm = 1.0, isolation_ratio = 0.2;           // [N m], [-]
  double period_s = 0.1, com_uncertainty_m = 0.0, inertia_uncertainty = 0.0;  // [s], [m], [-]
};
ObserverBankFlightParams make_observer_bank(const UioBank& design, const std::vector<int>& column_thruster,
                                            const Eigen::Matrix3d& inertia_kgm2, const ObserverBankWindows& windows);

// Sizes the state for the parameters; the observers start from the first rates they see.
ObserverBankState make_observer_bank_state(const ObserverBankFlightParams& params);

// A new watch: the windows and the verdict restart; the observers' states run on.
void restart_observer_bank(ObserverBankState& state);

// One period: the gyro's rates, the on-times of the watched lanes (lane -> thruster by `set`) and
// the commanded wrench they make (body axes, [N; N m]).
void step_observer_bank(const ObserverBankFlightParams& params, ObserverBankState& state, const Vec3& omega_body_radps,
                        const WatchedSet& set, const WatchedTon& lanes, const Vec6& commanded_wrench);

}  // namespace chaser::flight::fdi
