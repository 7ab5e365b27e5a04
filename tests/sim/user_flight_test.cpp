// sim/user_flight: a flight side other than Chaser's, its wrench through Chaser's TMU and allocation,
// its on-times straight through, and what the monitor needs (the guidance reference) added.
#include <gtest/gtest.h>

#include "io/scenario_loader.hpp"
#include "sim/user_flight.hpp"

namespace chaser::sim {
namespace {

struct Fixture {
  model::Scenario scenario = *io::load_scenario_file("scenarios/msr_terminal.yaml").scenario;
  flight::FlightParams params = flight::make_flight_params(scenario);
  flight::FlightState state;
  model::SensorMeasurements meas{.t = from_seconds(12.3), .r_lvlh_m = Vec3(0.0, -19.0, 0.0)};
};

// A demand above the TMU's thresholds is released whole (Fonod 2015, II.C: a += W T >= a_th, W~ = a / T)
// and the allocator realises it exactly (M ton = W~) on branch A, the set that flies at the start.
TEST(UserFlight, AWrenchIsReleasedByTheTmuAndAllocatedOnTheActiveSet) {
  Fixture f;
  Vec6 demand;
  demand << 5.0, -3.0, 2.0, 0.5, 0.0, -0.4;  // [N, N m]: impulses 0.2-0.5 N s, above 0.1
  const flight::FlightOutput out = wrench_flight_output(f.params, f.state, f.meas, demand);
  EXPECT_TRUE(out.released_wrench.isApprox(demand, 1e-12));
  EXPECT_TRUE(out.allocation_feasible);
  EXPECT_TRUE(out.commanded_wrench.isApprox(demand, 1e-9)) << out.commanded_wrench.transpose();
  for (int i = 0; i < f.scenario.thrusters.count; ++i) {
    EXPECT_GE(out.command.ton[i], 0.0);
    EXPECT_LE(out.command.ton[i], 1.0);
    if (i >= 8) {
      EXPECT_EQ(out.command.ton[i], 0.0) << "T" << i + 1 << " of standby branch B";
    }
  }
  // What was realised left the accumulator: nothing owed.
  EXPECT_LT(f.state.tmu.accumulated.norm(), 1e-9);
}

// A demand below the thresholds is held in the TMU: no thruster fires this period.
TEST(UserFlight, ASmallWrenchWaitsInTheTmu) {
  Fixture f;
  Vec6 demand = Vec6::Zero();
  demand(0) = 0.5;  // 0.05 N s < 0.1 N s
  const flight::FlightOutput out = wrench_flight_output(f.params, f.state, f.meas, demand);
  EXPECT_EQ(out.released_wrench, Vec6::Zero());
  for (double ton : out.command.ton) EXPECT_EQ(ton, 0.0);
  EXPECT_DOUBLE_EQ(f.state.tmu.accumulated(0), 0.05);
}

// On-times go to the hardware as given; the reference is the guidance's at the period's time.
TEST(UserFlight, OnTimesPassStraightThroughWithTheGuidanceReference) {
  Fixture f;
  model::ThrusterOnTimes ton{};
  ton[2] = 0.25;
  ton[12] = 1.0;  // a standby thruster too: the hardware decides what its closed latch does
  const flight::FlightOutput out = on_times_flight_output(f.params, f.state, f.meas, ton);
  EXPECT_EQ(out.command.ton, ton);
  EXPECT_EQ(out.command.latch_closed_groups, f.state.thrusters.closed_groups);
  const flight::GuidanceRef ref = flight::guidance_reference(f.params.guidance, f.params.orbit, 12.3);
  EXPECT_EQ(out.reference.r_lvlh_m, ref.r_lvlh_m);
  EXPECT_TRUE(f.state.initialised);  // as step_flight would have left it
}

}  // namespace
}  // namespace chaser::sim
