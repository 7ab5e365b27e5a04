// End-to-end and per-period benchmarks on the MSR terminal rendezvous scenario, and the COMRADE
// platform's (perturbed Earth orbit, tumbling target, 24 thrusters) beside it.
#include <benchmark/benchmark.h>

#include <array>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <utility>
#include <vector>

#include "core/rotation.hpp"
#include "flight/flight_software.hpp"
#include "io/scenario_loader.hpp"
#include "plant/plant.hpp"
#include "sim/run.hpp"

namespace {

// The period benchmarks' inputs: xorshift64, a fixed, cheap sequence of numbers in [0, 1).
struct Uniform {
  std::uint64_t x = 88172645463325252ULL;
  double operator()() {
    x ^= x << 13, x ^= x >> 7, x ^= x << 17;
    return static_cast<double>(x >> 11) * 0x1.0p-53;
  }
};

using namespace chaser;

model::Scenario shipped_scenario(const std::string& file) {
  const io::LoadResult loaded = io::load_scenario_file(CHASER_SOURCE_DIR "/scenarios/" + file);
  if (!loaded.scenario) {
    std::cerr << io::format_errors(loaded.errors);
    std::abort();
  }
  return *loaded.scenario;
}
model::Scenario msr_scenario() { return shipped_scenario("msr_terminal.yaml"); }

// The FDI variants of the per-period benchmarks: the scenario's (both published schemes, Chaser's
// deficit bank and detector), the published method alone (isolation_method: paper), or none.
enum class Fdi { kOn, kPublished, kOff };

model::Scenario with_fdi(model::Scenario s, Fdi fdi) {
  s.fdi.position.enabled = s.fdi.attitude.enabled = fdi != Fdi::kOff;
  if (fdi != Fdi::kOn) s.fdi.isolation_method = model::IsolationMethod::kPaper;  // no deficit bank, no detector
  return s;
}

// The whole 1200 s run, every model on, no telemetry: simulated seconds per wall-clock second.
// The FDI variants fly the same run (fault-free, no alarm): their difference is what the FDI adds
// to a run, its design in memory at the start included.
// Flies `scenario` whole every iteration and reports simulated seconds per wall second.
void fly_whole_runs(benchmark::State& state, const model::Scenario& scenario) {
  double simulated_s = 0;
  for (auto _ : state) {
    const sim::RunResult result = sim::run_scenario(scenario);
    simulated_s += result.simulated_s;
    benchmark::DoNotOptimize(result);
  }
  state.counters["sim_s_per_wall_s"] = benchmark::Counter(simulated_s, benchmark::Counter::kIsRate);
}

void BM_EndToEnd(benchmark::State& state, bool with_fault, Fdi fdi) {
  model::Scenario scenario = with_fdi(msr_scenario(), fdi);
  if (with_fault) scenario.faults = {model::FaultParams{.kind = model::FaultKind::kStuckOpen, .thruster = 7}};
  fly_whole_runs(state, scenario);
}
BENCHMARK_CAPTURE(BM_EndToEnd, nominal, false, Fdi::kOn)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_EndToEnd, nominal_fdi_published, false, Fdi::kPublished)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_EndToEnd, nominal_fdi_off, false, Fdi::kOff)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_EndToEnd, stuck_open_T8, true, Fdi::kOn)->Unit(benchmark::kMillisecond)->UseRealTime();

// The COMRADE scenarios' whole runs as shipped (ENVISAT 1,200 s, ASSIST 1,600 s; every environment
// model on, 24 thrusters, FDI off as the scenarios have it), no telemetry. The target:
// 30,000 simulated s per CPU s.
void BM_EndToEndComrade(benchmark::State& state, const char* file) { fly_whole_runs(state, shipped_scenario(file)); }
BENCHMARK_CAPTURE(BM_EndToEndComrade, envisat, "comrade_envisat.yaml")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_EndToEndComrade, assist, "comrade_assist.yaml")->Unit(benchmark::kMillisecond)->UseRealTime();

