#pragma once
// The flight software's own model of the servicer with its arm: the hub (a free body about its
// centre of mass) and the 7-DOF chain of model/arm.hpp, for the arm's controllers on board
// (COMRADE 2018, sec. 6: the compliance and H-infinity controllers behind a computed-torque
// precompensation, over 6 platform + 7 joint DOF). It never touches MuJoCo, which is the truth.
//
// Conventions shared by the files of this folder:
// - Bodies: 0 the hub, 1..7 the links. The gripper has no joint, so it is lumped into link 7 (its
//   mass, CoM and inertia added by parallel axes): link 7 below is link 7 with the gripper.
// - Frames: every link frame is parallel to its parent's at q = 0; joint i turns link i about
//   joint_axis (parent axes = link axes, it is the rotation's own axis) at joint_position_parent_m.
//   Link 1's parent is the hub's frame: body axes, origin at the hub's CoM (not the body's
//   reference point, which model::ArmParams::mount_body_m is given from); the mount, less the
//   CoM's offset, is folded into link 1's joint position.
// - Generalized velocity v (13), as MuJoCo orders a free joint followed by hinges: the velocity of
//   the hub's origin in WORLD axes [m/s], the hub's angular velocity in HUB BODY axes [rad/s], the
//   7 joint rates [rad/s]. The generalized forces are its conjugates: the force on the hub in world
//   axes [N], the torque about the hub's origin in hub axes [N m], the joint torques [N m].
#include <array>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "model/arm.hpp"

namespace chaser::flight::arm {

inline constexpr int kBaseDofs = 6;                                // the hub's free joint
inline constexpr int kServicerDofs = kBaseDofs + model::kArmJoints;  // 13

using JointVector = Eigen::Matrix<double, model::kArmJoints, 1>;
using ServicerVector = Eigen::Matrix<double, kServicerDofs, 1>;
using ServicerMatrix = Eigen::Matrix<double, kServicerDofs, kServicerDofs>;

struct ServicerLinkParams {
  Vec3 joint_position_parent_m = Vec3::Zero();  // [m] joint i's origin (link i's origin), parent frame
  Vec3 joint_axis = Vec3::UnitX();              // [-] unit, parent (= link) axes
  double mass_kg = 0.0;                         // [kg]
  Vec3 com_link_m = Vec3::Zero();               // [m] centre of mass, link frame
  Mat3 inertia_com_link_kgm2 = Mat3::Zero();    // [kg m^2] about the CoM, link axes
  double armature_kgm2 = 0.0;                   // [kg m^2] the drive's reflected rotor inertia
};

struct ServicerArmParams {
  double hub_mass_kg = 1.0;                                 // [kg]
  Mat3 hub_inertia_kgm2 = Mat3::Identity();                 // [kg m^2] about the hub's CoM, hub axes
  std::array<ServicerLinkParams, model::kArmJoints> links{};  // link 7 includes the gripper
  Vec3 tool_link7_m = Vec3::Zero();                         // [m] the gripper's tool point, link 7's frame
};

// A link with a rigid body added to it (the gripper, a grasped target): the body's mass, its CoM in
// the link's frame and its inertia about that CoM in the link's axes, combined with the link's by
// parallel axes.
ServicerLinkParams with_rigid_body(ServicerLinkParams link, double mass_kg, const Vec3& com_link_m,
                                   const Mat3& inertia_com_link_kgm2);

// The flight model of a scene's hub and arm (the target is not part of it): the mount from the
// hub's CoM folded into link 1, the gripper lumped into link 7, each link's principal inertia as a tensor.
ServicerArmParams servicer_arm_of(const model::MultibodySceneParams& scene);

// Every problem at once: masses >= 0 (the hub's > 0), inertias symmetric and positive semidefinite
// (the hub's definite, else H is singular), unit joint axes, armatures >= 0, all finite.
std::vector<std::string> validate(const ServicerArmParams& params);

}  // namespace chaser::flight::arm
