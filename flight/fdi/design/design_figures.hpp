#pragma once
// Figures of merit of a residual generator design (Fonod 2015, eqs. 30-32): checked a posteriori,
// since the eigenstructure design has no sensitivity constraint.
//
// The error e = x - x_hat of the observer of eq. 30 obeys e(k+1) = A_c e(k) + E_f_bar f(k) + E d(k)
// with A_c = A_bar - L C, and r = Q C e, so every transfer is R(z) X with
// R(z) = Q C (zI - A_c)^{-1}, z = e^{j 2 pi f T} (eq. 31-32). Gains are 2-norms over the residual
// components (the absolute value when n_r = 1), in residual units per unit input:
//   - unknown input: sigma_max(R(z) E_d) for the full E_d of eq. 28 and for E_d* of eq. 39;
//   - delay: an observer that assumes no delay sees the mismatch Gamma_1(delta) (u(k-1) - u(k))
//     (eq. 21), i.e. Gamma_1(delta) (z^-1 - 1) u(z): the gain from the command u_c to r is
//     sigma_max(R(z) Gamma_1(delta)) |1 - z^-1| for a constant delay, worst over sampled delays.
//     The difference of commands vanishes at DC, a persistent fault does not;
//   - fault: |R(z) E_f_bar e_i| for each fault direction i (per unit on-time of thruster i);
//   - command of thruster i through the delay: |R(z) Gamma_1(delta) F_i| |1 - z^-1|, worst over
//     delays and frequencies (needs the fault directions F in input space).
#include <Eigen/Core>
#include <complex>
#include <vector>

namespace chaser::flight::fdi {

struct FigureOptions {
  int frequency_points = 201;  // frequencies from DC to Nyquist 1 / (2T), evenly spaced
  int delay_points = 11;       // delays from delta_min to delta_max, evenly spaced
};

// What the figures are computed from.
struct ObserverUnderTest {
  Eigen::MatrixXd A_bar;      // [n_x x n_x]
  Eigen::MatrixXd C;          // [n_y x n_x]
  Eigen::MatrixXd L;          // [n_x x n_y]
  Eigen::MatrixXd Q;          // [n_r x n_y]
  Eigen::MatrixXd E_d;        // [n_x x N] eq. 28
  Eigen::MatrixXd E_d_star;   // [n_x x N] eq. 39
  Eigen::MatrixXd E_f_bar;    // [n_x x n_f] int_0^T e^{At} dt E_f
  std::vector<Eigen::MatrixXd> gamma1_samples;  // Gamma_1(delta_j), [n_x x n_u] each
  Eigen::MatrixXd fault_inputs;  // [n_u x n_f] fault directions in input space (may be empty)
  double period_s = 0.1;      // [s] T
};

struct DesignFigures {
  std::vector<std::complex<double>> achieved_eigenvalues;  // of A_bar - L C, sorted
  std::vector<double> frequency_hz;     // [Hz] the grid
  Eigen::VectorXd unknown_input_gain;   // sigma_max(R E_d) per frequency
  Eigen::VectorXd designed_input_gain;  // sigma_max(R E_d*) per frequency
  Eigen::VectorXd delay_gain;           // max over delta of sigma_max(R Gamma_1) |1 - z^-1| per frequency
  Eigen::MatrixXd fault_gain;           // [n_freq x n_f] |R E_f_bar e_i|
  Eigen::VectorXd fault_gain_dc;        // [n_f] the DC row of fault_gain
  Eigen::VectorXd command_delay_gain_max;      // [n_f] max over delta, f of |R Gamma_1 F_i| |1 - z^-1|
  double unknown_input_gain_max = 0.0;
  double designed_input_gain_max = 0.0;
  double delay_gain_max = 0.0;
};

// R(z) = Q C (zI - A_c)^{-1}, [n_r x n_x] complex.
Eigen::MatrixXcd residual_resolvent(const Eigen::MatrixXd& A_c, const Eigen::MatrixXd& QC,
                                    std::complex<double> z);

// |Q C (I - A_c)^{-1} E_f_bar e_i| for each column: the DC gain from a constant fault to r.
Eigen::VectorXd dc_fault_gains(const Eigen::MatrixXd& A_c, const Eigen::MatrixXd& QC,
                               const Eigen::MatrixXd& E_f_bar);

DesignFigures compute_design_figures(const ObserverUnderTest& observer,
                                     const FigureOptions& options = {});

}  // namespace chaser::flight::fdi