// COMRADE's whole synchronisation (3,000 s): as shipped (the deficit detector, and the active
// checks read from the rates); without the checks (what their pulses and readings cost a run);
// without them, with the observer bank on beside the deficit detector (what the bank costs a run,
// its design at the start included); and as shipped with the supervisor running beside (its
// nine estimators on T1, T5, T13, T17, diagnosing only: what it costs a run, its design included).
enum class SyncFdi { kShipped, kNoChecks, kObserverBank, kSupervisor };
void BM_EndToEndSync(benchmark::State& state, SyncFdi fdi) {
  model::Scenario scenario = shipped_scenario("comrade_sync.yaml");
  scenario.fdi.observer_bank.enabled = fdi == SyncFdi::kObserverBank;
  scenario.fdi.supervisor.enabled = fdi == SyncFdi::kSupervisor;
  if (fdi == SyncFdi::kNoChecks || fdi == SyncFdi::kObserverBank)
    scenario.fdi.active_check.enabled = scenario.fdi.rate_check.enabled = false;
  fly_whole_runs(state, scenario);
}
BENCHMARK_CAPTURE(BM_EndToEndSync, shipped, SyncFdi::kShipped)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_EndToEndSync, no_checks, SyncFdi::kNoChecks)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_EndToEndSync, observer_bank, SyncFdi::kObserverBank)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_EndToEndSync, supervisor, SyncFdi::kSupervisor)->Unit(benchmark::kMillisecond)->UseRealTime();

// The supervisor's period alone (flight/fdi/mode_supervisor.hpp): comrade_sync's nominal observer
// of order 9 and the eight corrections of T1, T5, T13 and T17 stuck open and stuck closed, settled.
void BM_SupervisorPeriod(benchmark::State& state) {
  model::Scenario scenario = shipped_scenario("comrade_sync.yaml");
  scenario.fdi.supervisor.enabled = true;
  const flight::fdi::SupervisorParams params = *flight::make_flight_params(scenario).supervisor;
  flight::fdi::SupervisorState supervisor = flight::fdi::make_supervisor_state(params);
  constexpr std::size_t kInputs = 1000;
  std::vector<Vec3> rates(kInputs);
  std::vector<model::ThrusterOnTimes> on_times(kInputs, model::ThrusterOnTimes{});
  Uniform uniform;
  for (std::size_t k = 0; k < kInputs; ++k) {
    rates[k] = Vec3(0.03, -0.02, 0.01) + 1e-4 * Vec3(uniform(), uniform(), uniform());
    for (int t = 0; t < scenario.thrusters.count; ++t) on_times[k][static_cast<std::size_t>(t)] = 0.05 * uniform();
  }
  double t_s = 0.0;
  for (std::size_t k = 0; k < 1100; ++k, t_s += 0.1)  // past settle_s
    flight::fdi::step_supervisor(params, supervisor, t_s, rates[k % kInputs], on_times[k % kInputs]);
  std::size_t k = 0;
  for (auto _ : state) {
    flight::fdi::step_supervisor(params, supervisor, t_s, rates[k], on_times[k]);
    k = k + 1 == kInputs ? 0 : k + 1;
  }
  benchmark::DoNotOptimize(supervisor.mu);
}
BENCHMARK(BM_SupervisorPeriod);

// The observer bank's period alone (flight/fdi/observer_bank.hpp): comrade_sync's 25 observers of
// order 9 on 24 thrusters, fed 1,000 recorded-like periods in turn (rates near the hold's, random
// on-times), its window full and deciding every tenth period.
void BM_ObserverBankPeriod(benchmark::State& state) {
  model::Scenario scenario = shipped_scenario("comrade_sync.yaml");
  scenario.fdi.observer_bank.enabled = true;
  const flight::FdirParams fdir = flight::make_flight_params(scenario).fdir;
  flight::fdi::ObserverBankState bank = flight::fdi::make_observer_bank_state(fdir.bank);
  const flight::fdi::WatchedSet& set = fdir.watched[0].set;
  constexpr std::size_t kInputs = 1000;
  std::vector<Vec3> rates(kInputs);
  std::vector<flight::fdi::WatchedTon> on_times(kInputs, flight::fdi::WatchedTon::Zero());
  std::vector<Vec6> wrenches(kInputs, Vec6::Zero());
  Uniform uniform;
  for (std::size_t k = 0; k < kInputs; ++k) {
    rates[k] = Vec3(0.03, -0.02, 0.01) + 1e-4 * Vec3(uniform(), uniform(), uniform());
    for (int lane = 0; lane < set.count; ++lane) on_times[k][lane] = 0.05 * uniform();
  }
  for (std::size_t k = 0; k < 1300; ++k)  // fill W + L = 120 s of blocks
    flight::fdi::step_observer_bank(fdir.bank, bank, rates[k % kInputs], set, on_times[k % kInputs], wrenches[0]);
  std::size_t k = 0;
  for (auto _ : state) {
    flight::fdi::step_observer_bank(fdir.bank, bank, rates[k], set, on_times[k], wrenches[k]);
    k = k + 1 == kInputs ? 0 : k + 1;
  }
  benchmark::DoNotOptimize(bank.statistic_Nm);
}
BENCHMARK(BM_ObserverBankPeriod);

