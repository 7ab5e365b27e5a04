#pragma once
// Position controller K_pos (Fonod 2015, Fig. 4): discrete LQR on the HCW model plus a feed-forward
// that cancels the HCW dynamics of the guidance reference.
//
//   F_d = F_ff - K [r_hat - r_ref; v_hat - v_ref]                                      (LVLH, N)
//   F_ff = m (a_ref(t + T/2) - A_acc [r_ref(t + T/2); v_ref(t + T/2)])
//
// A_acc are the acceleration rows of the continuous HCW matrix (core/linear_models.hpp). The
// feed-forward is evaluated at the middle of the period it is held over (reference values carried
// forward by T/2 with their derivatives, jerk included): with the force held constant, this is the
// period mean of the required force to O(T^2), where the value at the start of the period would
// leave an acceleration lag of jerk * T/2 and a steady tracking error of jerk T / (2 w_n^2)
// (0.2 mm in the MSR blends). At a hold point (v = a = j = 0) both forms are the same exact
// equilibrium force. K is the LQR gain of the ZOH-discretised HCW model with input force = m * acceleration,
// state weight diag(q_pos I, q_vel I) and input weight r_force I (model::ControlParams).
#include "core/types.hpp"
#include "flight/guidance.hpp"
#include "core/linear_models.hpp"
#include "flight/navigation.hpp"
#include "model/scenario.hpp"

namespace chaser::flight {

struct PositionControlParams {
  Mat36 K = Mat36::Zero();         // [N/m | N s/m] feedback gain on [r - r_ref; v - v_ref]
  double mass_kg = 1.0;            // [kg] nominal mass used by the feed-forward and the design
  double mean_motion_radps = 0.0;  // [rad/s] n of the HCW model
  double period_s = 0.1;           // [s] T, the force is held over one period
  bool design_converged = false;   // the LQR Riccati solver converged
};

// Gains from explicit design inputs (what make_position_control calls with the scenario's values).
PositionControlParams design_position_control(const model::ControlParams& weights, double mass_kg,
                                              double mean_motion_radps, double period_s);
PositionControlParams make_position_control(const model::Scenario& scenario);

// The same loop for a chaser of mass `mass_kg` (control.mass_from_gauge: the starting mass less the
// propellant used): the feed-forward's mass, and K scaled by mass_kg / params.mass_kg, so that the
// closed loop's poles, eig(Ad - Bd/m K), stay those designed (Bd/m' K m'/m = Bd/m K). The H-infinity
// loops (flight/hinf_control.hpp) ask for accelerations and multiply by mass_kg themselves.
PositionControlParams with_mass(const PositionControlParams& params, double mass_kg);

// Desired force F_d in LVLH [N].
Vec3 position_control(const PositionControlParams& params, const NavEstimate& nav, const GuidanceRef& ref);

// The feed-forward part alone, F_ff [N].
Vec3 position_feedforward(const PositionControlParams& params, const GuidanceRef& ref);

}  // namespace chaser::flight
