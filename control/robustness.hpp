#pragma once
// Robust stability of one designed axis over a box of plant uncertainty, checked point by point on
// a dense grid (COMRADE 2018, sec. 5-6 name the uncertainties).
//
// The true plant of an axis, as the designed controller meets it:
//
//   G(s) = k e^{-s tau} / s^2  prod_i F_i(s)
//
//  - k: the precompensation's gain error. Computed torque commands F = m_hat a (T = I_hat alpha); with
//    the true mass m and thrust scaled by (1 + d_F), the axis responds with k = (m_hat / m)(1 + d_F),
//    so k spans [(1 - d_F) / (1 + d_m), (1 + d_F) / (1 - d_m)] for relative knowledge d_m and thrust
//    dispersion d_F (thruster misalignment's loss along the axis, 1 - cos, is 1e-6 at 0.1 deg: left out);
//  - tau: the loop delay over the valves' range, T/2 + [0, delay_max] + rise/2;
//  - F_i: a mode the rigid model leaves out, seen from the body as a zero-pole pair (a liquid's first
//    slosh mode on its spring, an appendage on its hinge). A body m_b carrying a mode mass m_m on a
//    spring k_m and damper c: x_b / F = (m_m s^2 + c s + k_m) / (s^2 (m_b m_m s^2 + m (c s + k_m))),
//    m = m_b + m_m. Against the rigid 1 / (m s^2) that is
//
//      F(s) = r (s^2 + 2 zeta omega_z s + omega_z^2) / (s^2 + 2 zeta (omega_p^2 / omega_z) s + omega_p^2),
//      r = 1 / (1 - epsilon),  omega_p^2 = r omega_z^2,
//
//    with omega_z = sqrt(k_m / m_m) the mode's frequency with the body held, epsilon = m_m / m its
//    share of the mass (of the inertia, for a rotation) and c = 2 zeta m_m omega_z. F -> 1 at low
//    frequency (the whole mass moves) and -> r at high frequency (the body alone).
//
// Each grid point is judged by the closed loop's poles (the delay as the design's Pade
// approximation) and by the classical margins with the exact delay (loop_margins). A grid is a check,
// not a proof: between its points a sharp resonance could do worse (docs/control.md says how dense).
// Design-time code: allocates.
#include <string>
#include <vector>

#include "control/axis_design.hpp"

namespace chaser::control {

struct UncertainMode {
  std::string name;                 // e.g. "slosh", "stowed arm"
  double frequency_lo_radps = 0.0;  // [rad/s] omega_z range (> 0)
  double frequency_hi_radps = 0.0;  // [rad/s] >= lo
  double modal_fraction = 0.0;      // [-] epsilon in [0, 1)
  double damping = 0.0;             // [-] zeta in [0, 1)
};

struct AxisUncertainty {
  double gain_lo = 1.0, gain_hi = 1.0;        // [-] k range (> 0)
  double delay_lo_s = 0.0, delay_hi_s = 0.0;  // [s] tau range (>= 0)
  std::vector<UncertainMode> modes;
  int points_per_range = 5;                   // grid points along each range (>= 2; 1 where lo = hi)
};

// F(s) of a mode at omega_z (the header); unit static gain.
StateSpace mode_factor(double frequency_radps, double modal_fraction, double damping);

struct GridPoint {
  double gain = 1.0;
  double delay_s = 0.0;
  std::vector<double> mode_frequency_radps;  // one per mode
};

struct RobustnessResult {
  int points = 0;                  // grid points checked
  int unstable = 0;                // with a closed-loop pole at Re >= 0
  double worst_max_real_pole = 0.0;  // the largest max Re(pole) over the grid
  GridPoint worst_pole_point;
  double min_phase_margin_deg = 0.0;  // over the stable points, exact delay
  GridPoint min_phase_margin_point;
  double min_gain_margin_up = 0.0;    // [-] over the stable points
  double max_gain_margin_down = 0.0;  // [-] over the stable points (0: no downward limit anywhere)
  bool robustly_stable() const { return unstable == 0; }
};

// Throws std::invalid_argument naming every problem of the box (ranges reversed, out of range).
RobustnessResult robust_stability_grid(const AxisDesign& design, const AxisUncertainty& box);

}  // namespace chaser::control