// The rate check's period alone (flight/fdi/rate_check.hpp) on comrade_sync's 24 thrusters: a check
// every seventh period (the sync's busiest rate of checks) with eight thrusters commanded beside
// its pulse, each check read against its 2 x 5 neighbours and every commanded thruster's hypothesis.
void BM_RateCheckPeriod(benchmark::State& state) {
  model::Scenario scenario = shipped_scenario("comrade_sync.yaml");
  scenario.fdi.active_check.enabled = scenario.fdi.rate_check.enabled = true;
  const flight::FdirParams fdir = flight::make_flight_params(scenario).fdir;
  flight::fdi::RateCheckState check;
  constexpr std::size_t kInputs = 1001;  // a multiple of 7, so that the checks' pattern repeats
  std::vector<flight::fdi::RateCheckInput> inputs(kInputs);
  Uniform uniform;
  for (std::size_t k = 0; k < kInputs; ++k) {
    flight::fdi::RateCheckInput& in = inputs[k];
    in.t_s = 0.1 * static_cast<double>(k);
    in.omega_body_radps = Vec3(0.03, -0.02, 0.01) + 1e-4 * Vec3(uniform(), uniform(), uniform());
    in.torque_cmd_body_Nm = Vec3(uniform(), uniform(), uniform());
    for (int i = 0; i < 8; ++i) in.on_fraction[static_cast<std::size_t>(3 * i + (k % 3))] = 0.05 * uniform();
    if (k % 7 == 0) {
      in.checked = static_cast<int>((k / 7) % 24);
      in.on_fraction[static_cast<std::size_t>(in.checked)] = 0.075;
    }
  }
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(flight::fdi::step_rate_check(fdir.rate_check, check, inputs[k]));
    k = k + 1 == kInputs ? 0 : k + 1;
  }
}
BENCHMARK(BM_RateCheckPeriod);

// What `chaser run` waits for, less process start and scenario loading: the whole 1200 s run with
// its telemetry file written (csv or npy, every channel, finished and renamed), against none. The
// target: at least half the rate of BM_ControlPeriod/fdi_on's closed loop. As `chaser run`
// does, each run first removes the last one's file (renaming over it costs an ext4 flush).
void BM_RunWithTelemetry(benchmark::State& state, const char* extension) {
  const model::Scenario scenario = msr_scenario();
  const std::string path =
      *extension ? (std::filesystem::temp_directory_path() / (std::string("chaser_bench_telemetry.") + extension)).string()
                 : std::string();
  double simulated_s = 0;
  for (auto _ : state) {
    if (!path.empty()) std::filesystem::remove(path);
    const sim::RunResult result = sim::run_scenario(scenario, {.telemetry_path = path, .telemetry_channels = {}});
    if (!result.telemetry_ok) state.SkipWithError("telemetry not written");
    simulated_s += result.simulated_s;
  }
  if (!path.empty()) std::filesystem::remove(path);
  state.counters["sim_s_per_wall_s"] = benchmark::Counter(simulated_s, benchmark::Counter::kIsRate);
}
BENCHMARK_CAPTURE(BM_RunWithTelemetry, csv, "csv")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_RunWithTelemetry, npy, "npy")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_RunWithTelemetry, none, "")->Unit(benchmark::kMillisecond)->UseRealTime();

// Shared set-up for the per-period benchmarks: a plant and flight software 500 s into the approach.
struct LoopFixture {
  model::Scenario scenario;
  plant::Plant plant;
  flight::FlightParams flight_params = flight::make_flight_params(scenario);
  flight::FlightState flight_state;
  model::TargetOrbit circle{scenario.orbit};
  TimeNs period_ns = from_seconds(scenario.control_period_s);
  TimeNs t_ns = 0;

