#include "plant/arm_joints.hpp"

#include <algorithm>
#include <stdexcept>
#include <cmath>

#include <mujoco/mujoco.h>

#include "core/rotation.hpp"
#include "plant/handover.hpp"
#include "plant/multibody/mujoco_errors.hpp"
#include "plant/multibody_motion.hpp"

namespace chaser::plant {

namespace {

const MultibodyMotionParams* multibody_params(const PlantParams& params) {
  return std::get_if<MultibodyMotionParams>(&params.motion);
}
const MultibodyMotionParams* multibody_params(const Plant& plant) { return multibody_params(plant.params); }

}  // namespace

std::optional<std::string> wake_arm(Plant& plant, const model::Scenario& scenario, double scene_timestep_s) {
  if (auto problem = hand_over_to_multibody(plant, scenario, scene_timestep_s)) return problem;
  lock_arm(std::get<MultibodyMotionParams>(plant.params.motion), std::get<MultibodyMotionState>(plant.state.motion),
           false);
  return std::nullopt;
}

bool arm_awake(const Plant& plant) { return multibody_params(plant) != nullptr; }

model::ArmMeasurements sense_arm(const Plant& plant) { return sense_arm(plant.params, plant.state); }

model::ArmMeasurements sense_arm(const PlantParams& params, const PlantState& state) {
  model::ArmMeasurements m;
  const MultibodyMotionParams* p = multibody_params(params);
  if (p == nullptr) return m;
  const auto& s = std::get<MultibodyMotionState>(state.motion);
  const auto q = joint_angles_rad(*p, s), w = joint_rates_radps(*p, s), tau = joint_torques_applied_Nm(*p, s);
  m.joints = model::kArmJoints;
  for (std::size_t j = 0; j < q.size(); ++j) {
    m.q_rad[j] = q[j];
    m.q_dot_radps[j] = w[j];
    m.torque_Nm[j] = tau[j];
  }
  const JawReading jaws = read_jaws(*p, s);
  m.gripper_closed = jaws.holding;
  m.gripper_opening_m = jaws.opening_m;
  m.gripper_locked = grasp_engaged(*p, s);
  m.brakes_engaged = s.brakes_engaged;
  m.probe_latched = probe_latched(s);
  m.probe_hard_docked = probe_hard_docked(s);
  return m;
}

std::array<double, model::kArmJoints> brake_loads_Nm(const Plant& plant) {
  const MultibodyMotionParams* p = multibody_params(plant);
  if (p == nullptr) return {};
  return brake_loads_Nm(*p, std::get<MultibodyMotionState>(plant.state.motion));
}

const BerthState* berth_truth(const Plant& plant) {
  if (multibody_params(plant) == nullptr) return nullptr;
  return &std::get<MultibodyMotionState>(plant.state.motion).berth;
}

void set_closed_chain_joint_rates(Plant& plant, const std::array<double, model::kArmJoints>& rates_radps) {
  const MultibodyMotionParams* p = multibody_params(plant);
  if (p == nullptr) throw std::logic_error("set_closed_chain_joint_rates: the arm is not awake");
  set_closed_chain_joint_rates(*p, std::get<MultibodyMotionState>(plant.state.motion), rates_radps);
}

void set_braked_step(Plant& plant, double step_s) {
  const MultibodyMotionParams* p = multibody_params(plant);
  if (p == nullptr) throw std::logic_error("set_braked_step: the arm is not awake");
  set_braked_step(*p, std::get<MultibodyMotionState>(plant.state.motion), step_s);
}

void command_arm(Plant& plant, const model::ArmCommand& command) {
  const MultibodyMotionParams* p = multibody_params(plant);
  if (p == nullptr) return;
  auto& s = std::get<MultibodyMotionState>(plant.state.motion);
  const double limit = p->scene.arm.torque_momentary_Nm;
  std::array<double, model::kArmJoints> torque{};
  for (std::size_t j = 0; j < torque.size(); ++j) torque[j] = std::clamp(command.torque_Nm[j], -limit, limit);
  set_joint_torques(s, torque);
  if (command.engage_brakes && !s.brakes_engaged) engage_brakes(*p, s);
  command_jaws(*p, s, command.close_gripper);
  // The rigid closure: the gripper welded to the fixture where the jaws hold it, never on nothing.
  if (command.lock_gripper && !grasp_engaged(*p, s) && read_jaws(*p, s).holding) engage_grasp(*p, s);
  if (command.retract_probe) command_probe_retraction(*p, s);
}

GripperTruth gripper_truth(const PlantParams& params, PlantState& state, const Vec3& point_target_m,
                           const Quat& q_target_from_pose) {
  const MultibodyMotionParams* p = multibody_params(params);
  if (p == nullptr) return {};
  auto& s = std::get<MultibodyMotionState>(state.motion);
  const mjModel* m = &s.world.model();
  mjData* d = &s.world.data();
  multibody::guarded("the gripper's truth", [m, d] {
    mj_kinematics(m, d);
    mj_comPos(m, d);
    mj_comVel(m, d);
  });
  const int site = mj_name2id(m, mjOBJ_SITE, "tool");
  const int target = p->index.target;
  double tool_velocity[6], target_velocity[6];  // (angular; linear), world axes, at the site / the body's CoM
  mj_objectVelocity(m, d, mjOBJ_SITE, site, tool_velocity, 0);
  mj_objectVelocity(m, d, mjOBJ_BODY, target, target_velocity, 0);
  Mat3 world_from_tool;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) world_from_tool(i, j) = d->site_xmat[9 * site + 3 * i + j];
  const Quat q_world_from_target = multibody::body_attitude(*d, target).normalized();
  const Quat q_world_from_pose = (q_world_from_target * q_target_from_pose).normalized();
  const Mat3 pose_from_world = q_world_from_pose.toRotationMatrix().transpose();
  const Vec3 omega_target = Eigen::Map<const Vec3>(target_velocity);
  const Vec3 offset = q_world_from_target * point_target_m;
  const Vec3 r_point = Eigen::Map<const Vec3>(d->xpos + 3 * target) + offset;
  const Vec3 v_point = Eigen::Map<const Vec3>(target_velocity + 3) + omega_target.cross(offset);
  GripperTruth out;
  out.r_m = pose_from_world * (Eigen::Map<const Vec3>(d->site_xpos + 3 * site) - r_point);
  out.v_mps = pose_from_world * (Eigen::Map<const Vec3>(tool_velocity + 3) - v_point);
  out.attitude_rad = rotation_vector_from_quat(q_world_from_pose.conjugate() * Quat(world_from_tool));
  out.omega_radps = pose_from_world * (Eigen::Map<const Vec3>(tool_velocity) - omega_target);
  return out;
}

