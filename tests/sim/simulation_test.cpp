// sim::Simulation, the run loop as an object: stepped to the end it is run_scenario's run, its
// period's halves can be driven from outside, and a fault added mid-run is the scenario's fault.
#include <gtest/gtest.h>

#include "io/scenario_loader.hpp"
#include "sim/run.hpp"
#include "sim/simulation.hpp"

namespace chaser::sim {
namespace {

model::Scenario short_msr(double duration_s) {
  io::LoadResult loaded = io::load_scenario_file("scenarios/msr_terminal.yaml");
  EXPECT_TRUE(loaded.errors.empty()) << io::format_errors(loaded.errors);
  model::Scenario s = *loaded.scenario;
  s.duration_s = duration_s;
  return s;
}

TelemetryRows run_rows(const model::Scenario& s) {
  TelemetryRows rows;
  run_scenario(s, {.telemetry_path = {}, .telemetry_channels = {}, .telemetry_rows = &rows, .record_glr_per_second = false});
  return rows;
}

// The period split in its halves, driven from outside with Chaser's flight software, repeats
// run_scenario's rows exactly; a repeated begin_period senses nothing new.
TEST(Simulation, HalvesDrivenFromOutsideRepeatRunScenario) {
  const model::Scenario s = short_msr(20.0);
  const flight::FlightParams flight_params = flight::make_flight_params(s);
  TelemetryRows rows;
  Simulation sim(s, flight_params, {.telemetry_path = {}, .telemetry_channels = {}, .telemetry_rows = &rows,
                                    .record_glr_per_second = false});
  EXPECT_EQ(sim.periods(), 200);
  while (!sim.done()) {
    const model::SensorMeasurements first = sim.begin_period();
    const model::SensorMeasurements& again = sim.begin_period();
    ASSERT_EQ(first.r_lvlh_m, again.r_lvlh_m);  // the LIDAR noise is drawn once
    sim.end_period(flight::step_flight(sim.flight_params(), sim.flight_state(), again));
  }
  const RunResult result = sim.finish();
  EXPECT_EQ(result.periods, 200);
  EXPECT_EQ(result.simulated_s, 20.0);
  const TelemetryRows expected = run_rows(s);
  ASSERT_EQ(rows.channels, expected.channels);
  EXPECT_EQ(rows.values, expected.values);  // to the bit: doubles compared with ==
}

// A fault added at period 100 with onset 10 s is the same run as the scenario listing it.
TEST(Simulation, AFaultAddedMidRunIsTheScenarioFault) {
  model::Scenario s = short_msr(20.0);
  const model::FaultParams fault{.kind = model::FaultKind::kStuckOpen, .thruster = 7, .onset_s = 10.0};
  const flight::FlightParams flight_params = flight::make_flight_params(s);
  TelemetryRows rows;
  Simulation sim(s, flight_params, {.telemetry_path = {}, .telemetry_channels = {}, .telemetry_rows = &rows,
                                    .record_glr_per_second = false});
  while (sim.period() < 100) sim.step();
  sim.add_fault(fault);
  while (!sim.done()) sim.step();
  sim.finish();
  s.faults = {fault};
  EXPECT_EQ(rows.values, run_rows(s).values);
}

}  // namespace
}  // namespace chaser::sim
