// The active checks read from the rates (fdi.rate_check; flight/fdi/rate_check.hpp; docs/fdi.md,
// "Checks read from the rates") in COMRADE's synchronised flight, where the impulse statistic
// cannot see a thruster the flight does not fire: a fault-free run checks every thruster all along
// for half a kilogram and never alarms; T1, which the hold never fires, stuck closed in the
// fly-around, T4 weakened by 40 % in the hold, and T1 leaking in the fly-around, are each named, with
// their fault, by their checks; the rate check alone watches the checks; a rate check without the
// active checks is refused by name.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "core/constants.hpp"
#include "flight/diagnosis_schemes.hpp"
#include "sim/run.hpp"
#include "tests/support/scenario_refusal.hpp"

namespace chaser::sim {
namespace {

model::Scenario sync_checked(bool checks) {
  return testing::load_with("scenarios/comrade_sync.yaml",
                            {std::string("fdi.active_check.enabled=") + (checks ? "true" : "false"),
                             std::string("fdi.rate_check={enabled: ") + (checks ? "true" : "false") + "}"});
}

// Seed 1, fault-free: ~1,500 checks (each of the 24 every 25 s that the flight leaves it idle, and
// again at once where a busy period leaves a reading inconclusive), never three readings in a row at
// the threshold. Their propellant: a check burns its pulse, p = F t_pulse / (Isp g0), and its
// cancellers about as much again (their forces sum to the pulse's opposite), less what the two save
// the controller: between one and three p per check (the upper end: cancellers at twice the pulse,
// each cancelling force and torque in part). Seed 1: 1,537 checks, 0.21 kg more than without
// them (8.96 kg), 1.8 p per check.
TEST(SyncRateCheck, AFaultFreeSynchronisationChecksAllAlongAndNeverAlarms) {
  const RunResult checked = run_scenario(sync_checked(true));
  const RunResult unchecked = run_scenario(sync_checked(false));
  const SchemeResult& r = checked.fdir.schemes[flight::kRateCheckScheme];
  EXPECT_TRUE(r.enabled);
  EXPECT_LT(r.alarm_s, 0.0);
  EXPECT_LT(checked.fdir.isolated_thruster, 0);
  EXPECT_GT(checked.active_checks, 1000);
  EXPECT_EQ(unchecked.active_checks, 0);
  const model::Scenario s = sync_checked(true);
  double thrust_min_N = 1e9, thrust_max_N = 0;
  for (int i = 0; i < s.thrusters.count; ++i) {
    thrust_min_N = std::min(thrust_min_N, s.thrusters.thrusters[static_cast<std::size_t>(i)].max_thrust_N);
    thrust_max_N = std::max(thrust_max_N, s.thrusters.thrusters[static_cast<std::size_t>(i)].max_thrust_N);
  }
  const double pulse_kg = s.fdi.active_check.pulse_s / (s.chaser.isp_s * kStandardGravity);  // per N
  const double per_check_kg =
      (checked.propellant_used_kg - unchecked.propellant_used_kg) / static_cast<double>(checked.active_checks);
  EXPECT_GT(per_check_kg, thrust_min_N * pulse_kg);
  EXPECT_LT(per_check_kg, 3.0 * thrust_max_N * pulse_kg);
  EXPECT_TRUE(checked.figures.capture_achieved);
}

struct Case {
  model::FaultParams fault;
  double within_s;  // [s] after the onset
  model::FaultKind read_as;
  // [-] the size read (a loss's or a leak's; 1 for stuck closed), within 0.05: past a healthy
  // thruster's open share, -0.037..+0.038 over a fault-free flight (docs/fdi.md)
  double size;
};

// T1 stuck closed at 1,500 s: checked within 25 s of the onset, read 1.0 three times in a row
// (seed 1: 3.0 s). T4 losing 40 % at 2,750 s, in the hold that never fires it: each check reads
// ~0.4 against the threshold 0.25 (seed 1: 19.1 s, read as a loss of 0.43). T1 leaking 0.15 at
// 1,500 s: its checks' pulses add nothing (the valve is open already) and read 1, their baselines
// hold its torque uncommanded, 0.15 of its thrust: a leak of 0.15 (seed 1: 3.7 s, 0.151), whose
// thrust the recovery cancels, not stuck closed.
TEST(SyncRateCheck, AThrusterTheFlightDoesNotFireIsNamedByItsChecks) {
  const std::vector<Case> cases = {
      {{.kind = model::FaultKind::kStuckClosed, .thruster = 0, .onset_s = 1500.0}, 30.0, model::FaultKind::kStuckClosed, 1.0},
      {{.kind = model::FaultKind::kLoss, .thruster = 3, .onset_s = 2750.0, .loss_size = 0.4}, 60.0, model::FaultKind::kLoss,
       0.4},
      {{.kind = model::FaultKind::kLeak, .thruster = 0, .onset_s = 1500.0, .leak_size = 0.15, .leak_slope_per_s = 0.1},
       30.0, model::FaultKind::kLeak, 0.15},
  };
  for (const Case& c : cases) {
    model::Scenario s = sync_checked(true);
    s.faults = {c.fault};
    s.duration_s = c.fault.onset_s + c.within_s + 10.0;
    const RunResult run = run_scenario(s);
    const SchemeResult& r = run.fdir.schemes[flight::kRateCheckScheme];
    EXPECT_EQ(r.isolated_thruster, c.fault.thruster);
    EXPECT_GT(r.isolated_s, c.fault.onset_s) << c.fault.thruster;
    EXPECT_LT(r.isolated_s, c.fault.onset_s + c.within_s) << c.fault.thruster;
    EXPECT_EQ(r.diagnosed_kind, c.read_as) << c.fault.thruster;
    EXPECT_NEAR(r.diagnosed_size, c.size, 0.05) << c.fault.thruster;
    EXPECT_EQ(run.fdir.isolated_thruster, c.fault.thruster);  // the FDIR's confirmation: the recovery acts on it
  }
}

// The rate check is a scheme that watches the checks: with every other scheme off the scenario
// flies, and the checks are read.
TEST(SyncRateCheck, AloneItWatchesTheChecks) {
  model::Scenario s = testing::load_with("scenarios/comrade_sync.yaml", {"fdi.deficit.detection=false"});
  s.faults = {model::FaultParams{.kind = model::FaultKind::kStuckClosed, .thruster = 0, .onset_s = 1500.0}};
  s.duration_s = 1540.0;
  const RunResult run = run_scenario(s);
  EXPECT_FALSE(run.fdir.schemes[flight::kDeficitScheme].enabled);
  EXPECT_EQ(run.fdir.schemes[flight::kRateCheckScheme].isolated_thruster, 0);
}

TEST(SyncRateCheck, WithoutTheActiveChecksItIsRefusedByName) {
  testing::expect_refused("scenarios/comrade_sync.yaml", {"fdi.active_check.enabled=false", "fdi.rate_check={enabled: true}"},
                          "fdi.rate_check.enabled", "needs fdi.active_check.enabled");
  testing::expect_refused("scenarios/comrade_sync.yaml", {"fdi.rate_check={enabled: true, neighbours: 11}"},
                          "fdi.rate_check.neighbours", "");
  testing::expect_refused("scenarios/comrade_sync.yaml", {"fdi.rate_check={threshold: 1.5}"}, "fdi.rate_check.threshold",
                          "");
}

}  // namespace
}  // namespace chaser::sim
