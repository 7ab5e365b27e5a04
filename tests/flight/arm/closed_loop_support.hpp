#pragma once
// The arm's control laws flying MuJoCo's scene (the plant's truth model, an independent integrator
// of the same bodies): the state read from MuJoCo, a law's generalized force held over each 1 ms
// step (the joints' rate in COMRADE 2018, sec. 6.2.1), MuJoCo's RK4 at that step; and the capture's
// reference, a tool path in a tumbling target's frame.
#include <algorithm>
#include <cmath>

#include <mujoco/mujoco.h>

#include "core/rotation.hpp"
#include "flight/arm/arm_kinematics.hpp"
#include "flight/arm/task_space.hpp"
#include "plant/multibody/mjcf.hpp"
#include "plant/multibody/mujoco_model.hpp"
#include "tests/flight/arm/arm_test_support.hpp"

namespace chaser::flight::arm::testing {

struct Measured {
  Vec3 r_hub_world_m;
  Quat q_world_from_hub;
  JointVector joint_angles_rad;
  ServicerVector velocity;
};

inline Measured measure(const plant::multibody::MujocoModel& mujoco) {
  const mjData& d = mujoco.data();
  Measured m;
  m.r_hub_world_m = Vec3(d.qpos[0], d.qpos[1], d.qpos[2]);
  m.q_world_from_hub = Quat(d.qpos[3], d.qpos[4], d.qpos[5], d.qpos[6]);
  for (int i = 0; i < model::kArmJoints; ++i) m.joint_angles_rad(i) = d.qpos[7 + i];
  for (int k = 0; k < kServicerDofs; ++k) m.velocity(k) = d.qvel[k];
  return m;
}

// The joints' friction off: the laws' nominal closed loop (friction only dissipates, but it holds
// the arm where the springs' pull falls below it).
inline model::MultibodySceneParams frictionless_scene() {
  model::MultibodySceneParams scene = default_scene();
  for (model::ArmLinkParams& link : scene.arm.links) link.friction_Nm = 0.0;
  return scene;
}

// The scene's servicer at rest, the arm stowed; the target far away (contact is off in the scene).
struct Loop {
  model::MultibodySceneParams scene = frictionless_scene();
  plant::multibody::MujocoModel mujoco{plant::multibody::mjcf_of(scene)};
  ServicerArmParams params = servicer_arm_as_compiled(scene, mujoco);

  Loop() {
    Configuration c;
    for (int i = 0; i < model::kArmJoints; ++i)
      c.joint_angles_rad(i) = scene.arm.stowed_rad[static_cast<std::size_t>(i)];
    set_state(mujoco, c);
  }
  Measured measured() const { return measure(mujoco); }
  ArmKinematics kinematics() const {
    const Measured m = measured();
    return arm_kinematics(params, m.r_hub_world_m, m.q_world_from_hub, m.joint_angles_rad);
  }
  // One 1 ms step with the generalized force held.
  void step(const ServicerVector& generalized_force) {
    for (int k = 0; k < kServicerDofs; ++k) mujoco.data().qfrc_applied[k] = generalized_force(k);
    mujoco.step();
  }
};

inline FrameMotion at_rest(const Vec3& r_m, const Quat& q) {
  FrameMotion f;
  f.r_m = r_m;
  f.q_world_from_frame = q;
  return f;
}

// A quintic blend s(t) from 0 to 1 over [0, T] with zero rate and acceleration at both ends.
struct Blend {
  double s, rate, acceleration;
};
inline Blend quintic(double t, double duration) {
  if (t >= duration) return {1.0, 0.0, 0.0};
  const double x = std::clamp(t / duration, 0.0, 1.0);
  return {x * x * x * (10.0 - 15.0 * x + 6.0 * x * x), 30.0 * x * x * (1.0 - x) * (1.0 - x) / duration,
          60.0 * x * (1.0 - x) * (1.0 - 2.0 * x) / (duration * duration)};
}

// The capture's reference from a servicer at rest: the target's frame T 4.5 m ahead of the hub,
// turning at 4.6 deg/s about an axis close to the line to the hub (a synchronised hold sits on the
// target's angular-momentum axis); in T, the hub where it starts, and the tool from where it starts,
// in 20 s, to where the arm puts it half unfolded (elbow -60 deg, wrist -40 deg: the path keeps
// clear of the wrist's singularity at 0 deg, where a roll-pitch-roll wrist loses a direction, and
// of the joints' limits). The hub starts at rest beside a reference moving at 0.14 m/s.
class TumblingReach {
 public:
  TumblingReach(const ServicerArmParams& params, const ArmKinematics& start) {
    target_.r_m = start.r_hub_world_m + Vec3(4.5, 0.0, 0.0);
    target_.omega_radps = Vec3(4.0, 1.0, -1.5) * model::kArmDegToRad;
    hub_in_target_ = at_rest(Vec3(-4.5, 0.0, 0.0), Quat(start.world_from_hub));
    JointVector unfolded;
    unfolded << 0.2, 50.0 * model::kArmDegToRad, 0.0, -60.0 * model::kArmDegToRad, 0.1,
        -40.0 * model::kArmDegToRad, 0.1;
    const ArmKinematics goal = arm_kinematics(params, start.r_hub_world_m, Quat(start.world_from_hub), unfolded);
    tool_from_m_ = start.r_tool_world_m - target_.r_m;
    tool_to_m_ = goal.r_tool_world_m - target_.r_m;
    tool_from_q_ = Quat(start.world_from_link[6]);
    turn_ = Eigen::AngleAxisd(tool_from_q_.conjugate() * Quat(goal.world_from_link[6]));  // in the start's axes
  }

  TaskReference at(double t) const {
    FrameMotion target = target_;
    target.q_world_from_frame = quat_from_rotation_vector(target_.omega_radps * t);
    const Blend b = quintic(t, 20.0);
    FrameMotion tool;
    tool.r_m = tool_from_m_ + b.s * (tool_to_m_ - tool_from_m_);
    tool.v_mps = b.rate * (tool_to_m_ - tool_from_m_);
    tool.a_mps2 = b.acceleration * (tool_to_m_ - tool_from_m_);
    const Vec3 axis_parent = tool_from_q_ * turn_.axis();
    tool.q_world_from_frame = tool_from_q_ * Quat(Eigen::AngleAxisd(b.s * turn_.angle(), turn_.axis()));
    tool.omega_radps = b.rate * turn_.angle() * axis_parent;
    tool.alpha_radps2 = b.acceleration * turn_.angle() * axis_parent;
    TaskReference reference;
    reference.hub = compose(target, hub_in_target_);
    reference.tool = compose(target, tool);
    return reference;
  }

 private:
  FrameMotion target_, hub_in_target_;
  Vec3 tool_from_m_, tool_to_m_;
  Quat tool_from_q_;
  Eigen::AngleAxisd turn_;
};

}  // namespace chaser::flight::arm::testing
