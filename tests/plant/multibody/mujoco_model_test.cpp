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

TEST(MujocoModel, TooSmallAnArenaIsRefusedAtLoading) {
  std::string mjcf = mjcf_of(model::MultibodySceneParams{});
  mjcf.insert(mjcf.find("  <option"), "  <size nstack=\"200\"/>\n");
  EXPECT_THROW(MujocoModel model(mjcf), MujocoError);
}

}  // namespace
}  // namespace chaser::plant::multibody
