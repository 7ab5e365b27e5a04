#pragma once
// MJCF text (MuJoCo's XML model) generated from a multibody scene. MuJoCo 2.2.2 has no model-editing
// API, so the scene is written as text and compiled by MuJoCo (plant/multibody/mujoco_model.hpp).
// Every number is written in its shortest round-trip form, so the model holds exactly the
// parameters' doubles and the same scene always gives the same text.
//
// The scene: two free bodies, "hub" and "target", each about its centre of mass with its full
// inertia tensor; the arm's links "link1".."link7" and the "gripper" a chain below the hub, joint i
// ("joint1".."joint7") a hinge driven by a motor ("motor1".."motor7") of unit gear whose control
// is the joint torque [N m], limited to the arm's momentary torque. The world has no gravity and no
// contact: the orbit's forces and torques are applied per body by the plant, contact comes with
// the gripper's model. With scene.arm_locks, each joint also has a lock "lock1".."lock7" holding it
// at arm.stowed_rad (<equality><joint>, its q0 = 0 so the constant is the angle itself). With
// scene.grasp_weld, a weld "grasp" of the gripper to the target, inactive (plant/multibody/weld.hpp).
// With scene.berth_contact (ASSIST's berthing), the gripper is a capture probe: a sphere "probe_tip"
// at the tool point, the drogue's plates "drogue0".. and "drogue_floor" on the target, contact
// between them only (predefined pairs), and an inactive weld "berth" of the gripper to the target.
#include <string>

#include "model/arm.hpp"

namespace chaser::plant::multibody {

std::string mjcf_of(const model::MultibodySceneParams& scene);

}  // namespace chaser::plant::multibody
