#pragma once
// The capture's stabilisation on board (COMRADE 2018, sec. 4 and 6.1.4; model/capture.hpp's
// StabiliseParams): once the rigidisation's brakes hold, chaser, braked arm and target turn as one
// rigid composite, and the thrusters detumble it with a pure couple (no net force: the allocation is
// asked for the torque alone), "following a decaying reference profile" for its rotation.
//
// The law works on the composite's angular momentum in inertial axes, H = R J w (R the chaser's
// attitude, J the composite's inertia in the chaser's axes about the composite's CoM, w the
// chaser's rate: the composite is rigid, so its rate is the chaser's). For a rigid body acted on by
// a couple T, dH/dt = R T exactly, whatever J and however the body tumbles. The reference decays
// linearly from the momentum at the start, H_0, to zero over the duration D,
//   H_ref(t) = s(t) H_0,   s(t) = max(0, 1 - (t - t_0) / D),
// and the couple (chaser axes) is
//   T = R^T (dH_ref/dt + k (H_ref - H)),
// so the error decays as e^{-k t} and, with J right, H follows H_ref exactly: the couple is
// |H_0| / D throughout, its direction fixed in inertial space. No gyroscopic term is cancelled
// (momentum, unlike the rate, is not turned by the tumble), so the couple needs no more authority
// than |H_0| / D even about a non-principal axis.
//
// What the law assumes: J from its own model of chaser and arm (flight/arm) at the joints' angles
// when it begins, and the target's catalogue mass and inertia held where the grasp puts it (the
// gripper on the fixture in the grasp's attitude). A wrong J scales and turns the momentum it
// estimates, H_est = R J_est J^-1 R^T H; the law drives H_est, and with it the rate, to zero all
// the same (J_est J^-1 nonsingular), along a path off the reference. That error turns with the
// tumble, and the feedback chases it: the bandwidth k trades the couple's peak against how fast a
// true error goes (tests/flight/stabilise_test.cpp, the target's inertia 20 % off: the couple peaks
// at 1.8 |H_0| / D with k = 0.02 rad/s, 2.7 with 0.05, 3.4 with 0.1).
#include <array>

#include "core/zero_array.hpp"
#include "flight/arm/servicer_arm.hpp"
#include "flight/hinf_control.hpp"
#include "model/capture.hpp"

namespace chaser::flight {

// The composite's mass properties in the hub's axes (the chaser's body axes), from the hub's CoM.
struct CompositeInertia {
  double mass_kg = 0.0;                  // [kg] hub, links and target
  Vec3 com_hub_m = Vec3::Zero();         // [m] the composite's CoM
  Mat3 inertia_kgm2 = Mat3::Zero();      // [kg m^2] about com_hub_m
};

// The target as the grasp holds it: its catalogue mass and inertia (target axes, about its CoM), and
// the tool's pose on it (the fixture: the tool point at grasp_point_target_m, the tool's axes
// q_target_from_tool), from which its pose in the hub's frame follows through the arm's kinematics.
struct GraspedTarget {
  double mass_kg = 0.0;
  Mat3 inertia_kgm2 = Mat3::Zero();
  Vec3 grasp_point_target_m = Vec3::Zero();
  Quat q_target_from_tool = Quat::Identity();
};

// Hub, links (link 7 with the gripper) and target summed by the parallel-axis theorem, the arm at
// joint_angles_rad.
CompositeInertia composite_inertia(const arm::ServicerArmParams& servicer, const arm::JointVector& joint_angles_rad,
                                   const GraspedTarget& target);

struct StabiliseLawParams {
  model::StabiliseParams stabilise;
  GraspedTarget target;
  double period_s = 0.1;  // [s] the control period: the angular impulse's step, the H-infinity loops'
  // law kHinf: per inertial axis, the loop on the angular impulse (control/composite_design.hpp),
  // discretised at the period.
  std::array<DiscreteLoop, 3> hinf_loops{};
};

struct StabiliseState {
  double started_s = -1.0;                 // [s] (-1: not yet)
  Mat3 inertia_kgm2 = Mat3::Zero();        // [kg m^2] J, chaser axes, about the composite's CoM
  Vec3 momentum0_inertial_Nms = Vec3::Zero();  // [N m s] H_0
  // law kHinf: the angular impulse estimated and its reference (sums of the momentum over the
  // periods so far, inertial axes) and the loops' states.
  Vec3 impulse_Nms2 = Vec3::Zero();
  Vec3 impulse_reference_Nms2 = Vec3::Zero();
  std::array<LoopState, 3> loops = zero_array<LoopState, 3>();
  bool started() const { return started_s >= 0.0; }
};

// The couple [N m, chaser axes] at t_s from the attitude and rate estimates, once per control
// period. The first call begins the stabilisation: J from the servicer at the joints' angles, H_0
// the momentum estimated now. With law kHinf the couple is dH_ref/dt + K(Phi_ref - Phi) per
// inertial axis, Phi the angular impulse: the sum of the momentum times the period over the
// periods before (the reference's likewise, so that the two are integrated alike).
Vec3 stabilise_couple(const StabiliseLawParams& params, const arm::ServicerArmParams& servicer, StabiliseState& state,
                      const arm::JointVector& joint_angles_rad, const Quat& q_inertial_from_body,
                      const Vec3& omega_body_radps, double t_s);

// s(t): the share of H_0 the reference keeps at t_s.
double stabilise_reference_share(const model::StabiliseParams& params, const StabiliseState& state, double t_s);

}  // namespace chaser::flight
