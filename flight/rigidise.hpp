#pragma once
// The capture's rigidisation on board (COMRADE 2018, sec. 4 and 6.2.2; model/capture.hpp's
// RigidiseParams): the gripper locked on the fixture, the thrusters inhibited, the arm alone damps
// the remaining relative motion of chaser and target with the paper's saturated PD law at joint
// level,
//   u = -s(K_d q' + K_p (q - q_d)),
// q_d the joints' angles when the capture was confirmed (the paper: "the one at the capture
// point"), s the saturation at each drive's repeated peak M. Once every joint's rate has stayed
// below the brake threshold for the dwell, the brakes engage and the drives' demand is zero.
//
// The paper's saturation (its "linear saturation for (L, M)", the stability proof's condition:
// locally Lipschitz, strictly increasing, identity for |tau| <= L, |s| < M):
//   s(tau) = tau                                      |tau| <= L
//          = +-L + (M - L) tanh((tau -+ L) / (M - L))  beyond,
// its third branch printed as tau > -L, which must read tau > L. Its slope is 1 either side of L
// (tanh'(0) = 1), so s is C1. The plain clip, min(max(tau, -M), M), is the paper's Fig. 13 foil.
#include "flight/arm/servicer_arm.hpp"
#include "model/capture.hpp"
#include "model/messages.hpp"

namespace chaser::flight {

// The paper's linear saturation for (L, M), 0 < L < M.
double linear_saturation(double tau, double linear_limit, double limit);
// min(max(tau, -M), M).
double clip_saturation(double tau, double limit);

struct RigidiseLawParams {
  model::RigidiseParams rigidise;
  double torque_limit_Nm = 176.0;  // [N m] M: the drives' repeated peak
};

struct RigidiseState {
  arm::JointVector q_hold_rad = arm::JointVector::Zero();  // q_d: the angles at the capture's confirmation
  double started_s = -1.0;     // [s] the first step (-1: not yet)
  double quiet_since_s = -1.0; // [s] every joint's rate below the threshold since (-1: not now)
  double brakes_s = -1.0;      // [s] the brakes were commanded (-1: not yet)
  bool started() const { return started_s >= 0.0; }
};

// One joint step at t_s: the law's torques, or the brakes once engaged. The first call holds the
// joints' angles as q_d.
model::ArmCommand step_rigidise(const RigidiseLawParams& params, RigidiseState& state,
                                const model::ArmMeasurements& joints, double t_s);

}  // namespace chaser::flight
