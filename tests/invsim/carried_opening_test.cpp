#include "invsim/carried_opening.hpp"

#include <gtest/gtest.h>

namespace chaser::invsim {
namespace {

constexpr double kStepS = 1.0;
const std::array<double, 2> kHealthy{0.015, 0.015};  // [m/s^2] +, - groups
const std::array<double, 2> kHalvedPlus{0.0075, 0.015};

// An opening within the step flies as commanded and leaves nothing under way (the capped reading's
// pulse, bit for bit).
TEST(CarriedOpening, AnOpeningWithinTheStepIsFlownAsCommanded) {
  CarriedOpening c;
  const Pulse flown = open_for_step(c, Pulse{-1, 0.4}, kHealthy, kStepS);
  EXPECT_EQ(flown.direction, -1);
  EXPECT_EQ(flown.on_time_s, 0.4);
  EXPECT_EQ(c.direction, 0);
  EXPECT_EQ(c.remaining_s, 0.0);
}

// Eq. 1 without the cap: 2.5 steps of opening fly as a whole step, a whole step and half a step,
// and the inverse model's next commands are reduced by what is still under way (so a command equal
// to the remaining impulse asks for nothing more).
TEST(CarriedOpening, ALongOpeningContinuesAndIsNotAskedForTwice) {
  CarriedOpening c;
  EXPECT_EQ(open_for_step(c, Pulse{1, 2.5}, kHalvedPlus, kStepS).on_time_s, 1.0);
  EXPECT_EQ(c.direction, 1);
  EXPECT_DOUBLE_EQ(c.remaining_s, 1.5);
  // The inverse model still asks for 1.5 s of the halved group's acceleration: nothing beyond it.
  EXPECT_DOUBLE_EQ(command_beyond_carried(c, kHalvedPlus, kStepS, 1.5 * 0.0075), 0.0);
  EXPECT_DOUBLE_EQ(command_beyond_carried(c, kHalvedPlus, kStepS, 0.02), 0.02 - 1.5 * 0.0075);
  EXPECT_EQ(open_for_step(c, Pulse{0, 0.0}, kHalvedPlus, kStepS).on_time_s, 1.0);
  const Pulse last = open_for_step(c, Pulse{0, 0.0}, kHalvedPlus, kStepS);
  EXPECT_EQ(last.direction, 1);
  EXPECT_DOUBLE_EQ(last.on_time_s, 0.5);
  EXPECT_EQ(c.direction, 0);
  EXPECT_EQ(open_for_step(c, Pulse{0, 0.0}, kHalvedPlus, kStepS).direction, 0);
  EXPECT_EQ(command_beyond_carried(c, kHalvedPlus, kStepS, 0.003), 0.003);  // nothing under way
}

// A command the other way shortens the opening under way impulse for impulse (the groups'
// accelerations differ: the + group is halved), and opens the other group with what is left.
TEST(CarriedOpening, ACommandTheOtherWayShortensThenReverses) {
  CarriedOpening c{1, 2.0};  // 2 s of the halved + group: 0.015 m/s of impulse
  // 0.5 s of the healthy - group is 0.0075 m/s: the + opening loses 1 s.
  const Pulse flown = open_for_step(c, Pulse{-1, 0.5}, kHalvedPlus, kStepS);
  EXPECT_EQ(flown.direction, 1);
  EXPECT_DOUBLE_EQ(flown.on_time_s, 1.0);
  EXPECT_EQ(c.direction, 0);  // 2 - 1 - 1 = 0 s left
  CarriedOpening d{1, 0.2};  // 0.0015 m/s
  const Pulse reversed = open_for_step(d, Pulse{-1, 0.5}, kHalvedPlus, kStepS);  // 0.0075 m/s
  EXPECT_EQ(reversed.direction, -1);
  EXPECT_NEAR(reversed.on_time_s, (0.0075 - 0.0015) / 0.015, 1e-15);
  EXPECT_EQ(d.direction, 0);
}

}  // namespace
}  // namespace chaser::invsim
