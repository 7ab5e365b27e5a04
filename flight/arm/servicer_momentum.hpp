#pragma once
// The servicer's (hub and arm) angular momentum about its own centre of mass, in hub axes, from the
// hub's rate and the joints' angles and rates: what the diagnosis's Euler equation must see once
// the arm moves (flight/arm_reaction.hpp). Its rate of change is the external torque about the
// centre of mass (the thrusters'), whatever the arm does inside.
//
// From the joint-space mass matrix H (flight/arm/floating_base_mass_matrix.hpp), whose base rows
// are the linear momentum P (world axes) and the angular momentum h_O about the hub's origin O
// (hub axes): p = H v with v = (0, omega, q'). The hub's translation is left out (v_O = 0): the
// momentum about the centre of mass is the same in every translating frame. About the centre of
// mass c (from O), L = h_O - c x P. The locked inertia (the servicer frozen at these angles, about
// c) is H's hub block moved from O to c by the parallel-axis theorem. Fixed-size, no allocation.
#include "flight/arm/arm_kinematics.hpp"
#include "flight/arm/servicer_arm.hpp"

namespace chaser::flight::arm {

struct ServicerMomentum {
  Vec3 com_hub_m = Vec3::Zero();               // [m] the servicer's CoM from the hub's origin, hub axes
  Vec3 angular_momentum_Nms = Vec3::Zero();    // [N m s] about that CoM, hub axes
  Mat3 locked_inertia_kgm2 = Mat3::Zero();     // [kg m^2] about that CoM, hub axes
};

ServicerMomentum servicer_momentum(const ServicerArmParams& params, const JointVector& joint_angles_rad,
                                   const JointVector& joint_rates_radps, const Vec3& omega_hub_body_radps);

}  // namespace chaser::flight::arm
