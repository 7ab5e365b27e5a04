#pragma once
// The servicer's 13 degrees of freedom seen as tasks (COMRADE 2018, sec. 6.2.1: the chaser's pose
// and the gripper's pose relative to the target), for the combined controllers.
//
// The extended task x (13): the hub's pose (6), the tool's pose (6) and one joint angle, the
// redundancy coordinate. A 7-DOF arm has one degree of freedom more than the tool's six; with the
// joint angle of the arm's upper-arm roll (joint 3 of the S-R-S layout) added as a task, the
// extended Jacobian J (13 x 13, x' = J v) is square and, away from the six other joints'
// singularities, invertible. This is Baillieul's extended Jacobian with a joint coordinate: the
// redundancy is resolved by a coordinate that is integrable (a joint angle is one), which avoids
// the non-integrable null-space velocities that a projected null-space task has (Ott et al., ref.
// [20] of the paper), and dJ/dt needs no derivative of a projector.
//
// Velocities are world twists: rows 0-2 the hub's origin velocity (world), 3-5 the hub's angular
// velocity in WORLD axes (R omega_body), 6-11 the tool point's velocity and angular velocity
// (world, tool_jacobian), 12 the redundancy joint's rate. v is ordered as in servicer_arm.hpp.
#include "core/types.hpp"
#include "flight/arm/arm_kinematics.hpp"
#include "flight/arm/servicer_arm.hpp"

namespace chaser::flight::arm {

inline constexpr int kTaskDofs = kServicerDofs;  // 6 hub + 6 tool + 1 redundancy
inline constexpr int kRedundancyJoint = 2;       // joint 3 (index 2), the upper-arm roll
using TaskVector = ServicerVector;
using TaskJacobian = ServicerMatrix;

// A frame's motion in world axes: pose, twist and its derivative (of the origin's velocity, and of
// the angular velocity), all in world axes.
struct FrameMotion {
  Vec3 r_m = Vec3::Zero();
  Vec3 v_mps = Vec3::Zero();
  Vec3 a_mps2 = Vec3::Zero();
  Quat q_world_from_frame = Quat::Identity();
  Vec3 omega_radps = Vec3::Zero();
  Vec3 alpha_radps2 = Vec3::Zero();
};

// A child frame moving in a moving parent: child_in_parent's fields are relative to the parent,
// in the parent's axes (its velocity and acceleration are derivatives seen from the parent). The
// child in world axes, by the transport theorem: with d = R_P r_c,
//   r = r_P + d,  v = v_P + w_P x d + R_P v_c,
//   a = a_P + al_P x d + w_P x (w_P x d) + 2 w_P x R_P v_c + R_P a_c,
//   q = q_P q_c,  w = w_P + R_P w_c,  al = al_P + R_P al_c + w_P x R_P w_c.
FrameMotion compose(const FrameMotion& parent, const FrameMotion& child_in_parent);

// The reference of the extended task: the hub's and the tool's motion, the redundancy joint's
// angle [rad], rate and acceleration.
struct TaskReference {
  FrameMotion hub;
  FrameMotion tool;
  double joint_rad = 0.0, joint_rate_radps = 0.0, joint_acceleration_radps2 = 0.0;
};

// x' = J v, rows as above.
TaskJacobian extended_jacobian(const ArmKinematics& kinematics);

// (dJ/dt) w along the motion v (J's rate as the servicer moves at v, applied to w): the tool rows
// from link 7's (chain_motion, flight/arm/arm_kinematics.hpp), the hub's angular rows
// omega x (R w_omega), the rest zero.
TaskVector extended_jacobian_rate_times(const ArmKinematics& kinematics, const ServicerVector& velocity,
                                        const ServicerVector& w);

// The task's errors e (13): position errors r - r_ref [m], attitude errors as the vector part eps
// of q q_ref^-1 (world axes, sign chosen so that its scalar part is >= 0) [-], the joint's q - q_ref
// [rad]; with velocity errors e' = J v - x'_ref. A spring -k eps on an attitude has the potential
// 2 k (1 - eta), whose rate is k eps . (omega - omega_ref): eps is the attitude's coordinate for
// a passivity argument.
struct TaskErrors {
  TaskVector pose = TaskVector::Zero();
  TaskVector velocity = TaskVector::Zero();
  TaskVector reference_velocity = TaskVector::Zero();      // x'_ref
  TaskVector reference_acceleration = TaskVector::Zero();  // x''_ref
};
TaskErrors task_errors(const ArmKinematics& kinematics, const TaskJacobian& jacobian, const JointVector& joint_angles_rad,
                       const ServicerVector& velocity, const TaskReference& reference);

// The world attitude of the tool (link 7's axes).
Quat tool_attitude(const ArmKinematics& kinematics);

}  // namespace chaser::flight::arm
