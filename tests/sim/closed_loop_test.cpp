// Closed-loop runs of the MSR terminal rendezvous scenario: the whole chain, plant and flight.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/scenario_loader.hpp"
#include "sim/run.hpp"

namespace chaser::sim {
namespace {

model::Scenario msr_scenario() {
  const io::LoadResult loaded = io::load_scenario_file("scenarios/msr_terminal.yaml");
  EXPECT_TRUE(loaded.errors.empty()) << io::format_errors(loaded.errors);
  return *loaded.scenario;
}

// Nominal parameters, no fault: for 20 seeds (delays, noises, disturbances, thruster dispersion all
// redrawn) the chaser reaches the capture point inside the corridor with the target in view, and
// no FDI scheme raises an alarm (J_th = 20 against a fault-free maximum of about 13; the deficit
// detector's 100 against 22).
TEST(ClosedLoop, NominalApproachCapturesForTwentySeeds) {
  model::Scenario scenario = msr_scenario();
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    scenario.seed = seed;
    const RunResult r = run_scenario(scenario);
    const MissionFigures& f = r.figures;
    EXPECT_TRUE(f.capture_achieved) << "seed " << seed << ": final position error " << f.final_position_error_m
                                    << " m, speed " << f.final_speed_mps << " m/s, attitude "
                                    << f.final_attitude_error_rad << " rad";
    EXPECT_EQ(f.corridor_violation_periods, 0) << "seed " << seed << ", max angle " << f.max_corridor_angle_rad;
    EXPECT_EQ(f.out_of_view_periods, 0) << "seed " << seed;
    EXPECT_FALSE(f.diverged) << "seed " << seed;
    EXPECT_LT(scheme_result(r.fdir, "position").alarm_s, 0) << "seed " << seed << ": position-scheme false alarm";
    EXPECT_LT(scheme_result(r.fdir, "attitude").alarm_s, 0) << "seed " << seed << ": attitude-scheme false alarm";
    EXPECT_LT(scheme_result(r.fdir, "deficit").alarm_s, 0) << "seed " << seed << ": deficit-scheme false alarm";
    EXPECT_DOUBLE_EQ(r.simulated_s, scenario.duration_s);
  }
}

// A thruster stuck open at 1000 s with no diagnosis: the 22 N hard-over overwhelms a control loop
// designed for fractions of a newton, so the run must show it (corridor, capture, propellant).
TEST(ClosedLoop, StuckOpenWithoutDiagnosisIsVisibleInTheSummary) {
  model::Scenario scenario = msr_scenario();
  scenario.fdi.position.enabled = scenario.fdi.attitude.enabled = false;
  scenario.fdi.recovery = model::RecoveryPolicy::kNone;
  const RunResult nominal = run_scenario(scenario);
  scenario.faults = {model::FaultParams{.kind = model::FaultKind::kStuckOpen, .thruster = 7, .onset_s = 1000.0}};
  const RunResult faulty = run_scenario(scenario);
  const MissionFigures& f = faulty.figures;
  EXPECT_FALSE(f.capture_achieved);
  EXPECT_GT(faulty.propellant_used_kg, nominal.propellant_used_kg + 1.0);  // > 1 kg extra over 200 s
  EXPECT_TRUE(f.corridor_violation_periods > 0 || f.max_attitude_error_rad > 0.1 || f.diverged);
}

// The same fault with the FDIR on: a scheme raises the alarm within seconds, recovery closes
// branch A's latch valve (stopping the stuck thruster) and branch B brings the chaser to capture.
TEST(ClosedLoop, StuckOpenIsDetectedAndRecoveredOnBranchB) {
  model::Scenario scenario = msr_scenario();
  scenario.faults = {model::FaultParams{.kind = model::FaultKind::kStuckOpen, .thruster = 7, .onset_s = 1000.0}};
  const RunResult r = run_scenario(scenario);
  const auto earliest = [](double a, double b) { return a < 0 ? b : (b < 0 ? a : std::min(a, b)); };
  const double first_alarm_s = earliest(scheme_result(r.fdir, "position").alarm_s, scheme_result(r.fdir, "attitude").alarm_s);
  EXPECT_GE(first_alarm_s, 1000.0);
  EXPECT_LT(first_alarm_s, 1005.0);
  EXPECT_GE(r.fdir.recovery_s, first_alarm_s);
  EXPECT_TRUE(r.figures.capture_achieved);
  EXPECT_EQ(r.figures.corridor_violation_periods, 0);
}

// Diagnosis keeps running after a recovery: T8 (branch A) sticks open at 1000 s, recovery closes
// branch A's latch and flies branch B; T12 (branch B) sticks open at 1100 s and is detected and
// isolated like the first (the FDI re-armed on branch B's eight thrusters, rearm_after_recovery_s
// after the switch). No standby group is left, so the second diagnosis triggers no recovery.
TEST(ClosedLoop, SecondFaultAfterRecoveryIsDiagnosedOnBranchB) {
  model::Scenario scenario = msr_scenario();
  scenario.duration_s = 1130.0;
  scenario.faults = {model::FaultParams{.kind = model::FaultKind::kStuckOpen, .thruster = 7, .onset_s = 1000.0},
                     model::FaultParams{.kind = model::FaultKind::kStuckOpen, .thruster = 11, .onset_s = 1100.0}};
  const RunResult r = run_scenario(scenario);
  ASSERT_EQ(r.fdir.episodes.size(), 2u);
  const FdirResult& first = r.fdir.episodes[0];
  const FdirResult& second = r.fdir.episodes[1];
  EXPECT_EQ(first.isolated_thruster, 7);  // T8
  EXPECT_EQ(first.recovered_thruster, 7);
  EXPECT_GE(first.detection_s, 1000.0);
  EXPECT_LT(first.detection_s, 1005.0);
  EXPECT_EQ(second.isolated_thruster, 11);  // T12
  EXPECT_GE(second.detection_s, 1100.0);
  EXPECT_LT(second.detection_s, 1105.0);
  EXPECT_EQ(second.recovery_s, -1.0);  // branch B was the last standby group
  EXPECT_EQ(r.fdir.isolated_thruster, 7);  // the top-level fields are the first diagnosis's
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Same scenario and seed give bit-identical telemetry (every channel printed to 10 digits) and
// identical figures; another seed gives different telemetry.
TEST(ClosedLoop, SameSeedGivesBitIdenticalTelemetry) {
  model::Scenario scenario = msr_scenario();
  scenario.duration_s = 200.0;
  const auto dir = std::filesystem::temp_directory_path() / "chaser_determinism_test";
  std::filesystem::create_directories(dir);
  const RunResult a = run_scenario(scenario, {.telemetry_path = (dir / "a.csv").string(), .telemetry_channels = {}});
  const RunResult b = run_scenario(scenario, {.telemetry_path = (dir / "b.csv").string(), .telemetry_channels = {}});
  scenario.seed += 1;
  run_scenario(scenario, {.telemetry_path = (dir / "c.csv").string(), .telemetry_channels = {}});
  const std::string ta = read_file(dir / "a.csv");
  EXPECT_GT(ta.size(), 100000u);
  EXPECT_EQ(ta, read_file(dir / "b.csv"));
  EXPECT_NE(ta, read_file(dir / "c.csv"));
  EXPECT_EQ(a.propellant_used_kg, b.propellant_used_kg);
  EXPECT_EQ(a.figures.final_position_error_m, b.figures.final_position_error_m);
  std::filesystem::remove_all(dir);
}

// A campaign builds the flight software once from the nominal scenario and flies it on dispersed
// plants. With truth = nominal the shared design must give exactly the run that designs for itself
// (same code path, same numbers: bit equality); with a heavier, rotated-inertia truth the same
// flight software still captures (the LQR gains and FDI are not redesigned for the truth), and the
// run differs, so the truth is what the plant flew.
TEST(ClosedLoop, FlightDesignedFromNominalFliesADispersedPlant) {
  model::Scenario nominal = msr_scenario();
  nominal.duration_s = 300.0;
  const flight::FlightParams flight = flight::make_flight_params(nominal);
  const RunResult own = run_scenario(nominal);
  const RunResult shared = run_scenario(nominal, flight, {.telemetry_path = {}, .telemetry_channels = {}, .record_glr_per_second = true});
  EXPECT_EQ(own.propellant_used_kg, shared.propellant_used_kg);
  EXPECT_EQ(own.figures.final_position_error_m, shared.figures.final_position_error_m);
  // The per-second GLR maxima: one entry per second, positive where a scheme runs, below J_th.
  ASSERT_EQ(shared.glr_max_per_s.size(), 300u);
  EXPECT_TRUE(own.glr_max_per_s.empty());
  for (const auto& second : shared.glr_max_per_s) {
    EXPECT_GT(second[0], 0.0f);
    EXPECT_LT(second[0], nominal.fdi.glr_threshold);
    EXPECT_LT(second[1], nominal.fdi.glr_threshold);
  }

  model::Scenario truth = nominal;
  truth.chaser.mass_kg *= 1.1;
  truth.chaser.inertia_kgm2 *= 0.8;
  truth.chaser.com_body_m = Vec3(0.03, -0.03, 0.03);
  const RunResult dispersed = run_scenario(truth, flight);
  EXPECT_NE(own.propellant_used_kg, dispersed.propellant_used_kg);
  // 0.05 rad: the LIDAR keeps the target in view to 0.35 rad and capture needs 0.035 rad at the
  // end; the nominal run stays below 0.001 rad, so a flight design that fails on this truth (wrong
  // inertia in the LQR, an FDI false alarm and a branch switch) would show here.
  EXPECT_LT(dispersed.figures.max_attitude_error_rad, 0.05);
  EXPECT_EQ(dispersed.figures.corridor_violation_periods, 0);
}

}  // namespace
}  // namespace chaser::sim
