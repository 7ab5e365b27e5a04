#pragma once
// What the arm's motion does to the hub's torque rows, the diagnosis's Euler equation
// (flight/fdi/deficit_isolation.hpp, deficit_torque_row). Once awake, the arm exchanges momentum
// with the hub, and its moving mass moves the centre of mass the thrusters' torques act about. The
// rows model I w' + w x I w with the chaser's nominal inertia I about its nominal centre of mass
// and the thrusters' torques about that centre. The servicer's angular momentum L about its own
// centre of mass (flight/arm/servicer_momentum.hpp) obeys dL/dt + w x L = the thrusters' torque
// about that centre (body axes), whatever the joints do. The difference is carried as
//   h = L - J_0 w    (J_0 the servicer's locked inertia at the wake: h = 0 until the arm moves),
//   d = c - c_0      (its centre of mass's shift since the wake),
// and the row gains dh/dt + w x h + d x F, F the commanded force (its torque about the shifted
// centre, less what the columns, about the nominal one, say). Before the wake both are zero: the
// stowed arm is in the chaser's inertia.
#include "core/types.hpp"
#include "flight/arm/servicer_arm.hpp"
#include "model/messages.hpp"

namespace chaser::flight {

struct ArmReactionState {
  bool woken = false;
  Mat3 locked_inertia_wake_kgm2 = Mat3::Zero();  // [kg m^2] J_0, hub axes, about c_0
  Vec3 com_wake_hub_m = Vec3::Zero();            // [m] c_0, from the hub's origin
};

struct ArmReaction {
  Vec3 momentum_Nms = Vec3::Zero();  // [N m s] h, body axes
  Vec3 com_shift_m = Vec3::Zero();   // [m] d, body axes
};

// From the joints' measured angles and rates and the gyro's rate; the first call is the wake.
ArmReaction arm_reaction(const arm::ServicerArmParams& servicer, ArmReactionState& state,
                         const model::ArmMeasurements& joints, const Vec3& omega_body_radps);

}  // namespace chaser::flight
