#pragma once
// Engaging a weld at the pose its bodies have now. A MuJoCo weld holds the relative pose stored in
// its eq_data, which the compiler fills from the bodies' pose at qpos0: engaged as compiled, it
// would drag the bodies to where they were at qpos0. MuJoCo 2.2.2's weld (body1, body2) reads
// eq_data as [0:3] the anchor in body2's frame, [3:6] the point of body1's frame that must coincide
// with it, [6:10] body2's attitude relative to body1 (w, x, y, z), [10] the torque scale; its error
// is (x1 + R1 p - x2 - R2 a, the vector part of q2^-1 q1 q_rel). With the anchor at body2's origin,
// the pose now is p = R1^T (x2 - x1), q_rel = q1^-1 q2 (tests/plant/multibody/weld_test.cpp checks
// this reading: the engaged weld holds the pose of its moment, not qpos0's).
#include "plant/multibody/mujoco_model.hpp"

namespace chaser::plant::multibody {

// Writes the weld `equality`'s relative pose from its bodies' poses now (after MuJoCo's kinematics
// of the current qpos) and activates it; the torque scale stays the model's.
void engage_weld_here(MujocoModel& world, int equality);
// Deactivates it.
void release_weld(MujocoModel& world, int equality);
bool weld_engaged(const MujocoModel& world, int equality);

// The relative pose a weld holds (anchor at body2's origin): body2's origin in body1's frame and
// body2's attitude relative to body1; written, it is what the weld pulls the bodies to from the
// next step on (a weld drawn from one pose to another: the berthing's retraction).
struct WeldPose {
  Vec3 p_m = Vec3::Zero();
  Quat q_rel = Quat::Identity();
};
WeldPose weld_pose(const MujocoModel& world, int equality);
void set_weld_pose(MujocoModel& world, int equality, const WeldPose& pose);
// The weld's stiffness: MuJoCo's solref (time constant [s], damping ratio 1).
void set_weld_timeconst(MujocoModel& world, int equality, double timeconst_s);

}  // namespace chaser::plant::multibody
