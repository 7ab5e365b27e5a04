// The grasp's contact (model/arm.hpp's JawParams and FixtureParams in plant/multibody/mjcf.cpp): the
// gripper with its two sliding fingers has the gripper's mass properties (checked on MuJoCo's
// compiled bodies, not on model::gripper_bodies' arithmetic); a contact of the fixture's lip with
// the gripper injects no energy (the kinetic energy plus the fingers' servo springs never rises,
// and momentum is kept: contact forces are internal); the jaws' switches (plant::read_jaws) see
// the lip held by both fingers, and not when the fingers close on nothing.
#include <cmath>

#include <gtest/gtest.h>

#include "model/arm.hpp"
#include "plant/multibody/mjcf.hpp"
#include "plant/multibody/mujoco_model.hpp"
#include "plant/multibody_motion.hpp"

namespace chaser::plant::multibody {
namespace {

Vec3 vec3_at(const mjtNum* p) { return Vec3(p[0], p[1], p[2]); }

// The tool point of the default scene at qpos0 (arm stretched along +x, every frame parallel).
Vec3 tool_at_qpos0() {
  MujocoModel model(mjcf_of(model::MultibodySceneParams{}));
  model.forward();
  return vec3_at(model.data().site_xpos + 3 * mj_name2id(&model.model(), mjOBJ_SITE, "tool"));
}

// The scene with jaws and the fixture's lip `lip_from_tool_m` from the tool point at qpos0 (world
// axes = the grasp pose's axes), the target moving at `target_velocity_mps`; no joint friction.
MujocoModel jaw_scene(const Vec3& lip_from_tool_m, const Vec3& target_velocity_mps, bool weld = false) {
  model::MultibodySceneParams scene;
  for (auto& link : scene.arm.links) link.friction_Nm = 0.0;
  scene.grasp_contact = true;
  scene.grasp_weld = weld;
  scene.target_position_m = tool_at_qpos0() + lip_from_tool_m + Vec3(2.0, 0.0, 0.0);
  scene.fixture_target_m = Vec3(-2.0, 0.0, 0.0);  // the lip 2 m from the target's CoM along -x
  MujocoModel model(mjcf_of(scene));
  const int target_dof = model.model().jnt_dofadr[model.joint("target_free")];
  for (int i = 0; i < 3; ++i) model.data().qvel[target_dof + i] = target_velocity_mps(i);
  model.forward();
  return model;
}

// Kinetic energy plus the fingers' servo springs, kp (ctrl - q)^2 / 2.
double mechanical_energy_J(MujocoModel& model) {
  model.forward();
  const mjModel& m = model.model();
  const mjData& d = model.data();
  const Eigen::Map<const Eigen::VectorXd> v(d.qvel, m.nv);
  double energy = 0.5 * v.dot(model.mass_matrix() * v);
  for (const char* finger : {"finger_a", "finger_b"}) {
    const int actuator = mj_name2id(&m, mjOBJ_ACTUATOR, finger);
    const double q = d.qpos[m.jnt_qposadr[mj_name2id(&m, mjOBJ_JOINT, finger)]];
    energy += 0.5 * m.actuator_gainprm[actuator * mjNGAIN] * (d.ctrl[actuator] - q) * (d.ctrl[actuator] - q);
  }
  return energy;
}

TEST(Jaws, TheGripperWithItsOpenFingersHasTheGrippersMassProperties) {
  model::MultibodySceneParams scene;
  scene.grasp_contact = true;
  MujocoModel model(mjcf_of(scene));
  model.forward();
  const mjModel& m = model.model();
  const mjData& d = model.data();
  // MuJoCo's compiled bodies at qpos0, world axes = link 7's: composed about their joint CoM.
  double mass_kg = 0.0;
  Vec3 moment_kgm = Vec3::Zero();
  const int bodies[3] = {model.body("gripper"), model.body("finger_a"), model.body("finger_b")};
  for (const int b : bodies) {
    mass_kg += m.body_mass[b];
    moment_kgm += m.body_mass[b] * vec3_at(d.xipos + 3 * b);
  }
  const Vec3 com_m = moment_kgm / mass_kg;
  Mat3 inertia_kgm2 = Mat3::Zero();
  for (const int b : bodies) {
    Mat3 world_from_inertial;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) world_from_inertial(i, j) = d.ximat[9 * b + 3 * i + j];
    const Vec3 r = vec3_at(d.xipos + 3 * b) - com_m;
    inertia_kgm2 += world_from_inertial * vec3_at(m.body_inertia + 3 * b).asDiagonal() * world_from_inertial.transpose() +
                    m.body_mass[b] * (r.squaredNorm() * Mat3::Identity() - r * r.transpose());
  }
  const model::GripperParams& g = scene.arm.gripper;
  const Vec3 link7_m = vec3_at(d.xpos + 3 * model.body("gripper"));  // the gripper's frame is link 7's origin
  EXPECT_NEAR(mass_kg, g.mass_kg, 1e-12);
  EXPECT_LT((com_m - (link7_m + g.com_link7_m)).norm(), 1e-12);
  // MuJoCo diagonalises each body's inertia when it compiles (float-free, but eigen-solved): 1e-9.
  EXPECT_LT((inertia_kgm2 - Mat3(g.inertia_kgm2.asDiagonal())).norm(), 1e-9 * g.inertia_kgm2.norm());
}

// The contact is the three predefined pairs of the jaws with the lip and nothing else (no broad
// phase: collision="predefined", every geom out of the dynamic pass), each with the contact MuJoCo
// would mix from its two geoms: condim 3, friction 1, its default soft contact (0.02 s, damping
// ratio 1; impedance 0.9 to 0.95 over 1 mm).
TEST(Jaws, TheContactIsTheJawsWithTheLipOnlyAtMujocosDefaultSoftContact) {
  const MujocoModel model = jaw_scene(Vec3::Zero(), Vec3::Zero());
  const mjModel& m = model.model();
  EXPECT_EQ(m.opt.collision, mjCOL_PAIR);
  for (int g = 0; g < m.ngeom; ++g) EXPECT_EQ(m.geom_contype[g] | m.geom_conaffinity[g], 0) << "geom " << g;
  ASSERT_EQ(m.npair, 3);
  const int fixture = mj_name2id(&m, mjOBJ_GEOM, "fixture");
  const char* jaws[3] = {"palm", "finger_a", "finger_b"};
  for (int p = 0; p < m.npair; ++p) {
    SCOPED_TRACE(jaws[p]);
    EXPECT_EQ(m.pair_geom1[p], mj_name2id(&m, mjOBJ_GEOM, jaws[p]));
    EXPECT_EQ(m.pair_geom2[p], fixture);
    EXPECT_EQ(m.pair_dim[p], 3);
    EXPECT_EQ(m.pair_friction[5 * p], 1.0);
    EXPECT_EQ(m.pair_solref[mjNREF * p], 0.02);
    EXPECT_EQ(m.pair_solref[mjNREF * p + 1], 1.0);
    EXPECT_EQ(m.pair_solimp[mjNIMP * p], 0.9);
    EXPECT_EQ(m.pair_solimp[mjNIMP * p + 1], 0.95);
    EXPECT_EQ(m.pair_margin[p], 0.0);
  }
}

TEST(Jaws, TheLipStrikingThePalmInjectsNoEnergyAndKeepsMomentum) {
  // The lip between the open fingers, 1 cm ahead of the palm's face (0.04 m behind the tool point,
  // the lip 0.03 m deep), coming at 5 cm/s with 1 cm/s across: it strikes the palm after 0.2 s.
  MujocoModel model = jaw_scene(Vec3(-0.04 + 0.01 + 0.03, 0.0, 0.0), Vec3(-0.05, 0.01, 0.0));
  const double energy0 = mechanical_energy_J(model);
  const Vec3 p0 = model.momentum().linear_kgmps;
  double most_energy = energy0;
  int periods_in_contact = 0;
  for (int k = 0; k < 1000; ++k) {  // 1 s
    model.step();
    periods_in_contact += model.data().ncon > 0;
    most_energy = std::max(most_energy, mechanical_energy_J(model));
  }
  ASSERT_GT(periods_in_contact, 0);  // it did strike
  const double energy1 = mechanical_energy_J(model);
  // RK4 at 1 ms keeps the free flight's energy to ~1e-12 relative; the contact (MuJoCo's soft
  // constraint, critically damped, with friction across) only takes energy out: measured, 10.18 J
  // falls to 8.51 J over 96 steps in contact, the momentum kept to 1e-11 relative.
  EXPECT_LE(most_energy, energy0 * (1.0 + 1e-9));
  EXPECT_LT(energy1, energy0);
  EXPECT_LT((model.momentum().linear_kgmps - p0).norm(), 1e-8 * p0.norm());
}

TEST(Jaws, TheSwitchesSeeTheLipHeldByBothFingersAndNothingWhenTheyCloseOnNothing) {
  for (const bool with_lip : {true, false}) {
    // The lip centred between the fingers (or 1 m away), everything at rest.
    MujocoModel world = jaw_scene(with_lip ? Vec3::Zero() : Vec3(1.0, 0.0, 0.0), Vec3::Zero());
    MultibodyMotionParams params;
    params.scene.grasp_contact = true;
    params.index = indices_of(world);
    MultibodyMotionState state{.world = world, .earth = {}};
    const model::JawParams& jaws = params.scene.arm.gripper.jaws;
    EXPECT_FALSE(read_jaws(params, state).holding);
    EXPECT_NEAR(read_jaws(params, state).opening_m, 2.0 * jaws.open_half_gap_m, 1e-12);
    command_jaws(params, state, true);
    for (int k = 0; k < 500; ++k) state.world.step();  // 0.5 s
    const JawReading r = read_jaws(params, state);
    SCOPED_TRACE(with_lip ? "on the lip" : "on nothing");
    EXPECT_EQ(r.holding, with_lip);
    // On the lip the fingers stop at its 10 mm, pressed into it by MuJoCo's soft contact (< 1 mm);
    // on nothing they close to the tool point.
    EXPECT_NEAR(r.opening_m, with_lip ? 2.0 * params.scene.fixture.half_extents_m.z() : 0.0, 1e-3);
  }
}

// The rigid closure (engage_grasp) welds the gripper to the lip the jaws hold and locks the jaws:
// their contact is then off (its forces are internal to the welded pair), they read as holding,
// and each finger stays where it was (its servo held there: within 1e-6 m over 1 s with the arm
// driven), the momentum kept (the weld is internal too: the links' drives exchange ~1 kg m/s
// between the bodies, the scene's total stays within 1e-7 kg m/s of it; measured 2.6e-8).
TEST(Jaws, LockedTheJawsStayOnTheLipWithTheirContactOff) {
  MujocoModel world = jaw_scene(Vec3::Zero(), Vec3::Zero(), true);
  MultibodyMotionParams params;
  params.scene.grasp_contact = true;
  params.index = indices_of(world);
  MultibodyMotionState state{.world = world, .earth = {}};
  command_jaws(params, state, true);
  for (int k = 0; k < 500; ++k) state.world.step();  // 0.5 s: the jaws close on the lip
  ASSERT_TRUE(read_jaws(params, state).holding);
  engage_grasp(params, state);
  EXPECT_TRUE(grasp_engaged(params, state));
  EXPECT_TRUE(state.world.model().opt.disableflags & mjDSBL_CONTACT);
  const double opening_m = read_jaws(params, state).opening_m;
  const Vec3 p0 = state.world.momentum().linear_kgmps;
  const int motor1 = params.index.motor1;
  for (int k = 0; k < 1000; ++k) {  // 1 s, the arm's joints driven
    command_jaws(params, state, true);
    for (int j = 0; j < model::kArmJoints; ++j) state.world.data().ctrl[motor1 + j] = 3.0 * std::sin(1e-2 * k + j);
    state.world.step();
  }
  EXPECT_EQ(state.world.data().ncon, 0);
  const JawReading r = read_jaws(params, state);
  EXPECT_TRUE(r.holding);
  EXPECT_NEAR(r.opening_m, opening_m, 1e-6);
  EXPECT_LT((state.world.momentum().linear_kgmps - p0).norm(), 1e-7);
}

}  // namespace
}  // namespace chaser::plant::multibody
