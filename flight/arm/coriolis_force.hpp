#pragma once
// The Coriolis and centrifugal generalized force C(q, v) v (13) of the hub and arm, by the
// recursive Newton-Euler algorithm (Featherstone, RBDA sec. 5.3, Table 5.1; here in one frame, as
// MuJoCo's mj_rne writes it) with zero acceleration and no gravity: it is what the equation of motion H(q) dv/dt + C(q, v) v = tau
// leaves when dv/dt = 0, MuJoCo's qfrc_bias without gravity. v and tau are ordered as in
// flight/arm/servicer_arm.hpp; dv/dt is the derivative of that v (of the hub origin's velocity in
// world axes and of the hub's angular velocity in hub axes).
//
// In world axes about a point O fixed in the world where the hub's origin is now
// (flight/arm/spatial.hpp), the forward pass is
//   V_0 = (omega; v_hub),  A_0 = (0; -omega x v_hub)   (the hub's origin does not accelerate and
//                          omega_hub_body is constant, so omega is too; the spatial acceleration's
//                          linear part is the origin's acceleration less omega x v_O),
//   V_i = V_{i-1} + S_i qd_i,  A_i = A_{i-1} + V_i x S_i qd_i   (dS_i/dt = V_i x S_i in one frame),
//   F_i = I_i A_i + V_i x* I_i V_i,
// and the backward pass sums the forces from the tip: F^c_i = F_i + F^c_{i+1},
//   tau_i = S_i' F^c_i,  tau_base = (f; R' n) for F^c_0 = (n; f), R = R_world_from_hub.
#include "flight/arm/arm_kinematics.hpp"
#include "flight/arm/servicer_arm.hpp"

namespace chaser::flight::arm {

// velocity: (v_hub_world_mps, omega_hub_body_radps, joint rates [rad/s]).
ServicerVector coriolis_force(const ServicerArmParams& params, const ArmKinematics& kinematics,
                              const ServicerVector& velocity);

// C(q, v) w for any w, with the factorisation that makes dH/dt - 2 C skew-symmetric (the property
// a passivity-based controller's proof rests on: flight/arm/compliance_control.hpp). With each
// body's spatial Jacobian J_i (V_i = J_i v, world axes about O) and its inertia I_i about O,
//   H = sum_i J_i' I_i J_i,   C = sum_i J_i' (I_i dJ_i/dt + V_i x* I_i J_i),
// which is Newton-Euler's d(I_i V_i)/dt = I_i A_i + V_i x* I_i V_i summed through J_i'; since
// dI_i/dt = V_i x* I_i - I_i V_i x and (V x*) = -(V x)', dH/dt - 2 C = sum_i (A_i - A_i') + (B_i' - B_i)
// with A_i = (dJ_i/dt)' I_i J_i and B_i = J_i' I_i (V_i x) J_i: skew. The same two passes as the
// RNEA above, with W_i = J_i w and (dJ_i/dt) w in place of V_i and A_i; coriolis_force(v) is
// coriolis_times(v, v).
ServicerVector coriolis_times(const ServicerArmParams& params, const ArmKinematics& kinematics,
                              const ServicerVector& velocity, const ServicerVector& w);

}  // namespace chaser::flight::arm
