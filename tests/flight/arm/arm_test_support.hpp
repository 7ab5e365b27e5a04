#pragma once
// The scenes and configurations the flight model of the arm is held to, and the same state set in
// MuJoCo's model of the scene (plant/multibody), the reference.
#include <cmath>
#include <vector>

#include <mujoco/mujoco.h>

#include "core/random.hpp"
#include "core/rotation.hpp"
#include "core/types.hpp"
#include "flight/arm/servicer_arm.hpp"
#include "model/arm.hpp"
#include "plant/multibody/mujoco_model.hpp"

namespace chaser::flight::arm::testing {

// The default arm on a hub with a full inertia tensor (products of inertia exercise every term of
// the hub's block).
inline model::MultibodySceneParams default_scene() {
  model::MultibodySceneParams scene;
  scene.hub_inertia_kgm2 << 1850.0, 35.0, -60.0, 35.0, 1900.0, 25.0, -60.0, 25.0, 1300.0;
  return scene;
}

// The default arm made general: the hub's CoM off its reference point, axes off the link axes,
// CoMs and joints off the link's x axis, a tool point off-axis, so that no term of the kinematics or the inertias vanishes by symmetry.
inline model::MultibodySceneParams skewed_scene() {
  model::MultibodySceneParams scene = default_scene();
  scene.arm.mount_body_m = Vec3(1.05, 0.2, -0.15);
  scene.hub_com_body_m = Vec3(0.03, -0.02, 0.05);
  for (int i = 0; i < model::kArmJoints; ++i) {
    model::ArmLinkParams& link = scene.arm.links[static_cast<std::size_t>(i)];
    const double s = 0.1 * (i + 1);
    link.joint_axis += Vec3(0.3 * std::sin(i + 1.0), 0.2 * std::cos(2.0 * i), 0.25 * s);
    link.joint_axis.normalize();
    link.joint_position_parent_m += Vec3(0.0, 0.05 * std::cos(i + 0.5), -0.04 * std::sin(i + 0.3));
    link.com_link_m += Vec3(0.02 * s, -0.03, 0.015 * i);
  }
  scene.arm.gripper.position_link7_m = Vec3(0.3, 0.04, -0.05);
  scene.arm.gripper.com_link7_m = Vec3(0.15, -0.02, 0.03);
  return scene;
}

inline std::vector<model::MultibodySceneParams> scenes() { return {default_scene(), skewed_scene()}; }

// The flight model of the scene as MuJoCo compiled it. MuJoCo 2.2.2 diagonalises a body's
// fullinertia at compile time (mju_eig3, Jacobi rotations) and keeps the principal moments and
// their axes (body_inertia, body_iquat); for default_scene()'s hub they give back the tensor only to
// 8e-5 kg m^2 (4e-8 of it), more than rounding. The flight model is held to the numbers MuJoCo
// flies, so that the comparison checks the algorithms, not MuJoCo's compiler.
inline ServicerArmParams servicer_arm_as_compiled(const model::MultibodySceneParams& scene,
                                                  const plant::multibody::MujocoModel& mujoco) {
  ServicerArmParams params = servicer_arm_of(scene);
  const mjModel& m = mujoco.model();
  const int hub = mujoco.body("hub");
  const Mat3 hub_from_principal =
      Quat(m.body_iquat[4 * hub], m.body_iquat[4 * hub + 1], m.body_iquat[4 * hub + 2], m.body_iquat[4 * hub + 3])
          .toRotationMatrix();
  params.hub_inertia_kgm2 =
      hub_from_principal * Vec3(m.body_inertia + 3 * hub).asDiagonal() * hub_from_principal.transpose();
  return params;
}

struct Configuration {
  Vec3 r_hub_world_m = Vec3::Zero();
  Quat q_world_from_hub = Quat::Identity();
  JointVector joint_angles_rad = JointVector::Zero();
  ServicerVector velocity = ServicerVector::Zero();  // (v_hub world, omega_hub hub axes, rates)
};

// Anywhere within 10 m of the origin, any attitude (uniform: a normalised 4-D normal draw), the
// joints uniform within their limits; velocities of a servicing approach's size or more.
inline Configuration random_configuration(RandomStream& random, const model::ArmParams& arm) {
  Configuration c;
  for (int k = 0; k < 3; ++k) c.r_hub_world_m(k) = random.uniform(-10.0, 10.0);
  c.q_world_from_hub = Quat(random.normal(), random.normal(), random.normal(), random.normal()).normalized();
  for (int i = 0; i < model::kArmJoints; ++i) {
    const model::ArmLinkParams& link = arm.links[static_cast<std::size_t>(i)];
    c.joint_angles_rad(i) = random.uniform(link.lower_rad, link.upper_rad);
  }
  for (int k = 0; k < 3; ++k) c.velocity(k) = random.normal(0.0, 0.5);
  for (int k = 3; k < 6; ++k) c.velocity(k) = random.normal(0.0, 0.2);
  for (int k = 6; k < kServicerDofs; ++k) c.velocity(k) = random.normal(0.0, 0.5);
  return c;
}

// The configuration moved by dt along v: the hub's origin by v dt (world), its attitude by
// omega dt in hub axes (q_world_from_hub exp(omega dt / 2)), the joints by their rates.
inline Configuration moved(const Configuration& c, double dt_s) {
  Configuration out = c;
  out.r_hub_world_m += dt_s * c.velocity.head<3>();
  out.q_world_from_hub = c.q_world_from_hub * quat_from_rotation_vector(dt_s * c.velocity.segment<3>(3));
  out.joint_angles_rad += dt_s * c.velocity.tail<model::kArmJoints>();
  return out;
}

// The hub's free joint first (qpos: position, quaternion w x y z; qvel: v world, omega body), the
// seven hinges next, then the target's free joint, left at rest.
inline void set_state(plant::multibody::MujocoModel& model, const Configuration& c) {
  mjData& d = model.data();
  for (int k = 0; k < 3; ++k) d.qpos[k] = c.r_hub_world_m(k);
  d.qpos[3] = c.q_world_from_hub.w();
  d.qpos[4] = c.q_world_from_hub.x();
  d.qpos[5] = c.q_world_from_hub.y();
  d.qpos[6] = c.q_world_from_hub.z();
  for (int i = 0; i < model::kArmJoints; ++i) d.qpos[7 + i] = c.joint_angles_rad(i);
  for (int k = 0; k < kServicerDofs; ++k) d.qvel[k] = c.velocity(k);
  for (int k = kServicerDofs; k < model.model().nv; ++k) d.qvel[k] = 0.0;
  model.forward();
}

}  // namespace chaser::flight::arm::testing
