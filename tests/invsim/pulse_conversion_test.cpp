#include "invsim/pulse_conversion.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace chaser::invsim {
namespace {

constexpr PulseParams kParams{0.015, 1.0, 0.35, 0.35, 0.015};  // 120 N on 8000 kg, tau 1 s, Table 3 k

// App. B eq. 1: above the sensitivity dead zone and below saturation the pulse carries exactly
// the commanded impulse, u_max dtau = u tau (to rounding, 1e-15 relative).
TEST(PulseConversion, ImpulseEquivalenceAboveDeadZone) {
  for (double ratio = 0.3501; ratio <= 1.0; ratio += 0.0517) {
    for (int sign : {1, -1}) {
      const double u = sign * ratio * kParams.u_max_mps2;
      const Pulse p = convert_to_pulse(kParams, u);
      EXPECT_EQ(p.direction, sign);
      EXPECT_NEAR(p.direction * kParams.u_max_mps2 * p.on_time_s, u * kParams.step_s,
                  1e-15 * kParams.u_max_mps2);
    }
  }
}

// Eqs. 3-4: at or below k u_max nothing fires (the operator does not perceive the offset).
TEST(PulseConversion, DeadZoneSuppressesSmallCommands) {
  for (double ratio : {0.0, 1e-6, 0.2, 0.35}) {
    const Pulse p = convert_to_pulse(kParams, -ratio * kParams.u_max_mps2);
    EXPECT_EQ(p.direction, 0);
    EXPECT_EQ(p.on_time_s, 0.0);
  }
  EXPECT_EQ(convert_to_pulse(kParams, std::nan("")).direction, 0);
}

// k = min(k_t, k_f) (App. B): the more sensitive of the two factors sets the dead zone.
TEST(PulseConversion, SensitivityIsTheSmallerFactor) {
  const PulseParams p{0.015, 1.0, 0.2, 0.5, 0.015};
  EXPECT_EQ(convert_to_pulse(p, 0.25 * 0.015).direction, 1);
  EXPECT_EQ(convert_to_pulse(p, 0.15 * 0.015).direction, 0);
}

// A command beyond u_max opens the group for the whole step and no longer.
TEST(PulseConversion, SaturatesAtTheWholeStep) {
  const Pulse p = convert_to_pulse(kParams, 3.0 * kParams.u_max_mps2);
  EXPECT_EQ(p.direction, 1);
  EXPECT_EQ(p.on_time_s, kParams.step_s);
}

// The inverse model of the faulted spacecraft (pulses.paper.inverse_model: faulted): a group
// that lost one of its two thrusters (u_max halved) fires on the same commands as the healthy
// group (the dead zone is the pilot's, against the nominal u_max) and opens twice as long for
// the same impulse (eq. 1), up to the whole step.
TEST(PulseConversion, AWeakenedGroupOpensTwiceAsLongOnTheSameCommands) {
  const PulseParams weak{0.0075, 1.0, 0.35, 0.35, 0.015};
  for (double ratio : {0.0, 0.2, 0.35}) EXPECT_EQ(convert_to_pulse(weak, ratio * 0.015).direction, 0);
  for (double ratio = 0.3501; ratio < 0.5; ratio += 0.0217) {
    const Pulse healthy = convert_to_pulse(kParams, ratio * 0.015);
    const Pulse halved = convert_to_pulse(weak, ratio * 0.015);
    EXPECT_EQ(halved.direction, 1);
    EXPECT_NEAR(halved.on_time_s, 2.0 * healthy.on_time_s, 1e-15);
  }
  EXPECT_EQ(convert_to_pulse(weak, 0.6 * 0.015).on_time_s, 1.0);
}

}  // namespace
}  // namespace chaser::invsim
