#pragma once
// The multi-estimator supervisor of COMRADE 2018 (sec. 6.3, Fig. 14; its ref. 30: Efimov, Cieslak
// and Henry, Int. J. Adapt. Control Signal Process. 27(4), 2013): one estimator per functioning mode,
// one monitoring signal per estimator, and a switching signal sigma(t), with a dwell time and a
// hysteresis, that names the mode the accommodation flies (flight/flight_software.cpp gives each
// mode its allocation: the virtual actuator, docs/fdi.md).
//
// Modes: 0 nominal, then for each monitored thruster j, in the order given, "j stuck open" (1 + 2i)
// and "j stuck closed" (2 + 2i): 2N + 1 modes, 9 for the paper's T1, T5, T13, T17.
//
// Estimators. Mode m's is the rate model's nominal observer (flight/fdi/design/uio_bank.hpp: blind
// to no thruster, H = 0, Q = I) fed with mode m's input: the commanded on-times with thruster j's
// replaced by 1 (stuck open) or 0 (stuck closed), the paper's multiplicative stuck faults. In its
// own mode's plant each estimator's error obeys the nominal's error equation whatever is commanded,
// so the H-infinity design of every matched estimator is the nominal's, and so is its gain: the
// paper's nine gains L_1..L_9 are one gain here. The estimators are linear in their input, so
// estimator m is the nominal plus a correction driven by the one input it changes:
//   delta_m(k+1) = N delta_m + G e_j (u_m,j - u_j),   r_m = r_0 - C delta_m   (G = Bd, Q = I).
//
// Monitoring signals: the residual's energy with forgetting (Hespanha and Morse's),
//   mu_m(k+1) = a mu_m + (1 - a) |r_m - b|^2,   a = exp(-T / forgetting_s),
// less b, the residual that every estimator shares in fault-free flight. Under the hold's steady
// thrust the liquid sits far from where the model, linearised at rest, puts it, and the nominal's
// residual settles at ~3e-4 rad/s, as large as a weak fault's (observer_bank.hpp). b is the flown
// mode's residual low-passed over bias_s, far slower than a stuck thruster's few seconds.
//
// Switching: nothing before settle_s (the estimators start from the first rates and the bias from
// the first residual); then, once dwell_s has passed since the last switch, sigma goes to the mode
// k with the smallest mu if
//   (1 + hysteresis) mu_k + floor^2 < mu_sigma,
// the relative hysteresis against the noise's share, the floor [rad/s] against the monitoring
// signals' fault-free spread. A mode whose hypothesis the commands do not excite (stuck closed of a
// thruster that is not fired) has the nominal's mu, so the hysteresis keeps sigma: modes the data
// cannot separate do not alternate. Thrusters whose torques are parallel (on COMRADE's box layout,
// the same torque with the opposite force) are such modes for the rates whatever is fired: monitor
// one of each pair, or expect the lower-numbered mode of a tie.
//
// Allocation: sized when made; a period allocates nothing. Cost per period: the nominal observer
// (n^2 + 6 n + 3 n multiply-adds, n = 9) and n^2 + 4 n per mode.
#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/types.hpp"
#include "model/thrusters.hpp"

namespace chaser::flight::fdi {

struct UioBank;

enum class SupervisorFault { kNone, kStuckOpen, kStuckClosed };
const char* to_string(SupervisorFault fault);  // "none", "stuck_open", "stuck_closed"

struct SupervisorMode {
  int thruster = model::kNoThruster;  // index; kNoThruster: the nominal mode
  int column = -1;                    // its column of the rate model's inputs
  SupervisorFault fault = SupervisorFault::kNone;
  double on_fraction = 0;             // [-] the on-time the mode says the thruster gives: 1 or 0
};

struct SupervisorKeys {
  double period_s = 0.1;       // [s] T
  double forgetting_s = 2.0;   // [s] the monitoring signals' memory
  double bias_s = 100.0;       // [s] the shared residual's low-pass
  double settle_s = 100.0;     // [s] no switch before
  double dwell_s = 5.0;        // [s] between two switches
  double hysteresis = 1.0;     // [-] relative
  double floor_radps = 1e-4;   // [rad/s] absolute
};

struct SupervisorParams {
  int n = 0;                          // the estimators' order
  Eigen::MatrixXd Bd, Ed, C;          // the discretised rate model's inputs and output
  Eigen::MatrixXd update;             // [N, L] (n x (n + 3)): z(k+1) = N z + L y + Bd u + Ed tau
  Eigen::MatrixXd N;                  // n x n
  std::array<int, model::kMaxThrusters> column_of{};  // thruster index -> model column, -1: none
  std::vector<SupervisorMode> modes;  // [0] nominal
  Eigen::Matrix3d inertia_kgm2 = Eigen::Matrix3d::Identity();  // for the gyroscopic torque -omega x I omega
  double forget = 0, bias_forget = 0;  // [-] a per period
  std::int64_t settle_periods = 0, dwell_periods = 0;
  double hysteresis = 1.0;
  double floor_sq = 0;  // [(rad/s)^2]
};

inline constexpr int kMaxSupervisorSwitches = 16;  // switches a run's summary lists

struct SupervisorSwitch {
  double t_s = 0;  // [s]
  int mode = 0;    // the mode switched to
};

struct SupervisorState {
  bool started = false;
  Eigen::VectorXd z;                    // the nominal estimator
  Eigen::MatrixXd delta;                // n x modes: each mode's correction (column 0 unused)
  Eigen::VectorXd mu;                   // [(rad/s)^2] per mode
  Eigen::VectorXd u, known, v, next;    // scratch: on-times by column, Bd u + Ed tau, [z; y], N delta
  Eigen::Vector3d bias = Eigen::Vector3d::Zero();  // [rad/s] b
  std::int64_t period = 0;
  std::int64_t last_switch_period = 0;
  int mode = 0;                         // sigma
  int switches = 0;
  std::array<SupervisorSwitch, kMaxSupervisorSwitches> log{};  // the first switches
};

// The estimators from the nominal observer of a design (design.nominal), the monitored thrusters
// (indices) and the model's column -> thruster map. Throws std::invalid_argument when a monitored
// thruster has no column, appears twice, or a key is out of range (times > 0, hysteresis >= 0,
// floor >= 0).
SupervisorParams make_supervisor(const UioBank& design, const std::vector<int>& column_thruster,
                                 const std::vector<int>& monitored, const Eigen::Matrix3d& inertia_kgm2,
                                 const SupervisorKeys& keys);

SupervisorState make_supervisor_state(const SupervisorParams& params);

// One period at t_s: the gyro's rates and the on-times every thruster was commanded this period (by
// index). Returns true when sigma changed.
bool step_supervisor(const SupervisorParams& params, SupervisorState& state, double t_s, const Vec3& omega_body_radps,
                     const model::ThrusterOnTimes& on_times);

}  // namespace chaser::flight::fdi
