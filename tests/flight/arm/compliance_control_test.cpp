// The combined compliance controller flying MuJoCo's scene (the plant's truth model, an independent
// integrator of the same bodies): hub and arm with every generalized force applied as the law
// commands it, held over each 1 ms step (the joints' rate in COMRADE 2018, sec. 6.2.1), MuJoCo's
// RK4 at that step.
//
// - Regulation: from the stowed arm to a grasping pose, the law's storage function V never rises
//   by more than the sampling allows, and the errors vanish. The bound: over one 1 ms step the held
//   torque's work differs from the continuous law's by O(h^2 |tau'| |v|), allowed 1e-6 V(0) per
//   step; measured: a largest rise of 3.1e-8 J from V(0) = 96 J, V(40 s) = 1.3e-5 J.
// - Tracking: the capture's reference, the hub at a point of a tumbling target frame (4.6 deg/s)
//   and the tool following a smooth path in that frame, the hub starting at rest: the errors decay
//   as the tasks' bandwidths say, feedforward doing the rest (no lag is left while the frame turns).
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include "core/rotation.hpp"
#include "flight/arm/compliance_control.hpp"
#include "plant/multibody/mjcf.hpp"
#include "plant/multibody/mujoco_model.hpp"
#include "tests/flight/arm/arm_test_support.hpp"

namespace chaser::flight::arm {
namespace {

using plant::multibody::MujocoModel;
using plant::multibody::mjcf_of;

struct Measured {
  Vec3 r_hub_world_m;
  Quat q_world_from_hub;
  JointVector joint_angles_rad;
  ServicerVector velocity;
};

Measured measure(const MujocoModel& mujoco) {
  const mjData& d = mujoco.data();
  Measured m;
  m.r_hub_world_m = Vec3(d.qpos[0], d.qpos[1], d.qpos[2]);
  m.q_world_from_hub = Quat(d.qpos[3], d.qpos[4], d.qpos[5], d.qpos[6]);
  for (int i = 0; i < model::kArmJoints; ++i) m.joint_angles_rad(i) = d.qpos[7 + i];
  for (int k = 0; k < kServicerDofs; ++k) m.velocity(k) = d.qvel[k];
  return m;
}

// The scene's servicer at rest, the arm stowed; the target far away (contact is off in the scene).
// The joints' friction off: the law's nominal closed loop (friction only dissipates, but it holds
// the arm where the springs' pull falls below it).
model::MultibodySceneParams frictionless_scene() {
  model::MultibodySceneParams scene = testing::default_scene();
  for (model::ArmLinkParams& link : scene.arm.links) link.friction_Nm = 0.0;
  return scene;
}

struct Loop {
  model::MultibodySceneParams scene = frictionless_scene();
  MujocoModel mujoco{mjcf_of(scene)};
  ServicerArmParams params = testing::servicer_arm_as_compiled(scene, mujoco);

