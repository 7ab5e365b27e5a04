#include "flight/fdi/event_resolution.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "core/random.hpp"

namespace chaser::flight::fdi {
namespace event_resolution_test {

constexpr double kT = 0.1;        // [s]
constexpr int kFaulty = 3;

std::array<double, kMaxWatchedThrusters> flow() {
  model::ThrusterSetParams set;
  set.count = 8;
  return nominal_mass_flow_kgps(set, watched_set(model::all_thrusters(set)), 220.0);
}

WatchedTon sparse_ton(RandomStream& rng) {
  WatchedTon ton = WatchedTon::Zero();
  for (int i = 0; i < 8; ++i)
    if (rng.uniform() < 0.06) ton(i) = rng.uniform(0.1, 1.0);
  return ton;
}

enum class Case { kNone, kStuckOpen, kBlocked };

// A sequence of sparse commands; from period `onset` thruster 3 is stuck open or blocked. The
// sensor reads the realised consumption plus white noise; the alarm comes 7 periods after onset.
// Returns the first period with over_consumption, or -1.
int run(Case fault_case, const EventResolutionParams& p, std::uint64_t seed, int periods = 3000,
        int onset = 1000) {
  RandomStream rng(seed, "event/commands");
  RandomStream noise(seed, "event/sensor");
  const auto mdot = flow();
  EventResolutionState state;
  double used_kg = 0.0;
  for (int k = 0; k < periods; ++k) {
    const WatchedTon commanded = sparse_ton(rng);
    WatchedTon realised = commanded;
    if (k >= onset && fault_case == Case::kStuckOpen) realised(kFaulty) = 1.0;
    if (k >= onset && fault_case == Case::kBlocked) realised(kFaulty) = 0.0;
    used_kg += expected_propellant_increment_kg(realised, mdot, kT);
    const double measured = used_kg + noise.normal(0.0, p.sensor_sigma_kg);
    const bool alarm = k >= onset + 7;
    const bool over = step_event_resolution(p, state, measured,
                                            expected_propellant_increment_kg(commanded, mdot, kT), alarm);
    if (!alarm) {
      EXPECT_FALSE(over);
    }
    if (over) return k;
  }
  return -1;
}

// Nominal flow F / (Isp g0): 22 N at 220 s is 10.2 g/s; the predicted increment is sum T_on T mdot.
TEST(EventResolution, NominalFlowAndExpectedIncrement) {
  const auto mdot = flow();
  EXPECT_NEAR(mdot[0], 22.0 / (220.0 * kStandardGravity), 1e-15);
  WatchedTon ton = WatchedTon::Zero();
  ton(1) = 0.5;
  ton(6) = 0.25;
  EXPECT_NEAR(expected_propellant_increment_kg(ton, mdot, kT), 0.75 * kT * mdot[0], 1e-16);
}

// Stuck open: the faulty thruster burns (1 - T_on) T mdot ~ 1 g per period more than predicted;
// with sigma_m = 1 g and k_sigma = 5 the threshold is 7.1 g (plus 5 % of the ~0.03 g/period
// prediction), so the flag must rise about 7-8 periods after the alarm (allowed: 4..15).
TEST(EventResolution, StuckOpenIsOverConsumption) {
  EventResolutionParams p;
  p.sensor_sigma_kg = 1e-3;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const int k = run(Case::kStuckOpen, p, seed);
    ASSERT_GE(k, 0) << "seed " << seed;
    EXPECT_GE(k - 1007, 4) << "seed " << seed;
    EXPECT_LE(k - 1007, 15) << "seed " << seed;
  }
}

// Blocked: less is burned than predicted, the excess is negative: never over-consumption.
// No fault (a false GLR alarm): the excess is noise of std sqrt(2) sigma_m; with k_sigma = 5 the
// union bound over 2000 periods is 2000 Q(5) = 6e-4 per run.
TEST(EventResolution, BlockedAndNoFaultAreNot) {
  EventResolutionParams p;
  p.sensor_sigma_kg = 1e-3;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    EXPECT_EQ(run(Case::kBlocked, p, seed), -1) << "seed " << seed;
    EXPECT_EQ(run(Case::kNone, p, seed), -1) << "seed " << seed;
  }
}

// The noise model behind the threshold: with no margin and k_sigma = 2, the flag on the first
// period after the reference rises with probability Q(2) = 0.02275 (difference of two readings,
// std sqrt(2) sigma_m). 40,000 trials: binomial std 7.5e-4, tolerance 4 std.
TEST(EventResolution, FalseAlarmRateMatchesTheNoiseModel) {
  EventResolutionParams p;
  p.sensor_sigma_kg = 2e-3;
  p.k_sigma = 2.0;
  p.relative_margin = 0.0;
  RandomStream noise(7, "event/rate");
  int raised = 0;
  const int trials = 40000;
  for (int t = 0; t < trials; ++t) {
    EventResolutionState state;
    step_event_resolution(p, state, 1.0 + noise.normal(0, 2e-3), 0.0, true);
    raised += step_event_resolution(p, state, 1.0 + 1e-3 + noise.normal(0, 2e-3), 1e-3, true);
  }
  EXPECT_NEAR(static_cast<double>(raised) / trials, 0.02275, 4 * 7.5e-4);
}

// Latching and the reference: the flag stays false before the alarm whatever is measured, and
// once raised stays raised even if the excess goes away.
TEST(EventResolution, LatchesAndIgnoresReadingsBeforeTheAlarm) {
  EventResolutionParams p;
  p.sensor_sigma_kg = 1e-3;
  EventResolutionState state;
  EXPECT_FALSE(step_event_resolution(p, state, 5.0, 0.0, false));  // large reading, no alarm
  EXPECT_FALSE(step_event_resolution(p, state, 5.0, 0.0, true));   // reference
  EXPECT_FALSE(step_event_resolution(p, state, 5.005, 0.0, true));  // 5 g < 7.07 g
  EXPECT_TRUE(step_event_resolution(p, state, 5.008, 0.0, true));   // 8 g > 7.07 g
  EXPECT_TRUE(step_event_resolution(p, state, 5.0, 0.0, true));
}

TEST(EventResolution, ValidateNamesTheProblems) {
  EventResolutionParams p;
  EXPECT_TRUE(validate(p).empty());
  p.k_sigma = 0.0;
  p.relative_margin = -1.0;
  EXPECT_EQ(validate(p).size(), 2u);
}

}  // namespace event_resolution_test
}  // namespace chaser::flight::fdi