ArmFigure arm_figure(const PlantParams& params, PlantState& state) {
  const MultibodyMotionParams* p = multibody_params(params);
  if (p == nullptr) return {};
  auto& s = std::get<MultibodyMotionState>(state.motion);
  const mjModel* m = &s.world.model();
  mjData* d = &s.world.data();
  multibody::guarded("the arm's figure", [m, d] { mj_kinematics(m, d); });
  const int target = p->index.target, hub = p->index.hub;
  const Vec3 r_target = multibody::body_position(*d, target);
  const Quat q_world_from_target = multibody::body_attitude(*d, target).normalized();
  const Quat q_world_from_hub = multibody::body_attitude(*d, hub).normalized();
  const Mat3 target_from_world = q_world_from_target.toRotationMatrix().transpose();
  const auto in_target = [&](const Vec3& world_m) { return Vec3(target_from_world * (world_m - r_target)); };
  const auto point = [](const double* xyz) { return Vec3(xyz[0], xyz[1], xyz[2]); };
  ArmFigure out;
  // The hub's MuJoCo frame is at its CoM (plant/multibody/mjcf.cpp): the body frame's origin is
  // hub_com_body_m behind it.
  out.hub_m = in_target(multibody::body_position(*d, hub) - q_world_from_hub * p->scene.hub_com_body_m);
  out.q_target_from_hub = (q_world_from_target.conjugate() * q_world_from_hub).normalized();
  const int joint1 = mj_name2id(m, mjOBJ_JOINT, "joint1");
  for (int j = 0; j < model::kArmJoints; ++j)
    out.joint_m[static_cast<std::size_t>(j)] = in_target(point(d->xanchor + 3 * (joint1 + j)));  // joint1..7 in a row
  out.tool_m = in_target(point(d->site_xpos + 3 * mj_name2id(m, mjOBJ_SITE, "tool")));
  return out;
}

std::optional<model::ArmMeasurements> sense_arm_with_camera(const PlantParams& params, PlantState& state, double t_s) {
  if (multibody_params(params) == nullptr || !params.sensors.arm_camera) return std::nullopt;
  const model::ArmCameraParams& camera = *params.sensors.arm_camera;
  model::ArmMeasurements m = sense_arm(params, state);
  m.fixture = sample_with_latency(
      camera.period_s, camera.latency_s, t_s, state.sensors.arm_camera_next_s, state.sensors.arm_camera_pending,
      [&](double taken_s) {
        const GripperTruth g = gripper_truth(params, state, params.fixture_target_m, params.q_target_from_fixture);
        // The fixture in camera (tool) axes: q_camera_from_fixture = (q_fixture^-1 q_tool)^-1, and
        // its origin from the camera, -R_camera_from_fixture r (r the tool from the fixture, fixture axes).
        const Quat q_camera_from_fixture = quat_from_rotation_vector(g.attitude_rad).conjugate();
        const Vec3 r_camera_m = q_camera_from_fixture * (-g.r_m);
        const Vec3 r_eye_m = r_camera_m + Vec3(camera.setback_m, 0.0, 0.0);  // the fixture from the camera's eye
        const double range_m = r_eye_m.norm();
        RandomStream& noise = state.streams.arm_camera;  // drawn whether or not the fixture is seen
        const Vec3 position_error(noise.normal(), noise.normal(), noise.normal());
        const Vec3 attitude_error(noise.normal(), noise.normal(), noise.normal());
        model::RelativePoseMeasurement sample;
        sample.valid = range_m <= camera.range_max_m && range_m > 0.0 &&
                       r_eye_m.x() >= range_m * std::cos(camera.fov_half_angle_rad);
        sample.taken_s = taken_s;
        sample.r_camera_m = r_camera_m + camera.position_bias_m + camera.position_noise_m * position_error;
        sample.q_camera_from_fixture =
            (q_camera_from_fixture * quat_from_rotation_vector(camera.attitude_noise_rad * attitude_error)).normalized();
        return sample;
      });
  return m;
}

}  // namespace chaser::plant