  Loop() {
    testing::Configuration c;
    for (int i = 0; i < model::kArmJoints; ++i)
      c.joint_angles_rad(i) = scene.arm.stowed_rad[static_cast<std::size_t>(i)];
    testing::set_state(mujoco, c);
  }
  ArmKinematics kinematics() const {
    const Measured m = measure(mujoco);
    return arm_kinematics(params, m.r_hub_world_m, m.q_world_from_hub, m.joint_angles_rad);
  }
  // One 1 ms step under the law; returns the law's output at the step's start.
  ComplianceOutput step(const TaskReference& reference, const ComplianceGains& gains) {
    const Measured m = measure(mujoco);
    const ComplianceOutput out =
        compliance_control(params, arm_kinematics(params, m.r_hub_world_m, m.q_world_from_hub, m.joint_angles_rad),
                           m.joint_angles_rad, m.velocity, reference, gains);
    for (int k = 0; k < kServicerDofs; ++k) mujoco.data().qfrc_applied[k] = out.generalized_force(k);
    mujoco.step();
    return out;
  }
};

FrameMotion at_rest(const Vec3& r_m, const Quat& q) {
  FrameMotion f;
  f.r_m = r_m;
  f.q_world_from_frame = q;
  return f;
}

TEST(ComplianceControl, RegulatesToAGraspingPoseWithANonIncreasingStorage) {
  Loop loop;
  const ArmKinematics start = loop.kinematics();
  TaskReference reference;
  reference.hub = at_rest(start.r_hub_world_m, Quat(start.world_from_hub));
  // The grasping pose: the tool 1.2 m further ahead and 0.3 m aside, pointing along the hub's +x.
  reference.tool = at_rest(Vec3(3.2, 0.3, -0.2), Quat::Identity());
  reference.joint_rad = 0.0;
  const ComplianceGains gains = compliance_gains(loop.params, start, ComplianceBandwidths{});
  ASSERT_TRUE(validate(gains).empty());

  double storage = loop.step(reference, gains).storage_J;
  const double storage_start = storage;
  double worst_rise_J = 0.0;
  ComplianceOutput out;
  for (int n = 1; n < 40'000; ++n) {
    out = loop.step(reference, gains);
    worst_rise_J = std::max(worst_rise_J, out.storage_J - storage);
    storage = out.storage_J;
  }
  EXPECT_GT(storage_start, 50.0);
  EXPECT_LT(worst_rise_J, 1e-6 * storage_start);
  EXPECT_LT(out.errors.pose.segment<3>(6).norm(), 1e-4);  // [m]
  EXPECT_LT(out.errors.pose.segment<3>(9).norm(), 1e-4);  // [-] eps, half the angle: 0.01 deg
  EXPECT_LT(out.errors.pose.head<3>().norm(), 1e-4);
  EXPECT_LT(out.errors.velocity.norm(), 1e-3);
  EXPECT_LT(storage, 1e-6 * storage_start);
  std::printf("storage %.3f J -> %.3e J, worst rise per step %.3e J, tool error %.3e m\n", storage_start, storage,
              worst_rise_J, out.errors.pose.segment<3>(6).norm());
}

// A quintic blend s(t) from 0 to 1 over [0, T] with zero rate and acceleration at both ends.
struct Blend {
  double s, rate, acceleration;
};
Blend quintic(double t, double duration) {
  const double x = std::clamp(t / duration, 0.0, 1.0);
  if (t >= duration) return {1.0, 0.0, 0.0};
  return {x * x * x * (10.0 - 15.0 * x + 6.0 * x * x), 30.0 * x * x * (1.0 - x) * (1.0 - x) / duration,
          60.0 * x * (1.0 - x) * (1.0 - 2.0 * x) / (duration * duration)};
}

TEST(ComplianceControl, TracksAToolPathInATumblingFrame) {
  Loop loop;
  const ArmKinematics start = loop.kinematics();
  // The target's frame T: 4.5 m ahead of the hub, turning at 4.6 deg/s about an axis close to the
  // line to the hub (a synchronised hold sits on the target's angular-momentum axis).
  FrameMotion target;
  target.r_m = start.r_hub_world_m + Vec3(4.5, 0.0, 0.0);
  target.omega_radps = Vec3(4.0, 1.0, -1.5) * model::kArmDegToRad;
  const auto target_at = [&target](double t) {
    FrameMotion f = target;
    f.q_world_from_frame = quat_from_rotation_vector(target.omega_radps * t);
    return f;
  };
  // In T: the hub where it starts; the tool from where it starts, in 20 s, to where the arm puts it
  // half unfolded (elbow -60 deg, wrist -40 deg: the path keeps clear of the wrist's singularity
  // at 0 deg, where a roll-pitch-roll wrist loses a direction, and of the joints' limits).
  const FrameMotion hub_in_target = at_rest(Vec3(-4.5, 0.0, 0.0), Quat(start.world_from_hub));
  JointVector unfolded;
  unfolded << 0.2, 50.0 * model::kArmDegToRad, 0.0, -60.0 * model::kArmDegToRad, 0.1, -40.0 * model::kArmDegToRad, 0.1;
  const ArmKinematics goal = arm_kinematics(loop.params, start.r_hub_world_m, Quat(start.world_from_hub), unfolded);
  const Vec3 tool_from_m = start.r_tool_world_m - target.r_m, tool_to_m = goal.r_tool_world_m - target.r_m;
  const Quat tool_from_q(start.world_from_link[6]);
  const Eigen::AngleAxisd turn(tool_from_q.conjugate() * Quat(goal.world_from_link[6]));  // in the start's axes
  const auto tool_in_target_at = [&](double t) {
    const Blend b = quintic(t, 20.0);
    FrameMotion f;
    f.r_m = tool_from_m + b.s * (tool_to_m - tool_from_m);
    f.v_mps = b.rate * (tool_to_m - tool_from_m);
    f.a_mps2 = b.acceleration * (tool_to_m - tool_from_m);
    const Vec3 axis_parent = tool_from_q * turn.axis();
    f.q_world_from_frame = tool_from_q * Quat(Eigen::AngleAxisd(b.s * turn.angle(), turn.axis()));
    f.omega_radps = b.rate * turn.angle() * axis_parent;
    f.alpha_radps2 = b.acceleration * turn.angle() * axis_parent;
    return f;
  };
  const ComplianceGains gains = compliance_gains(loop.params, start, ComplianceBandwidths{});
  double worst_tool_m = 0.0, worst_tool_eps = 0.0, worst_hub_m = 0.0;
  ComplianceOutput out;
  for (int n = 0; n < 40'000; ++n) {
    const double t = n * 1e-3;
    TaskReference reference;
    reference.hub = compose(target_at(t), hub_in_target);
    reference.tool = compose(target_at(t), tool_in_target_at(t));
    out = loop.step(reference, gains);
    if (t < 25.0) continue;  // the hub starts at rest beside a reference moving at 0.14 m/s
    worst_tool_m = std::max(worst_tool_m, out.errors.pose.segment<3>(6).norm());
    worst_tool_eps = std::max(worst_tool_eps, out.errors.pose.segment<3>(9).norm());
    worst_hub_m = std::max(worst_hub_m, out.errors.pose.head<3>().norm());
  }
  // From 25 s on: the tool within 0.1 mm and 0.01 deg of its path, the hub (its task tuned to
  // 0.5 rad/s, critically damped) within 1 mm and closing; at 40 s both within 0.1 mm.
  EXPECT_LT(worst_tool_m, 1e-4);
  EXPECT_LT(worst_tool_eps, 1e-4);
  EXPECT_LT(worst_hub_m, 1e-3);
  EXPECT_LT(out.errors.pose.head<3>().norm(), 1e-4);
  EXPECT_LT(out.errors.pose.segment<3>(6).norm(), 1e-5);
  std::printf("after 25 s: tool %.3e m, eps %.3e, hub %.3e m; at 40 s: hub %.3e m, tool %.3e m\n", worst_tool_m,
              worst_tool_eps, worst_hub_m, out.errors.pose.head<3>().norm(), out.errors.pose.segment<3>(6).norm());
}

}  // namespace
}  // namespace chaser::flight::arm
