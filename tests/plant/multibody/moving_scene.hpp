#pragma once
// The tests' moving scene: the default scene with the hub's and ENVISAT's inertias, ENVISAT drifting
// at 1 cm/s and spinning at 2.5 deg/s (COMRADE's tumble: |p| = 78 kg m/s, |L| ~ 5,400 kg m^2/s),
// the hub at rest, the arm bent; and the joints' drive, each a 2 N m sine of its own frequency,
// small enough that no joint reaches its limit.
#include <cmath>
#include <numbers>

#include "model/arm.hpp"
#include "plant/multibody/mjcf.hpp"
#include "plant/multibody/mujoco_model.hpp"

namespace chaser::plant::multibody {

inline MujocoModel moving_scene(model::MultibodySceneParams scene) {
  scene.hub_inertia_kgm2 = Vec3(1850.0, 1900.0, 1300.0).asDiagonal();
  scene.target_inertia_kgm2 << 17023.0, 397.0, -2171.0, 397.0, 124826.0, 344.0, -2171.0, 344.0, 129112.0;
  MujocoModel model(mjcf_of(scene));
  mjData& d = model.data();
  const int target_dof = model.model().jnt_dofadr[model.joint("target_free")];
  d.qvel[target_dof + 0] = 0.01;
  d.qvel[target_dof + 4] = 2.5 * std::numbers::pi / 180.0;
  const int joint1 = model.model().jnt_qposadr[model.joint("joint1")];
  for (int j = 0; j < model::kArmJoints; ++j) d.qpos[joint1 + j] = 0.3 * std::sin(j + 1.0);
  model.forward();
  return model;
}

// The joints' drive at the model's time: each joint a 2 N m sine of its own frequency.
inline void drive_joints(MujocoModel& model) {
  mjData& d = model.data();
  for (int j = 0; j < model::kArmJoints; ++j) d.ctrl[j] = 2.0 * std::sin((1.0 + 0.7 * j) * d.time);
}

}  // namespace chaser::plant::multibody
