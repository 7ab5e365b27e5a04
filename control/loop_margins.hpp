#pragma once
// Classical figures of a SISO feedback loop, from its frequency response:
//
//   L(j w) = G(j w) K(j w) e^{-j w tau},   S = 1 / (1 + L),   T = L / (1 + L)
//
// with the loop broken at the plant input or output (the same for SISO) and negative feedback.
// The transport delay tau is exact here (e^{-j w tau}), not a Pade approximation, so the margins
// are those of the delayed loop itself.
//
// - Gain margins: at every phase crossover (L real and negative, L = -|L|), the loop gain can be
//   scaled by 1/|L| before the Nyquist plot passes through -1. A crossover with |L| < 1 bounds an
//   increase of the gain (gain_margin_up = min 1/|L|); one with |L| > 1 bounds a decrease
//   (gain_margin_down = max 1/|L|): a double integrator under lead control has such a low-frequency
//   crossover. The loop stays stable for gains k in (gain_margin_down, gain_margin_up).
// - Phase margin: at every gain crossover (|L| = 1), L's angle from -1 either way round,
//   180 deg - |arg L(j w_c)| with arg in (-180, 180]; the smallest over the crossovers (a lightly
//   damped mode can make several). Delay margin: the clockwise angle to -1, (180 deg + arg L) [rad]
//   / w_c, the least over the crossovers.
// - Peaks and bandwidth: M_S = max |S|, M_T = max |T|; the bandwidth is where |S| first crosses
//   1/sqrt(2) from below (Skogestad & Postlethwaite, "Multivariable Feedback Control", 2nd ed.,
//   sec. 2.4.5, omega_B).
//
// These hold only for a stable closed loop (check its poles first: a margin of an unstable loop
// means nothing). S&P eqs. 2.40-2.41 tie them to the peak: GM >= M_S / (M_S - 1) and
// PM >= 2 arcsin(1 / (2 M_S)); the tests use that as an independent check.
//
// Method: a log grid of points_per_decade points per decade over [omega_min, omega_max], with points
// added around every lightly damped pole of G and K (damping ratio < 0.2: 33 points across 16 of
// its half-power widths, so a sharp resonance is not stepped over); each
// sign change (of |L| - 1 for gain crossovers, of Im L with Re L < 0 for phase crossovers, of
// |S| - 1/sqrt(2) for the bandwidth) is refined by bisection in ln w to kMarginLogTolerance, and
// each peak by golden section on the grid intervals beside the largest point. A crossing or peak
// narrower than the grid spacing can be missed (a sweep, like hinf_norm_estimate).
// Design-time code: allocates.
#include <complex>
#include <limits>
#include <vector>

#include "control/state_space.hpp"

namespace chaser::control {

// The loop as a product: L(s) = G(s) K(s) e^{-s tau}. G and K are SISO.
struct SisoLoop {
  StateSpace plant;       // G: 1 input, 1 output
  StateSpace controller;  // K: 1 input, 1 output
  double delay_s = 0.0;   // [s] tau >= 0, exact
};

std::complex<double> loop_response(const SisoLoop& loop, double omega_radps);

struct LoopMargins {
  double gain_margin_up = std::numeric_limits<double>::infinity();  // [-] 1 / |L| at the phase crossovers with |L| < 1
  double gain_margin_down = 0.0;               // [-] 1 / |L| at the phase crossovers with |L| > 1; 0 if none
  double phase_crossover_radps = std::numeric_limits<double>::quiet_NaN();  // of gain_margin_up
  double phase_margin_deg = std::numeric_limits<double>::infinity();       // [deg] smallest; inf if |L| never 1
  double gain_crossover_radps = std::numeric_limits<double>::quiet_NaN();  // [rad/s] of the phase margin
  double delay_margin_s = std::numeric_limits<double>::infinity();         // [s] least PM / w_c
  double sensitivity_peak = 0.0;               // [-] M_S
  double sensitivity_peak_radps = 0.0;         // [rad/s]
  double complementary_peak = 0.0;             // [-] M_T
  double complementary_peak_radps = 0.0;       // [rad/s]
  double bandwidth_radps = std::numeric_limits<double>::quiet_NaN();  // |S| first reaches 1/sqrt(2)
};

constexpr int kMarginPointsPerDecade = 200;
constexpr double kMarginLogTolerance = 1e-12;

// Throws std::invalid_argument if G or K is not SISO, tau < 0 or not finite, or the range is not
// 0 < omega_min < omega_max (finite).
LoopMargins loop_margins(const SisoLoop& loop, double omega_min_radps, double omega_max_radps,
                         int points_per_decade = kMarginPointsPerDecade);

}  // namespace chaser::control
