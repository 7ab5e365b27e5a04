#pragma once
// Forward kinematics of the hub and arm, and the tool point's geometric Jacobian.
//
// Poses (Featherstone, RBDA sec. 4.1, by recursion along the chain from the hub):
//   R_world_from_link_i = R_world_from_parent Rot(axis_i, q_i),
//   r_link_i = r_parent + R_world_from_parent joint_position_parent_i,
// link 1's parent being the hub; the tool point is r_link_7 + R_world_from_link_7 tool_link7_m.
//
// Jacobian J (6 x 13): (v_tool; omega_tool) = J v, both in world axes, v ordered as in
// flight/arm/servicer_arm.hpp. Column by column:
//   hub velocity (world) e_k:      (e_k; 0),
//   hub angular velocity (hub) e_k: (R e_k x (r_tool - r_hub); R e_k), R = R_world_from_hub,
//   joint i:                        (a_i x (r_tool - r_link_i); a_i), a_i joint i's axis in world.
// MuJoCo's mj_jacSite gives the same matrix for its qvel (a free joint's angular velocity in body
// axes), which tests/flight/arm checks.
#include <array>

#include <Eigen/Core>

#include "core/types.hpp"
#include "flight/arm/servicer_arm.hpp"
#include "flight/arm/spatial.hpp"

namespace chaser::flight::arm {

using ToolJacobian = Eigen::Matrix<double, 6, kServicerDofs>;

struct ArmKinematics {
  Vec3 r_hub_world_m = Vec3::Zero();             // [m] the hub's origin (its CoM)
  Mat3 world_from_hub = Mat3::Identity();
  std::array<Mat3, model::kArmJoints> world_from_link{};
  std::array<Vec3, model::kArmJoints> r_link_world_m{};    // [m] link i's origin = joint i's
  std::array<Vec3, model::kArmJoints> axis_world{};        // [-] joint i's unit axis
  std::array<Vec3, model::kArmJoints> r_com_world_m{};     // [m] link i's CoM (link 7's with the gripper)
  Vec3 r_tool_world_m = Vec3::Zero();            // [m] the tool point; its axes are link 7's
};

// The hub's pose (q_world_from_hub is normalised here, as MuJoCo normalises a free joint's
// quaternion) and the joint angles [rad].
ArmKinematics arm_kinematics(const ServicerArmParams& params, const Vec3& r_hub_world_m, const Quat& q_world_from_hub,
                             const JointVector& joint_angles_rad);

ToolJacobian tool_jacobian(const ArmKinematics& kinematics);

// The chain's motion for a velocity v and a second generalized vector w, each body's in world axes
// about the fixed point O where the hub's origin is now (flight/arm/spatial.hpp), by one forward
// pass from the hub (Featherstone, RBDA Table 5.1): V_i = J_i v, W_i = J_i w, and
// W'_i = (dJ_i/dt) w along v. A hinge's subspace turns as V_i x S_i; the free joint's angular
// column as omega x (its linear part is in world axes, so it does not turn): the hub's
// (dJ_0/dt) w = (omega x a; v_hub x a), a = R w_omega. Index 0 is the hub, i the link i. With
// w = v, W'_i is the body's velocity-product acceleration, the RNEA's A_i.
struct ChainMotion {
  std::array<Vec6, model::kArmJoints> subspace{};  // S_i, hinge i's (a_i; (r_i - O) x a_i)
  std::array<Vec6, 1 + model::kArmJoints> velocity{}, w{}, w_rate{};
};
ChainMotion chain_motion(const ArmKinematics& kinematics, const Eigen::Matrix<double, kServicerDofs, 1>& velocity,
                         const Eigen::Matrix<double, kServicerDofs, 1>& w);

// Each body's spatial inertia in world axes about the hub's origin (flight/arm/spatial.hpp):
// [0] the hub, [i] link i. The rotational inertias turn with their bodies, R I R'.
using BodyInertias = std::array<SpatialInertia, 1 + model::kArmJoints>;
BodyInertias body_inertias_about_hub(const ServicerArmParams& params, const ArmKinematics& kinematics);

}  // namespace chaser::flight::arm
