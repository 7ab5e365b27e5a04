#pragma once
// Robust stability of one designed axis by the structured singular value: the gain and delay of
// its robustness box (control/robustness.hpp) pulled out as an uncertainty block Delta, and
// AB13MD's upper bound on mu of the interconnection M(j w) over a frequency grid.
//
// The LFT (S&P, "Multivariable Feedback Control", 2nd ed., sec. 8.6 and 8.8; multiplicative input
// uncertainty). The true plant is G(s) = k e^{-s tau} / s^2 (the modes are left to the grid check,
// robust_stability_grid). Centre both ranges:
//
//   k = k0 (1 + r_k delta_k),                  k0 = (k_lo + k_hi) / 2,  r_k = (k_hi - k_lo) / (k_hi + k_lo),
//   e^{-s tau} = e^{-s tau0} (1 + w_tau delta_tau),  tau0 = (tau_lo + tau_hi) / 2,  Delta_tau = (tau_hi - tau_lo) / 2,
//
// with delta_k in [-1, 1] (real; a complex disk for the complex bound) and |delta_tau| <= 1 complex.
// At each frequency {e^{-j w d} - 1 : |d| <= Delta_tau} lies in the disk of radius
//
//   w_tau(w) = 2 sin(min(w Delta_tau / 2, pi / 2))           (delay_weight)
//
// (the chord of the arc), so the delay is covered, conservatively, by a complex scalar. With
// L0 = k0 K(s) e^{-s tau0} / s^2 (negative feedback), S = 1 / (1 + L0), T = L0 S, and Delta =
// diag(delta_tau, delta_k) closing z = M w through w = Delta z,
//
//   M = [ -w_tau T   -w_tau T ]       det(I - M Delta) = 1 + T (r_k delta_k + w_tau delta_tau
//       [  r_k S     -r_k T   ]                                  + r_k w_tau delta_k delta_tau)
//                                                             = (1 + L) / (1 + L0)  (tested),
//
// L the perturbed loop. If the nominal loop (k0, tau0) is stable and mu(M(j w)) < 1 / alpha at every
// w, the loop is stable for every k in k0 (1 +- alpha r_k) and every delay in tau0 +- alpha Delta_tau:
// the gain block scales linearly, and the disk alpha w_tau(w) covers the arc of alpha Delta_tau
// (sin(alpha x) <= alpha sin x for alpha >= 1 on [0, pi/2]; radius 2 beyond). So the margin
// 1 / peak mu is the factor by which the box can grow. Two bounds:
//  - complex: both blocks complex. The classic bound; for the real gain it lets k be complex,
//    k0 (1 + r_k delta) with |delta| <= 1, and is conservative for a real parameter;
//  - mixed: delta_k real (AB13MD's G scaling, Fan, Tits & Doyle 1991), delta_tau complex (the
//    delay is a covering disk either way).
// Both are bounds from a grid of frequencies, refined at the peak: a sharp peak between grid points
// could be higher. Design-time code: allocates.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "control/axis_design.hpp"
#include "control/mu_bound.hpp"
#include "control/robustness.hpp"

namespace chaser::control {

struct LoopUncertaintyLft {
  double gain_nominal = 1.0;     // [-] k0
  double gain_radius = 0.0;      // [-] r_k, relative
  double delay_nominal_s = 0.0;  // [s] tau0
  double delay_radius_s = 0.0;   // [s] Delta_tau
};

// The centred ranges of box's gain and delay (its modes are not part of the LFT). Throws
// std::invalid_argument naming every problem (a range reversed, a gain <= 0, a delay < 0).
LoopUncertaintyLft loop_lft(const AxisUncertainty& box);

// w_tau(w) of the header: 2 sin(min(w Delta / 2, pi / 2)).
double delay_weight(double omega_radps, double delay_radius_s);

// M(j w), ordered (delta_tau, delta_k), for the axis' controller on k0 e^{-s tau0} / s^2 (exact delay).
Eigen::MatrixXcd loop_interconnection(const AxisDesign& design, const LoopUncertaintyLft& lft, double omega_radps);

constexpr int kMuPointsPerDecade = 100;

struct LoopMu {
  LoopUncertaintyLft lft;
  bool nominal_stable = false;        // closed loop at (k0, tau0), Pade delay: mu means nothing otherwise
  double nominal_max_real_pole = 0.0;
  MuStatus status = MuStatus::kOk;    // the first AB13MD failure, if any
  std::string message;
  std::vector<double> omega_radps;    // the grid, with the points where L0 is real
  std::vector<double> mu_complex;     // AB13MD bound, both blocks complex
  std::vector<double> mu_mixed;       // AB13MD bound, delta_k real
  double peak_complex = 0.0, peak_complex_radps = 0.0;
  double peak_mixed = 0.0, peak_mixed_radps = 0.0;
  // 1 / peak: the factor the box may grow by with stability guaranteed; inf for a zero peak.
  double margin_complex() const;
  double margin_mixed() const;
  bool ok() const { return status == MuStatus::kOk && nominal_stable; }
};

// The bounds on a log grid of kMuPointsPerDecade per decade from two decades below the controller's
// slowest pole (at most 1e-4 omega_B) to the margin band's top (margin_band_top_radps), with the
// frequencies where L0 is real added (there alone a real gain can destabilise: real mu is
// discontinuous in w, and a grid alone steps over those points), each peak refined by golden section in ln w on the intervals beside
// the grid's largest point. Throws std::invalid_argument for a bad box or an axis with no controller.
LoopMu loop_mu(const AxisDesign& design, const AxisUncertainty& box);

}  // namespace chaser::control
