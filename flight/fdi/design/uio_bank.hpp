#pragma once
// A bank of discrete-time H-infinity unknown-input observers on the body-rate model, one per
// monitored thruster (COMRADE 2018, sec. 6.3): observer i cannot see thruster i's fault, so when
// thruster i fails its residual stays at its noise while the others' grow, and the smallest
// residual names the thruster (the paper's rule).
//
// The model is rate_model.hpp's reduced one, ZOH-discretised at the control period (the on-time
// fractions are held over a period; the gyro is sampled once per period):
//   x(k+1) = Ad x + Bd u + Ed d,   y = C x + v,
// d the torque the model leaves out (the liquid beyond its linear modes, the environment), per
// period; v the gyro's noise per sample. Thruster i's fault adds Bd e_i f(k) (any fault kind:
// stuck open, stuck closed, leak, loss all act along that column).
//
// Observer i, in Chen and Patton's form (Robust Model-Based Fault Diagnosis, 1999, sec. 3.2),
// discrete:
//   z(k+1) = N z + G u + L y,   x_hat = z + H y,   r = Q (y - C x_hat),
//   F = Bd e_i,  H = F (C F)^+,  T = I - H C,  G = T Bd,  A1 = T Ad,
//   N = A1 - K Q C,  L = K Q + N H,
// Q (2 x 3, orthonormal rows) the output directions orthogonal to C F. T F = 0, so the error
// eps = T x - z obeys eps(k+1) = N eps + T Ed d - (A1 H + K Q) v whatever f does: fault i is
// decoupled exactly. The existence condition is rank(C F) = rank(F) = 1: thruster i has a torque.
// The residual uses only Q's two directions because the third, along C F, is where the observer
// reads the unknown input: its innovation component there is zero by construction.
//
// The gain K is the central a-priori H-infinity filter's (Hassibi, Sayed and Kailath, Indefinite-
// Quadratic Estimation and Control, 1999, ch. 4) for the error above: with
//   w = [d / sigma_d; v / sigma_v],  Bw = [T Ed sigma_d, -A1 H sigma_v],  Dv = [0, sigma_v Q],
// (Bw Dv' = 0: H Q' = 0) and the performance output z = C eps (the rate estimate's error), P is
// the stabilising solution of
//   P = A1 P A1' + Bw Bw' - A1 P M' (Re)^-1 M P A1',   M = [Q C; C],   Re = diag(sigma_v^2 I, -g^2 I) + M P M',
// (SB02OD, control/discrete_riccati.hpp), K = A1 P C'Q' (sigma_v^2 I + Q C P C'Q')^-1, feasible when
// P >= 0, g^2 I - C P C' > 0 and N is stable. gamma_min is found by bisection, and the observer
// uses gamma = backoff x gamma_min (at gamma_min itself the gain is ill-conditioned). The bound is
// then checked independently: the error system's largest singular value over a frequency sweep
// (gamma_sweep <= gamma).
//
// Design time: allocates.
#include <string>
#include <vector>

#include "flight/fdi/design/rate_model.hpp"

namespace chaser::flight::fdi {

inline constexpr double kUioBlindTolerance = 1e-6;  // [-] relative fault gain below which an observer is blind

struct UioBankParams {
  double period_s = 0.1;                 // [s] the control period: the observers' sample time
  double gyro_noise_radps = 1e-6;        // [rad/s] 1 sigma per sample, each axis
  double disturbance_torque_Nm = 0.1;    // [N m] 1 sigma per period, each axis: what the model leaves out
  double gamma_backoff = 1.1;            // [-] gamma = backoff x gamma_min, > 1
  // The figures (gamma_sweep, residual_noise_rms, fault_gain, blind, closest, isolation_snr): the
  // sweep alone costs as much as the gains. The flight software designs without them.
  bool figures = true;
  // The per-thruster observers; without them, the nominal alone (what the supervisor's estimators
  // share, flight/fdi/mode_supervisor.hpp), and no figures.
  bool decoupled = true;
};

struct UioObserver {
  int thruster = 0;              // the column of B it is blind to; -1: the nominal observer
  Eigen::MatrixXd N, G, L, H;    // z(k+1) = N z + G u + L y,  x_hat = z + H y
  Eigen::MatrixXd Q;             // [2 x 3] residual r = Q (y - C x_hat); the nominal's: I (3 x 3)
  Eigen::MatrixXd K;             // [n x 2] gain on the projected innovation (n x 3: the nominal's)
  double gamma_min = 0;          // [-] smallest gamma the Riccati test admits (w normalised, z in rad/s)
  double gamma = 0;              // [-] the gamma designed for
  double gamma_sweep = 0;        // [-] the error system's H-infinity norm by frequency sweep
  double spectral_radius = 0;    // [-] of N
  double residual_noise_rms = 0;  // [rad/s] |r|'s rms from d and v (steady-state covariance)
};

struct UioBank {
  Eigen::MatrixXd Ad, Bd, Ed, C;       // the discretised reduced rate model
  UioObserver nominal;                 // blind to none (H = 0, Q = I): what detects a fault
  std::vector<UioObserver> observers;  // one per thruster, by thruster
  // [observer][thruster]: |r| at steady state [rad/s] per unit constant on-time of that
  // thruster's fault; zero on the diagonal (decoupled). Thrusters whose torques are parallel
  // (on COMRADE's corners: same torque, opposite force) differ only by what their force does to
  // the liquid, and read small off the diagonal.
  Eigen::MatrixXd fault_gain;
  // Per thruster j: the other observers blind to its fault at steady state (fault gain below
  // kUioBlindTolerance of observer j's largest), and, among the rest, the one least moved by it
  // and its steady residual per unit on-time over its noise rms. The rates alone cannot tell j from
  // the thrusters whose observers are blind to it: the smallest residual names the group.
  std::vector<std::vector<int>> blind;
  std::vector<int> closest;
  std::vector<double> isolation_snr;  // [-]
};

// Throws std::invalid_argument naming the parameter when one is out of range, and when a
// thruster has no torque (no observer can decouple it from the rates).
UioBank design_uio_bank(const RateModel& model, const UioBankParams& params);

// The scenario's bank: its rate model, control period and gyro noise.
UioBankParams uio_bank_params(const model::Scenario& scenario);
UioBank design_uio_bank(const model::Scenario& scenario, bool figures = true);

// The observer's error system for the sweep: state eps, input w (normalised d then v), output
// C eps; discrete at params.period_s. Largest singular value over theta in [0, pi], on a grid
// refined around its peak.
double discrete_hinf_norm(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& C,
                          const Eigen::MatrixXd& D);

}  // namespace chaser::flight::fdi
