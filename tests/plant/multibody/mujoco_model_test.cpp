// The MuJoCo wrapper's errors: a model MuJoCo refuses, a name it lacks and a state that diverges
// are clear exceptions, never an exit.
#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "model/arm.hpp"
#include "plant/multibody/mjcf.hpp"
#include "plant/multibody/mujoco_model.hpp"

namespace chaser::plant::multibody {
namespace {

TEST(MujocoModel, AModelMujocoRefusesIsAnErrorWithItsMessage) {
  try {
    MujocoModel model("<mujoco><worldbody><body><joint type=\"spiral\"/></body></worldbody></mujoco>");
    FAIL() << "compiled";
  } catch (const MujocoError& e) {
    EXPECT_NE(std::string(e.what()).find("MuJoCo refused the model"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("spiral"), std::string::npos) << e.what();
  }
}

TEST(MujocoModel, ANameTheModelLacksIsAnError) {
  MujocoModel model(mjcf_of(model::MultibodySceneParams{}));
  EXPECT_EQ(model.joint("joint7"), 7);  // after the hub's free joint and joints 1..6
  EXPECT_THROW(model.body("no_such_body"), MujocoError);
}

TEST(MujocoModel, ANonFiniteStateIsADivergedStepNamingTheTime) {
  MujocoModel model(mjcf_of(model::MultibodySceneParams{}));
  for (int i = 0; i < 3; ++i) model.step();
  model.data().qvel[7] = std::numeric_limits<double>::quiet_NaN();
  try {
    model.step();
    FAIL() << "stepped";
  } catch (const MujocoError& e) {
    EXPECT_NE(std::string(e.what()).find("diverged at t = 0.003"), std::string::npos) << e.what();
  }
}

TEST(MujocoModel, AnErrorInsideMujocoIsAnExceptionAndTheNextCallWorks) {
  // MuJoCo's own error entry point, as its engine calls it: the default handler would end the process.
  try {
    guarded("a test", [] { mju_error("an engine error"); });
    FAIL() << "returned";
  } catch (const MujocoError& e) {
    EXPECT_STREQ(e.what(), "MuJoCo, a test: an engine error");
  }
  // Nested guards: the inner error returns to the inner guard, the outer goes on.
  bool outer_went_on = false;
  guarded("the outer", [&] {
    try {
      guarded("the inner", [] { mju_error("inner"); });
    } catch (const MujocoError&) {
      outer_went_on = true;
    }
  });
  EXPECT_TRUE(outer_went_on);
  MujocoModel model(mjcf_of(model::MultibodySceneParams{}));
  EXPECT_NO_THROW(model.step());
}

// step_applying is mj_step split at its velocity stage: with forces that depend on the step's
// start (here a generalised force from the bodies' positions and velocities), it gives the same
// state to the bit as forces computed from the start's kinematics followed by step(), with the
// jaws in the scene and the joints driven, for RK4 and Euler. The reference computes
// its forces on a copy: mj_kinematics normalises qpos's quaternions in place, so a kinematics pass
// of the reference's own would normalise them twice in a step and move their last bits.
TEST(MujocoModel, StepApplyingIsTheStepWithTheForcesSetAtItsStart) {
  for (const char* integrator : {"RK4", "Euler", "implicit"}) {
    SCOPED_TRACE(integrator);
    model::MultibodySceneParams scene;
    scene.grasp_contact = true;
    scene.integrator = integrator;
    MujocoModel reference(mjcf_of(scene));
    for (int j = 0; j < reference.model().nu; ++j) reference.data().ctrl[j] = 0.5 * (j + 1);
    reference.data().qvel[3] = 0.02;  // the hub turns
    MujocoModel split = reference;
    const auto set_forces = [](const mjModel& m, const mjData& from, mjData& to) {
      for (int i = 0; i < m.nv; ++i)
        to.qfrc_applied[i] = 1e-3 * from.xipos[3 * (1 + i % (m.nbody - 1))] + 0.1 * from.cvel[i % (6 * m.nbody)];
    };
    for (int k = 0; k < 100; ++k) {
      MujocoModel start = reference;
      mjModel* m = &start.mutable_model();
      mjData* d = &start.data();
      mj_kinematics(m, d);
      mj_comPos(m, d);
      mj_comVel(m, d);
      set_forces(*m, *d, reference.data());
      reference.step();
      split.step_applying([&split, &set_forces] { set_forces(split.model(), split.data(), split.data()); });
    }
    // The implicit integrator is not exported by MuJoCo 2.2.2: its step evaluates anew after
    // `apply`, normalising the quaternions a second time, so it agrees to rounding only.
    const double tolerance = std::string(integrator) == "implicit" ? 1e-13 : 0.0;
    const mjModel& m = reference.model();
    for (int i = 0; i < m.nq; ++i) EXPECT_NEAR(split.data().qpos[i], reference.data().qpos[i], tolerance) << "qpos " << i;
    for (int i = 0; i < m.nv; ++i) EXPECT_NEAR(split.data().qvel[i], reference.data().qvel[i], tolerance) << "qvel " << i;
    for (int i = 0; i < m.na; ++i) EXPECT_EQ(split.data().act[i], reference.data().act[i]) << "act " << i;
    EXPECT_EQ(split.data().time, reference.data().time);
  }
}

TEST(MujocoModel, TooSmallAnArenaIsRefusedAtLoading) {
  std::string mjcf = mjcf_of(model::MultibodySceneParams{});
  mjcf.insert(mjcf.find("  <option"), "  <size nstack=\"200\"/>\n");
  EXPECT_THROW(MujocoModel model(mjcf), MujocoError);
}

}  // namespace
}  // namespace chaser::plant::multibody