  explicit LoopFixture(Fdi fdi = Fdi::kOn) : LoopFixture(with_fdi(msr_scenario(), fdi)) {}
  explicit LoopFixture(model::Scenario s)
      : scenario(std::move(s)), plant(plant::make_plant(scenario, start_state(scenario), scenario.seed)) {
    for (int k = 0; k < 5000; ++k) step();
  }
  static plant::RigidState start_state(const model::Scenario& s) {
    const flight::GuidanceRef ref = flight::guidance_reference(s.guidance, model::TargetOrbit(s.orbit), 0.0);
    return plant::RigidState{ref.r_lvlh_m, ref.v_lvlh_mps, ref.q_inertial_from_body, ref.omega_body_radps,
                             s.chaser.mass_kg};
  }
  model::ThrusterCommand flight_period() { return flight_period_traced().command; }
  flight::FlightOutput flight_period_traced() {
    last_meas = plant::sense_plant(plant.params, plant.state, t_ns,
                                   plant::q_inertial_from_lvlh(plant, circle, to_seconds(t_ns)));
    return flight::step_flight(flight_params, flight_state, last_meas);
  }
  model::SensorMeasurements last_meas;
  void step() {
    const model::ThrusterCommand command = flight_period();
    plant::step_plant(plant.params, plant.state, command, t_ns);
    t_ns += period_ns;
  }
};

// One full control period: sensors, flight software, thruster model and propagation, with the
// scenario's FDI (both published schemes, Chaser's deficit bank and detector), with the published
// method alone (isolation_method: paper), and off: the differences are what each costs.
//
// Every variant flies the same 200 s (2,000 periods from 500 s into the approach, fault-free) over
// and over: the state goes back to the 500 s one, untimed, every 2,000 periods. Left to run on, a
// faster variant would fly further (past the capture, hours of simulated time) and the variants
// would time different periods.
// The closed loop from 500 s into the approach, put back there every 2,000 periods.
struct Flier {
  LoopFixture f;
  plant::PlantState plant_start = f.plant.state;
  std::unique_ptr<flight::FlightState> flight_start = std::make_unique<flight::FlightState>(f.flight_state);
  TimeNs t_start = f.t_ns;
  explicit Flier(Fdi fdi) : f(fdi) {}
  explicit Flier(model::Scenario s) : f(std::move(s)) {}
  void reset() {
    f.plant.state = plant_start;
    f.flight_state = *flight_start;
    f.t_ns = t_start;
  }
};
constexpr int kFlownPeriods = 2000;

// Steps the closed loop once per iteration, back to the start (untimed) every kFlownPeriods.
void fly_timed(benchmark::State& state, Flier& flier) {
  int k = 0;
  for (auto _ : state) {
    flier.f.step();
    if (++k == kFlownPeriods) {
      state.PauseTiming();
      flier.reset();
      k = 0;
      state.ResumeTiming();
    }
  }
}

void BM_ControlPeriod(benchmark::State& state, Fdi fdi) {
  Flier flier(fdi);
  fly_timed(state, flier);
}
BENCHMARK_CAPTURE(BM_ControlPeriod, fdi_on, Fdi::kOn);
BENCHMARK_CAPTURE(BM_ControlPeriod, fdi_published, Fdi::kPublished);
BENCHMARK_CAPTURE(BM_ControlPeriod, fdi_off, Fdi::kOff);

// The same closed-loop period on the COMRADE ENVISAT scenario, 500 s into its V-bar leg: the
// perturbed plant with the tumbling target, and flight software allocating 24 thrusters.
void BM_ControlPeriodComrade(benchmark::State& state) {
  Flier flier(shipped_scenario("comrade_envisat.yaml"));
  fly_timed(state, flier);
}
BENCHMARK(BM_ControlPeriodComrade);

// The FDI's share of a control period, paired: the three variants of BM_ControlPeriod fly their
// 2,000 periods in turn (the order rotating), each timed, so that what drifts on a shared machine
// (clock, neighbours: BM_ControlPeriod's repetitions spread by +-50 ns) falls on all three alike.
// Counters: period_off_ns, and share_published and share_on = (variant - off) / off, the FDI's
// added cost as a fraction of the period without it (the budget: at most 0.10).
void BM_FdiShareOfControlPeriod(benchmark::State& state) {
  std::array<Flier, 3> fliers{Flier(Fdi::kOff), Flier(Fdi::kPublished), Flier(Fdi::kOn)};
  std::array<double, 3> seconds{};
  int round = 0;
  for (auto _ : state) {
    for (int j = 0; j < 3; ++j) {
      const int v = (round + j) % 3;
      const auto start = std::chrono::steady_clock::now();
      for (int k = 0; k < kFlownPeriods; ++k) fliers[v].f.step();
      seconds[v] += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      fliers[v].reset();
    }
    ++round;
  }
  const double periods = static_cast<double>(state.iterations()) * kFlownPeriods;
  state.counters["period_off_ns"] = 1e9 * seconds[0] / periods;
  state.counters["share_published"] = seconds[1] / seconds[0] - 1.0;
  state.counters["share_on"] = seconds[2] / seconds[0] - 1.0;
}
BENCHMARK(BM_FdiShareOfControlPeriod)->Unit(benchmark::kMillisecond)->MinTime(3.0);

