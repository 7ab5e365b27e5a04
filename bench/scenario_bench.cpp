// End-to-end and per-period benchmarks on the MSR terminal rendezvous scenario.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <iostream>

#include "flight/flight_software.hpp"
#include "io/scenario_loader.hpp"
#include "plant/plant.hpp"
#include "sim/run.hpp"

namespace {

using namespace chaser;

model::Scenario msr_scenario() {
  const io::LoadResult loaded = io::load_scenario_file(CHASER_SOURCE_DIR "/scenarios/msr_terminal.yaml");
  if (!loaded.scenario) {
    std::cerr << io::format_errors(loaded.errors);
    std::abort();
  }
  return *loaded.scenario;
}

// The whole 1200 s run, every model on, no telemetry: simulated seconds per wall-clock second.
void BM_EndToEnd(benchmark::State& state, bool with_fault) {
  model::Scenario scenario = msr_scenario();
  if (with_fault) scenario.faults = {model::FaultParams{.kind = model::FaultKind::kStuckOpen, .thruster = 7}};
  double simulated_s = 0;
  for (auto _ : state) {
    const sim::RunResult result = sim::run_scenario(scenario);
    simulated_s += result.simulated_s;
    benchmark::DoNotOptimize(result);
  }
  state.counters["sim_s_per_wall_s"] = benchmark::Counter(simulated_s, benchmark::Counter::kIsRate);
}
BENCHMARK_CAPTURE(BM_EndToEnd, nominal, false)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_EndToEnd, stuck_open_T8, true)->Unit(benchmark::kMillisecond)->UseRealTime();

// Shared set-up for the per-period benchmarks: a plant and flight software 500 s into the approach.
struct LoopFixture {
  model::Scenario scenario;
  plant::Plant plant;
  flight::FlightParams flight_params = flight::make_flight_params(scenario);
  flight::FlightState flight_state;
  TimeNs period_ns = from_seconds(scenario.control_period_s);
  TimeNs t_ns = 0;

  explicit LoopFixture(bool fdi_on = true, bool deficit = true)
      : scenario(with_fdi(msr_scenario(), fdi_on, deficit)),
        plant(plant::make_plant(scenario, start_state(scenario), scenario.seed)) {
    for (int k = 0; k < 5000; ++k) step();
  }
  static model::Scenario with_fdi(model::Scenario s, bool on, bool deficit) {
    s.fdi.position.enabled = s.fdi.attitude.enabled = on;
    if (!on || !deficit) s.fdi.isolation_method = model::IsolationMethod::kPaper;  // no deficit bank, no detector
    return s;
  }
  static plant::RigidState start_state(const model::Scenario& s) {
    const flight::GuidanceRef ref = flight::guidance_reference(s.guidance, s.orbit.mean_motion_radps(), 0.0);
    return plant::RigidState{ref.r_lvlh_m, ref.v_lvlh_mps, ref.q_inertial_from_body, ref.omega_body_radps,
                             s.chaser.mass_kg};
  }
  model::ThrusterCommand flight_period() {
    const model::SensorMeasurements meas = plant::sense_plant(plant.params, plant.state, t_ns);
    return flight::step_flight(flight_params, flight_state, meas).command;
  }
  void step() {
    const model::ThrusterCommand command = flight_period();
    plant::step_plant(plant.params, plant.state, command, t_ns);
    t_ns += period_ns;
  }
};

// One full control period: sensors, flight software, thruster model and propagation, with the
// scenario's FDI (both published schemes, Chaser's deficit bank and detector), with the published
// method alone (isolation_method: paper), and off: the differences are what each costs.
void BM_ControlPeriod(benchmark::State& state, bool fdi_on, bool deficit) {
  LoopFixture f(fdi_on, deficit);
  for (auto _ : state) f.step();
}
BENCHMARK_CAPTURE(BM_ControlPeriod, fdi_on, true, true);
BENCHMARK_CAPTURE(BM_ControlPeriod, fdi_published, true, false);
BENCHMARK_CAPTURE(BM_ControlPeriod, fdi_off, false, false);

// Thruster model and propagation of one period with a fixed command: T1 for 30 % and its partner
// T5 for 60 % of the period (a pure torque plus a net force; five pieces with the delay).
void BM_PropagationPeriod(benchmark::State& state) {
  LoopFixture f;
  model::ThrusterCommand command;
  command.ton[0] = 0.3;
  command.ton[4] = 0.6;
  for (auto _ : state) {
    plant::step_plant(f.plant.params, f.plant.state, command, f.t_ns);
    f.t_ns += f.period_ns;
  }
}
BENCHMARK(BM_PropagationPeriod);

// Flight software alone: navigation, guidance, control, TMU, TMF. The plant stays frozen 500 s into
// the approach while the reference moves on, so the controllers demand thrust and the allocator
// runs every period: a busier period than the closed loop's typical one.
void BM_FlightPeriod(benchmark::State& state, bool fdi_on) {
  LoopFixture f(fdi_on);
  for (auto _ : state) {
    benchmark::DoNotOptimize(f.flight_period());
    f.t_ns += f.period_ns;
  }
}
BENCHMARK_CAPTURE(BM_FlightPeriod, fdi_on, true);
BENCHMARK_CAPTURE(BM_FlightPeriod, fdi_off, false);

}  // namespace
