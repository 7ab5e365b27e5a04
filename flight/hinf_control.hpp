#pragma once
// The six H-infinity loops of control.hinf, flown (COMRADE 2018, sec. 5): the
// computed-torque precompensation, then per axis the loop designed on what remains
// (control/six_axis_design.hpp), discretised by Tustin at the control period (control/tustin.hpp).
//
//   translation:  F_d = F_ff - m A_acc [r_hat - r_ref; v_hat - v_ref] + m R^T (u_B + f_B),
//                 u_B,i = K_i(e_B,i), e_B = R (r_ref - r_hat)
//   rotation (body):     C_d = omega x (I omega) - I (omega x omega_r) + I u_rot,  u_rot = K(-theta)
//
// F_ff is the LQR's feed-forward of the reference (flight/position_control.hpp: the reference's
// acceleration less HCW at mid-period); the second term cancels HCW on the estimated error, so the
// loop sees the double integrator it was designed on. The rotation's computed torque is the LQR's
// (flight/attitude_control.hpp). The loops see position and angle only, as designed (S/KS on the
// error); rates are the controllers' own. Each loop's acceleration is clamped at its authority (the
// design's: what the set gives along the axis alone); the loop states run on (no anti-windup):
// the TMU and the allocator absorb the rest, as for the LQR.
// The translation loops act on the error in the reference attitude's body axes (R = R_body_from_lvlh
// of the reference), the axes their authority was designed for, and f_B cancels what that frame's
// rotation relative to LVLH adds to the error's dynamics (Coriolis and centripetal; hinf_control.cpp).
// In the synchronised hold the reference turns with the target, and an error of the chaser's
// own (its mass, a thruster's thrust or misalignment, all fixed in the body) is then a constant
// input disturbance, which the loops' W_d rejects; in LVLH axes it turned at the target's rate
// (0.044 rad/s, beside the 0.08 rad/s bandwidth) and was hardly rejected at all: 2 of 20 dispersed
// runs captured (docs/gnc.md, "COMRADE's synchronisation phase").
#include <array>

#include "control/axis_design.hpp"
#include "core/types.hpp"
#include "core/zero_array.hpp"
#include "flight/attitude_control.hpp"
#include "flight/guidance.hpp"
#include "flight/navigation.hpp"
#include "flight/position_control.hpp"
#include "model/scenario.hpp"

namespace chaser::flight {

inline constexpr int kMaxLoopStates = 8;  // the designs have 4 (plant 3 + W_S 1); checked on design
using LoopState = Eigen::Matrix<double, kMaxLoopStates, 1>;

// x+ = a x + b e, u = c x + d e, states [0, kMaxLoopStates) with zero padding.
struct DiscreteLoop {
  Eigen::Matrix<double, kMaxLoopStates, kMaxLoopStates> a = Eigen::Matrix<double, kMaxLoopStates, kMaxLoopStates>::Zero();
  LoopState b = LoopState::Zero();
  Eigen::Matrix<double, 1, kMaxLoopStates> c = Eigen::Matrix<double, 1, kMaxLoopStates>::Zero();
  double d = 0.0;
  double authority = 0.0;  // [m/s^2 | rad/s^2] |u| is clamped here
  int states = 0;
};

struct HinfControlParams {
  bool enabled = false;               // control.law == hinf
  std::array<DiscreteLoop, 6> loops;  // x, y, z (LVLH), rx, ry, rz (body)
};

struct HinfControlState {
  std::array<LoopState, 6> x = zero_array<LoopState, 6>();
};

// The loop of one axis design, discretised by Tustin at the period. Throws std::runtime_error when
// the controller is not SISO or has more than kMaxLoopStates states.
DiscreteLoop discrete_loop(const control::AxisDesign& design, double period_s);

// Disabled unless control.law is hinf; then designs the six loops (control/six_axis_design.hpp,
// without the robustness grid) and discretises them. Throws std::runtime_error naming the axis when
// a design fails or has more than kMaxLoopStates states.
HinfControlParams make_hinf_control(const model::Scenario& scenario);

// One step of one loop: u = clamp(c x + d e), then x advances.
double step_loop(const DiscreteLoop& loop, LoopState& x, double error);

struct HinfDemand {
  Vec3 force_lvlh_N = Vec3::Zero();
  Vec3 torque_body_Nm = Vec3::Zero();
};

// The force and torque demands of the header. `position` and `attitude` give the precompensation's
// mass, inertia, mean motion and period (the LQR's design inputs; their gains are not used).
HinfDemand hinf_control(const HinfControlParams& params, HinfControlState& state, const PositionControlParams& position,
                        const AttitudeControlParams& attitude, const NavEstimate& nav, const GuidanceRef& ref,
                        const model::LvlhFrame& lvlh);

}  // namespace chaser::flight
