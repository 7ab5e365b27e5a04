// The escape's judgement (sim/escape_result.hpp): the camera's angle against its closed form, the
// figures' minima and maxima over the periods, and each requirement failing the verdict alone.
#include "sim/escape_result.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace chaser::sim {
namespace {

TEST(EscapeResult, TheCameraAngleIsBetweenItsAxisAndTheLineFromItsEyeToTheCentre) {
  const Quat facing_minus_x(0.0, 0.0, 0.0, 1.0);  // the tool's x along -x
  EXPECT_NEAR(camera_angle_rad(Vec3(4.0, 0.0, 0.0), facing_minus_x, 0.2), 0.0, 1e-15);
  // The eye 0.2 m behind the tool point, at (4.2, 3, 0): the centre atan(3 / 4.2) off its axis.
  EXPECT_NEAR(camera_angle_rad(Vec3(4.0, 3.0, 0.0), facing_minus_x, 0.2), std::atan2(3.0, 4.2), 1e-15);
  EXPECT_NEAR(camera_angle_rad(Vec3(-4.0, 0.0, 0.0), facing_minus_x, 0.2), std::numbers::pi, 1e-15);  // behind it
}

constexpr double kLoadLimitNm = 176.0;  // [N m] the braked joints' load limit

// A plan triggered at 100 s: its steps 30, 300, 200 and 400 s.
flight::EscapeLawParams plan() {
  flight::EscapeLawParams p;
  p.escape.retract_duration_s = 30.0;
  p.escape.withdraw_duration_s = 300.0;
  p.escape.desynchronise_duration_s = 200.0;
  p.escape.retreat_duration_s = 400.0;
  return p;
}

TEST(EscapeResult, ThePeriodsFiguresSplitAtTheDesynchronisationAndTheToolsAtTheRetraction) {
  const flight::EscapeLawParams p = plan();
  flight::EscapeState state;
  EscapeResult r;
  add_escape_period(r, p, state, {.t_s = 50.0, .chaser_clearance_m = 0.1, .distance_m = 7.4});
  EXPECT_FALSE(r.flown);  // not triggered yet
  state.trigger = flight::EscapeTrigger::kCommand;
  state.start_s = 100.0;
  add_escape_period(r, p, state, {.t_s = 100.0, .chaser_clearance_m = 2.5, .tool_clearance_m = 0.0,
                                  .camera_angle_rad = 0.1, .distance_m = 7.4});  // the tool at the fixture
  add_escape_period(r, p, state, {.t_s = 200.0, .chaser_clearance_m = 2.0, .tool_clearance_m = 0.8,
                                  .camera_angle_rad = 0.2, .distance_m = 9.0});
  add_escape_period(r, p, state, {.t_s = 500.0, .chaser_clearance_m = 8.0, .tool_clearance_m = 6.0,
                                  .camera_angle_rad = 0.15, .distance_m = 12.0});
  add_escape_period(r, p, state, {.t_s = 1100.0, .chaser_clearance_m = 25.0, .tool_clearance_m = 23.0,
                                  .camera_angle_rad = 0.1, .distance_m = 30.1});
  ASSERT_TRUE(r.flown);
  EXPECT_STREQ(r.trigger, "command");
  EXPECT_EQ(r.desynchronise_s, 430.0);
  EXPECT_EQ(r.hold_s, 1030.0);
  EXPECT_EQ(r.min_clearance_synchronised_m, 2.0);
  EXPECT_EQ(r.min_clearance_synchronised_at_s, 200.0);
  EXPECT_EQ(r.min_clearance_unsynchronised_m, 8.0);
  EXPECT_EQ(r.min_tool_clearance_m, 0.8);  // from the retraction's end at 130 s
  EXPECT_EQ(r.max_camera_angle_rad, 0.2);
  EXPECT_EQ(r.max_camera_angle_at_s, 200.0);
  EXPECT_EQ(r.final_distance_m, 30.1);
  EXPECT_TRUE(escape_meets_requirements(r, 30.0, 0.7, kLoadLimitNm));
  EXPECT_TRUE(escape_meets_requirements(r, 30.0, std::nan(""), kLoadLimitNm));  // no camera: not judged
  EXPECT_FALSE(escape_meets_requirements(r, 30.0, 0.15, kLoadLimitNm));        // the camera's angle
  EXPECT_FALSE(escape_meets_requirements(r, 29.5, 0.7, kLoadLimitNm));         // the distance
  EscapeResult close = r;
  close.min_clearance_synchronised_m = 0.4;
  EXPECT_FALSE(escape_meets_requirements(close, 30.0, 0.7, kLoadLimitNm));
  close = r;
  close.min_clearance_unsynchronised_m = 2.9;
  EXPECT_FALSE(escape_meets_requirements(close, 30.0, 0.7, kLoadLimitNm));
  close = r;
  close.min_tool_clearance_m = -0.01;
  EXPECT_FALSE(escape_meets_requirements(close, 30.0, 0.7, kLoadLimitNm));
  close = r;
  close.final_t_s = 1000.0;  // the run ended before the hold
  EXPECT_FALSE(escape_meets_requirements(close, 30.0, 0.7, kLoadLimitNm));
}

TEST(EscapeResult, TheBrakesTimeIsRecordedAndTheirLoadJudgedOnlyWhenBraked) {
  const flight::EscapeLawParams p = plan();
  flight::EscapeState state;
  state.trigger = flight::EscapeTrigger::kCommand;
  state.start_s = 100.0;
  EscapeResult r;
  add_escape_period(r, p, state, {.t_s = 100.0, .chaser_clearance_m = 2.5, .camera_angle_rad = 0.1, .distance_m = 7.4});
  EXPECT_TRUE(std::isnan(r.brakes_s));
  state.brakes_s = 130.0;
  add_escape_period(r, p, state, {.t_s = 1100.0, .chaser_clearance_m = 25.0, .tool_clearance_m = 23.0,
                                  .camera_angle_rad = 0.1, .distance_m = 30.1});
  EXPECT_EQ(r.brakes_s, 130.0);
  r.peak_brake_load_Nm = 12.0;
  EXPECT_TRUE(escape_meets_requirements(r, 30.0, 0.7, kLoadLimitNm));
  EXPECT_FALSE(escape_meets_requirements(r, 30.0, 0.7, 11.9));  // the loads over the limit
  r.peak_brake_load_Nm = std::nan("");                           // braked, no load recorded: unmet
  EXPECT_FALSE(escape_meets_requirements(r, 30.0, 0.7, kLoadLimitNm));
  r.brakes_s = std::nan("");                                     // never braked: the loads not judged
  EXPECT_TRUE(escape_meets_requirements(r, 30.0, 0.7, kLoadLimitNm));
}

TEST(EscapeResult, ARefusedCommandIsRecordedAndNothingIsFlown) {
  flight::EscapeState state;
  state.refused_s = 2890.0;
  EscapeResult r;
  add_escape_period(r, plan(), state, {.t_s = 2900.0});
  EXPECT_FALSE(r.flown);
  EXPECT_EQ(r.refused_s, 2890.0);
  EXPECT_FALSE(escape_meets_requirements(r, 30.0, 0.7, kLoadLimitNm));
}

}  // namespace
}  // namespace chaser::sim