// Thruster model and propagation of one period with a fixed command: T1 for 30 % and its partner
// T5 for 60 % of the period (a pure torque plus a net force; five pieces with the delay).
// The COMRADE variant is the perturbed Earth-orbit plant (both bodies, every environment model)
// under the same command on its 24-thruster set: the plant's per-period cost beside MSR's.
void BM_PropagationPeriod(benchmark::State& state, const char* file) {
  LoopFixture f(shipped_scenario(file));
  model::ThrusterCommand command;
  command.ton[0] = 0.3;
  command.ton[4] = 0.6;
  for (auto _ : state) {
    plant::step_plant(f.plant.params, f.plant.state, command, f.t_ns);
    f.t_ns += f.period_ns;
  }
}
BENCHMARK_CAPTURE(BM_PropagationPeriod, msr, "msr_terminal.yaml");
BENCHMARK_CAPTURE(BM_PropagationPeriod, comrade_envisat, "comrade_envisat.yaml");

// Flight software alone: navigation, guidance, control, TMU, TMF. The plant stays frozen 500 s into
// the approach while the reference moves on, so the controllers demand thrust and the allocator
// runs every period: a busier period than the closed loop's typical one.
void BM_FlightPeriod(benchmark::State& state, Fdi fdi) {
  LoopFixture f(fdi);
  for (auto _ : state) {
    benchmark::DoNotOptimize(f.flight_period());
    f.t_ns += f.period_ns;
  }
}
BENCHMARK_CAPTURE(BM_FlightPeriod, fdi_on, Fdi::kOn);
BENCHMARK_CAPTURE(BM_FlightPeriod, fdi_off, Fdi::kOff);

// The FDIR alone (flight::step_fdir: both published schemes, event resolution, and with
// `deficit` the deficit bank and detector), replayed on 2,000 periods (200 s) of the closed loop
// recorded from 500 s into the approach, fault-free, so every period is the usual one: no alarm,
// no isolation. Its time against BM_ControlPeriod/fdi_off (which flies the same 200 s) is the FDI's
// share of a control period (the budget: at most 10 %). Every 2,000 periods the state goes back to the
// recorded start, untimed.
void BM_FdirPeriod(benchmark::State& state, Fdi fdi) {
  LoopFixture f(fdi);
  const flight::FdirState start = f.flight_state.fdir;
  std::vector<std::pair<model::SensorMeasurements, flight::FdirInput>> trace;
  for (int k = 0; k < 2000; ++k) {
    const flight::FlightOutput out = f.flight_period_traced();
    const double t_s = to_seconds(f.last_meas.t);
    // What step_flight hands step_fdir (flight_software.cpp), rebuilt from its output.
    trace.emplace_back(f.last_meas,
                       flight::FdirInput{.t_s = t_s,
                                         .period = f.last_meas.t / f.period_ns,
                                         .q_est_inertial_from_body = out.estimate.q_inertial_from_body,
                                         .q_ref_inertial_from_body = out.reference.q_inertial_from_body,
                                         .q_inertial_from_lvlh = f.flight_params.orbit.q_inertial_from_lvlh(t_s),
                                         .ton = flight::watched_on_times(f.flight_params.fdir, f.flight_state.fdir, out.command.ton),
                                         .commanded_wrench = out.commanded_wrench});
    plant::step_plant(f.plant.params, f.plant.state, out.command, f.t_ns);
    f.t_ns += f.period_ns;
  }
  auto fdir = std::make_unique<flight::FdirState>(start);
  std::size_t k = 0;
  int alarms = 0;
  for (auto _ : state) {
    flight::FdirOutput out;
    flight::step_fdir(f.flight_params.fdir, *fdir, trace[k].first, trace[k].second, out);
    benchmark::DoNotOptimize(out);
    if (++k == trace.size()) {
      state.PauseTiming();
      alarms += std::any_of(out.schemes.begin(), out.schemes.end(), [](const auto& s) { return s.alarm; });
      *fdir = start;
      k = 0;
      state.ResumeTiming();
    }
  }
  if (alarms > 0) state.SkipWithError("the fault-free replay raised an alarm: not the usual period");
}
BENCHMARK_CAPTURE(BM_FdirPeriod, fdi_on, Fdi::kOn);
BENCHMARK_CAPTURE(BM_FdirPeriod, fdi_published, Fdi::kPublished);

}  // namespace
