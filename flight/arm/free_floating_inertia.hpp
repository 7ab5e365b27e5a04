#pragma once
// The servicer with a body held rigidly by its gripper (the grasped target), and the joint-space
// inertia of that chain left free to float: what a joint controller sees once the capture has
// closed the chain and the thrusters are off (the rigidisation, COMRADE 2018 sec. 6.2.2).
//
// Payload. Welded to the gripper, the target moves with link 7, so hub, arm and target are one
// floating-base chain of 13 degrees of freedom: the target's mass and inertia are added to link 7
// (parallel axes), and floating_base_mass_matrix gives its mass matrix H.
//
// Free-floating inertia. With no force or torque on the hub (no thrust), the chain's momentum is
// conserved and the hub's velocity follows the joints' rates, v_b = -H_bb^-1 H_bq q'. The kinetic
// energy is then q'^T H* q' / 2 with
//   H* = H_qq - H_qb H_bb^-1 H_bq
// (the Schur complement of the base block; Umetani and Yoshida's generalized inertia matrix for a
// free-flying manipulator), and a joint torque tau, from rest, accelerates the joints by H*^-1 tau.
// It does not depend on how the base's velocity is parametrised. Fixed-size, no allocation.
#include "flight/arm/arm_kinematics.hpp"
#include "flight/arm/servicer_arm.hpp"

namespace chaser::flight::arm {

using JointMatrix = Eigen::Matrix<double, model::kArmJoints, model::kArmJoints>;

// A rigid body held by the gripper: its mass, its CoM in link 7's frame (the tool's axes), its
// inertia about that CoM in link 7's axes.
struct Link7Payload {
  double mass_kg = 0.0;                  // [kg]
  Vec3 com_link7_m = Vec3::Zero();       // [m]
  Mat3 inertia_link7_kgm2 = Mat3::Zero();  // [kg m^2]
};

// The payload of a target whose frame the tool holds at grasp_point_target_m (target axes, from its
// CoM) in the attitude q_target_from_tool: its CoM at tool_link7_m - R_tool_target grasp_point_target_m,
// its inertia turned into the tool's (link 7's) axes.
Link7Payload grasped_payload(const ServicerArmParams& servicer, double mass_kg, const Mat3& inertia_kgm2,
                             const Vec3& grasp_point_target_m, const Quat& q_target_from_tool);

// The servicer with the payload added to link 7 (with_rigid_body).
ServicerArmParams with_payload(ServicerArmParams servicer, const Link7Payload& payload);

// H* from a floating-base mass matrix (hub block first, as floating_base_mass_matrix orders it).
JointMatrix free_floating_joint_inertia(const ServicerMatrix& mass_matrix);

}  // namespace chaser::flight::arm
