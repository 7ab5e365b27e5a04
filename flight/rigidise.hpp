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
//
// The H-infinity law (capture.rigidise.law: hinf; COMRADE 2018 Table 7's other column, whose design
// the paper does not print): with the thrusters off, hub, arm and target float as one chain, and
// from rest a joint torque tau accelerates the joints by H*^-1 tau, H* the chain's free-floating
// joint inertia (flight/arm/free_floating_inertia.hpp; the target its catalogue body where the
// grasp holds it). So the law is the computed torque
//   tau = s(H* u),   u_j = K_j(q_d,j - q_j),
// each joint's error a double integrator in u_j, closed by one S/KS loop per joint
// (control/joint_design.hpp) on the angle alone, s the same saturation. H* and the loops are made at
// the law's first step, from the angles it holds: seven designs, once per run. The loops' low-
// frequency gain removes the steady yield under the turning composite's centripetal load, which
// the PD carries as K_p (q - q_d).
#include <array>

#include "core/zero_array.hpp"
#include "flight/arm/free_floating_inertia.hpp"
#include "flight/arm/servicer_arm.hpp"
#include "flight/hinf_control.hpp"
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
  // law kHinf: the flight software's servicer with the grasped target on link 7, the loops' period
  // (the joints') and delay.
  arm::ServicerArmParams held;
  double joint_period_s = 1e-3;  // [s]
  double delay_s = 1e-3;         // [s]
};

struct RigidiseState {
  arm::JointVector q_hold_rad = arm::JointVector::Zero();  // q_d: the angles at the capture's confirmation
  double started_s = -1.0;     // [s] the first step (-1: not yet)
  double quiet_since_s = -1.0; // [s] every joint's rate below the threshold since (-1: not now)
  double brakes_s = -1.0;      // [s] the brakes were commanded (-1: not yet)
  // law kHinf, from the first step: H* at q_d and each joint's loop and its state.
  arm::JointMatrix inertia_kgm2 = arm::JointMatrix::Zero();
  std::array<DiscreteLoop, model::kArmJoints> loops{};
  std::array<LoopState, model::kArmJoints> x = zero_array<LoopState, model::kArmJoints>();
  bool started() const { return started_s >= 0.0; }
};

// H* of params.held at the joints' angles (the hub's pose does not enter it).
arm::JointMatrix rigidise_joint_inertia(const RigidiseLawParams& params, const arm::JointVector& joint_angles_rad);

// The seven loops designed on H*'s diagonal and discretised at the joints' period. Throws
// std::runtime_error naming the joint whose design fails.
std::array<DiscreteLoop, model::kArmJoints> rigidise_loops(const RigidiseLawParams& params,
                                                           const arm::JointMatrix& inertia_kgm2);

// One joint step at t_s: the law's torques, or the brakes once engaged. The first call holds the
// joints' angles as q_d (and, law kHinf, designs the loops there). may_brake false: the brakes'
// dwell does not run (a berthing soft docked: the brakes wait for the pins).
model::ArmCommand step_rigidise(const RigidiseLawParams& params, RigidiseState& state,
                                const model::ArmMeasurements& joints, double t_s, bool may_brake = true);

}  // namespace chaser::flight
