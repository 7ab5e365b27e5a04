// The grasp's weld (plant/multibody/weld.hpp) on the scene with everything moving: ENVISAT drifting
// and tumbling, the arm driven. Engaged, it holds the gripper's pose relative to the target of the
// moment it engaged (which checks the reading of MuJoCo 2.2.2's eq_data), where engaged as compiled
// it drags the bodies towards their qpos0 pose; its forces are internal (the scene's momentum is
// kept) and, engaging with relative motion, it is an inelastic impact (kinetic energy only falls).
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "model/arm.hpp"
#include "plant/multibody/mjcf.hpp"
#include "plant/multibody/mujoco_model.hpp"
#include "plant/multibody/weld.hpp"
#include "tests/plant/multibody/moving_scene.hpp"

namespace chaser::plant::multibody {
namespace {

struct RelativePose {
  Vec3 p_m;  // the target's CoM in the gripper's frame
  Quat q;    // the target's attitude relative to the gripper's
};

RelativePose gripper_to_target(MujocoModel& model) {
  mjData& d = model.data();
  mj_kinematics(&model.model(), &d);
  const int g = model.body("gripper"), t = model.body("target");
  const Vec3 xg(d.xpos[3 * g], d.xpos[3 * g + 1], d.xpos[3 * g + 2]), xt(d.xpos[3 * t], d.xpos[3 * t + 1], d.xpos[3 * t + 2]);
  const Quat qg(d.xquat[4 * g], d.xquat[4 * g + 1], d.xquat[4 * g + 2], d.xquat[4 * g + 3]);
  const Quat qt(d.xquat[4 * t], d.xquat[4 * t + 1], d.xquat[4 * t + 2], d.xquat[4 * t + 3]);
  return {qg.conjugate() * (xt - xg), qg.conjugate() * qt};
}

// The moving scene (moving_scene.hpp) with the weld, the target 4 m ahead; `torques`: the joints
// driven, else no joint torque and no friction.
MujocoModel weld_scene(bool torques) {
  model::MultibodySceneParams scene;
  scene.grasp_weld = true;
  scene.target_position_m = Vec3(4.0, 0.5, -0.3);
  if (!torques)
    for (auto& link : scene.arm.links) link.friction_Nm = 0.0;
  return moving_scene(scene);
}

void step_for(MujocoModel& model, double seconds, bool torques) {
  const int steps = static_cast<int>(std::lround(seconds / model.model().opt.timestep));
  for (int k = 0; k < steps; ++k) {
    if (torques) drive_joints(model);
    model.step();
  }
}

double kinetic_energy_J(MujocoModel& model) {
  model.forward();
  const Eigen::Map<const Eigen::VectorXd> v(model.data().qvel, model.model().nv);
  return 0.5 * v.dot(model.mass_matrix() * v);
}

TEST(Weld, EngagedItHoldsThePoseOfItsMomentNotQpos0s) {
  MujocoModel model = weld_scene(true);
  const int grasp = mj_name2id(&model.model(), mjOBJ_EQUALITY, "grasp");
  ASSERT_GE(grasp, 0);
  EXPECT_FALSE(weld_engaged(model, grasp));
  step_for(model, 0.3, true);  // the bodies have moved off qpos0
  MujocoModel as_compiled = model;
  const RelativePose engaged = gripper_to_target(model);
  engage_weld_here(model, grasp);
  EXPECT_TRUE(weld_engaged(model, grasp));
  as_compiled.mutable_model().eq_active[grasp] = 1;  // the trap: the pose stored at qpos0
  step_for(model, 1.0, true);
  step_for(as_compiled, 1.0, true);
  const RelativePose held = gripper_to_target(model), dragged = gripper_to_target(as_compiled);
  // Measured: 2.0e-5 m and 8.7e-5 rad after 1 s, what the soft weld (20 ms time constant) gives
  // while it takes up the relative motion of its moment (0.17 m/s, 0.04 rad/s) and the joints'
  // torques; as compiled, 0.48 m off.
  EXPECT_LT((held.p_m - engaged.p_m).norm(), 1e-3);
  EXPECT_LT(held.q.angularDistance(engaged.q), 1e-3);
  EXPECT_GT((dragged.p_m - engaged.p_m).norm(), 2e-2);  // as compiled it pulls towards qpos0's pose
  release_weld(model, grasp);
  EXPECT_FALSE(weld_engaged(model, grasp));
}

TEST(Weld, ItsForcesAreInternalAndEngagingIsAnInelasticImpact) {
  MujocoModel model = weld_scene(false);
  const int grasp = mj_name2id(&model.model(), mjOBJ_EQUALITY, "grasp");
  step_for(model, 0.3, false);
  const Momentum p0 = model.momentum();
  const double e0_J = kinetic_energy_J(model);
  engage_weld_here(model, grasp);
  double largest_J = e0_J;
  for (int k = 0; k < 10; ++k) {
    step_for(model, 0.1, false);
    largest_J = std::max(largest_J, kinetic_energy_J(model));
  }
  const Momentum p1 = model.momentum();
  const double e1_J = kinetic_energy_J(model);
  // Linear momentum is kept to rounding (measured 8e-10 kg m/s of 78). Angular momentum drifts by
  // 1.4e-3 kg m^2/s of 5,400 (2.5e-7): MuJoCo's soft weld applies its force pair at the two points it
  // joins, which stand apart by the violation while it takes up the motion of its moment (here
  // violent: ENVISAT's 2.5 deg/s at 4 m, 0.17 m/s), and the pair's couple (violation x force) is the
  // drift. A real grasp engages at a few mm/s, where it is nil. Bound: 1e-6 of |L|.
  EXPECT_LT((p1.linear_kgmps - p0.linear_kgmps).norm(), 1e-8);
  EXPECT_LT((p1.angular_kgm2ps - p0.angular_kgm2ps).norm(), 1e-6 * p0.angular_kgm2ps.norm());
  // The impact takes the gripper-to-target motion out: energy falls and never rises above its start.
  EXPECT_LT(e1_J, e0_J);
  EXPECT_LE(largest_J, e0_J * (1.0 + 1e-12));
}

}  // namespace
}  // namespace chaser::plant::multibody
