#pragma once
// The servicer's arm as the plant has it: woken (the multibody plant takes over and the joints'
// locks open), its joint sensors read and its joint torques commanded, and the truth of where the
// gripper is against the fixture (for the mission monitor, never for the flight software).
#include <array>
#include <optional>
#include <string>

#include "core/types.hpp"
#include "model/messages.hpp"
#include "model/scenario.hpp"
#include "plant/plant.hpp"

namespace chaser::plant {

// The arm wakes: the perturbed Earth-orbit plant hands its bodies to the multibody one (the arm
// stowed, at rest relative to the hub: plant/handover.hpp) and the joints' locks open. Returns why
// it cannot, or nothing.
std::optional<std::string> wake_arm(Plant& plant, const model::Scenario& scenario, double scene_timestep_s = 1e-3);

// Whether the plant flies the multibody scene with its arm free.
bool arm_awake(const Plant& plant);

// The joint sensors now: angles and rates as the joints are (the encoders' noise, ~1e-5 rad, is
// below everything the capture is judged by, and not modelled), the torques last commanded.
model::ArmMeasurements sense_arm(const Plant& plant);
model::ArmMeasurements sense_arm(const PlantParams& params, const PlantState& state);

// Braked, each joint's load [N m]: the torque its brake carries, at the last MuJoCo step's start
// (plant/multibody_motion.hpp); zeros before the brakes engage or without the arm awake. Truth,
// for judging the loads against the drives' limits, never a sensor.
std::array<double, model::kArmJoints> brake_loads_Nm(const Plant& plant);

// ASSIST's berthing as the plant has it (plant/multibody_motion.hpp's BerthState): truth, for
// judging the docking and its loads, never a sensor. Null without the arm awake.
const BerthState* berth_truth(const Plant& plant);

// With the grasp engaged on the multibody plant: the joints' rates set, the hub and the target
// moving so that the weld holds and the scene's momentum is kept (plant/multibody_motion.hpp's
// set_closed_chain_joint_rates). Throws std::logic_error otherwise.
void set_closed_chain_joint_rates(Plant& plant, const std::array<double, model::kArmJoints>& rates_radps);

// Braked, MuJoCo's step from the next advance on (plant/multibody_motion.hpp's set_braked_step).
// Throws std::logic_error without the arm awake and braked.
void set_braked_step(Plant& plant, double step_s);

// The joint torques held from now to the next command, each clamped at the drive's hard limit
// (chaser.arm.torque_momentary_Nm): the inner torque loop cannot give more.
void command_arm(Plant& plant, const model::ArmCommand& command);

// The gripper against a pose fixed on the target (the fixture, or the pre-grasp pose short of it),
// true values, in the axes of that pose (x the tool's approach axis): the tool point's position
// and its velocity relative to the pose's point (the difference of the two points' inertial
// velocities), the rotation vector of q_pose^-1 q_tool, and the tool's angular velocity less the
// target's. Refreshes MuJoCo's positions and velocities derived from the state (mj_kinematics,
// mj_comPos, mj_comVel, which every step recomputes first): the state and the run are unchanged.
struct GripperTruth {
  Vec3 r_m = Vec3::Zero();
  Vec3 v_mps = Vec3::Zero();
  Vec3 attitude_rad = Vec3::Zero();
  Vec3 omega_radps = Vec3::Zero();
};
// point_target_m, q_target_from_pose: the pose on the target (target axes, from its CoM).
GripperTruth gripper_truth(const PlantParams& params, PlantState& state, const Vec3& point_target_m,
                           const Quat& q_target_from_pose);
inline GripperTruth gripper_truth(Plant& plant, const Vec3& point_target_m, const Quat& q_target_from_pose) {
  return gripper_truth(plant.params, plant.state, point_target_m, q_target_from_pose);
}

// The arm's figure, true, in the target's axes from its CoM: the chaser's body-frame origin (the
// reference point thrusters and mount are given from) and the hub's attitude,
// each joint's anchor (a point on its axis) and the tool point. For drawing the capture
// (python/plot_reach.py's stick figures), never for the flight software. Refreshes MuJoCo's
// positions derived from the state (mj_kinematics): the state and the run are unchanged.
struct ArmFigure {
  Vec3 hub_m = Vec3::Zero();
  Quat q_target_from_hub = Quat::Identity();
  std::array<Vec3, model::kArmJoints> joint_m{};
  Vec3 tool_m = Vec3::Zero();
};
ArmFigure arm_figure(const PlantParams& params, PlantState& state);
inline ArmFigure arm_figure(Plant& plant) { return arm_figure(plant.params, plant.state); }

// The joint sensors (sense_arm) and the arm camera's sample at the control period starting at t_s
// (model::ArmCameraParams): taken when its period has come, if the fixture (PlantParams'
// fixture frame) is inside the camera's cone and range, and delivered once its latency has passed.
// Nothing before the arm wakes.
std::optional<model::ArmMeasurements> sense_arm_with_camera(const PlantParams& params, PlantState& state, double t_s);

}  // namespace chaser::plant
