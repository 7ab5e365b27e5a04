// The multi-estimator supervisor (fdi.supervisor; flight/fdi/mode_supervisor.hpp, flight/supervision.hpp;
// docs/fdi.md, "The supervisor") in COMRADE's synchronised flight, accommodating (fdi.recovery: none):
// fault-free it never leaves the nominal mode; T5 stuck open in the hold switches it once to "T5
// stuck open" within seconds, after which the allocation flies without T5 and cancels its thrust,
// and the hold ends on its marks; bad keys are refused by name.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/scenario_loader.hpp"
#include "io/scenario_sections.hpp"
#include "model/positive_span.hpp"
#include "model/thruster_geometry.hpp"
#include "sim/run.hpp"
#include "tests/support/scenario_refusal.hpp"

namespace chaser::sim {
namespace {

model::Scenario supervised() {
  return testing::load_with("scenarios/comrade_sync.yaml",
                            {"fdi.supervisor.enabled=true", "fdi.supervisor.accommodate=true", "fdi.recovery=none"});
}

// Seed 1, the whole 3,000 s: no switch (200 dispersed runs: none, docs/fdi.md).
TEST(SyncSupervisor, AFaultFreeSynchronisationStaysNominal) {
  const RunResult run = run_scenario(supervised());
  ASSERT_TRUE(run.supervisor.enabled);
  EXPECT_EQ(run.supervisor.switches, 0);
  EXPECT_EQ(run.supervisor.thruster, model::kNoThruster);
  EXPECT_TRUE(run.figures.capture_achieved);
}

// T5 stuck open at 1,500 s: mode 3 ("T5 stuck open": T1's two modes come first) within 3 s (the
// monitoring signal's 2 s memory; seed 1: 2.3 s), one switch; 200 s on, the chaser holds within
// COMRADE Table 1's 0.1 m of the capture point (seed 1: 0.043 m), its thrust cancelled. The mode's allocation meets every
// demand exactly, unsaturated (the virtual actuator's state stays zero: the loop the controller
// sees is the nominal's).
TEST(SyncSupervisor, AStuckOpenThrusterIsFlownAround) {
  model::Scenario s = supervised();
  s.faults = {model::FaultParams{.kind = model::FaultKind::kStuckOpen, .thruster = 4, .onset_s = 1500.0}};
  s.duration_s = 1700.0;
  const RunResult run = run_scenario(s);
  ASSERT_EQ(run.supervisor.switches, 1);
  EXPECT_EQ(run.supervisor.log[0].mode, 3);
  EXPECT_EQ(run.supervisor.thruster, 4);
  EXPECT_EQ(run.supervisor.fault, flight::fdi::SupervisorFault::kStuckOpen);
  EXPECT_GT(run.supervisor.log[0].t_s, 1500.0);
  EXPECT_LT(run.supervisor.log[0].t_s, 1503.0);
  EXPECT_LT(run.figures.final_position_error_m, 0.1);
  EXPECT_EQ(run.infeasible_allocations, 0);
  EXPECT_EQ(run.saturated_periods, 0);
}

TEST(SyncSupervisor, BadKeysAreRefusedByName) {
  testing::expect_refused("scenarios/comrade_sync.yaml", {"fdi.supervisor.enabled=true", "fdi.supervisor.accommodate=true"},
                          "fdi.supervisor.accommodate", "needs fdi.recovery: none");
  testing::expect_refused("scenarios/comrade_sync.yaml", {"fdi.supervisor.accommodate=true"},
                          "fdi.supervisor.accommodate", "needs fdi.supervisor.enabled");
  testing::expect_refused("scenarios/comrade_sync.yaml", {"fdi.supervisor.enabled=true", "fdi.supervisor.thrusters=[T1, T99]"},
                          "fdi.supervisor.thrusters.1", "must be a thruster name");
  testing::expect_refused("scenarios/comrade_sync.yaml", {"fdi.supervisor.dwell_s=0"}, "fdi.supervisor.dwell_s", "");
  testing::expect_refused("scenarios/comrade_sync.yaml", {"fdi.supervisor.enabled=true", "fdi.supervisor.dwell_s=0.01"},
                          "fdi.supervisor.dwell_s", "must be >= control_period_s");
}

// Accommodating, a monitored thruster's modes fly the starting set without it: on a set that needs
// every one of its thrusters to push and turn everywhere (COMRADE's 24 cut down, one thruster at a
// time, while they still span), the supervisor is refused by name.
TEST(SyncSupervisor, AThrusterTheSetCannotFlyWithoutIsRefused) {
  model::Scenario s = supervised();
  model::ThrusterMask kept = model::initial_active_set(s.thrusters);
  for (int t = 0; t < s.thrusters.count; ++t) {
    const model::ThrusterMask without = kept & ~model::thruster_bit(t);
    if (model::positive_span(model::configuration_columns(s.thrusters, without, s.chaser.com_body_m)).spans) kept = without;
  }
  model::ThrusterSetParams minimal = s.thrusters;
  minimal.count = 0;
  for (int t = 0; t < s.thrusters.count; ++t)
    if (kept >> t & 1U) minimal.thrusters[static_cast<std::size_t>(minimal.count++)] = s.thrusters.thrusters[static_cast<std::size_t>(t)];
  ASSERT_GE(minimal.count, 7);  // six directions need seven thrusters at least
  s.thrusters = minimal;
  s.fdi.supervisor.thrusters = model::thruster_bit(0);
  io::Diagnostics d;
  io::validate_scenario(s, d);
  const std::string errors = io::format_errors(d.errors());
  EXPECT_NE(errors.find("fdi.supervisor.thrusters: T1's modes fly the set that flies at the start without it"),
            std::string::npos)
      << errors;
  s.fdi.supervisor.accommodate = false;  // diagnosing only, it flies nothing without T1
  io::Diagnostics quiet;
  io::validate_scenario(s, quiet);
  EXPECT_EQ(io::format_errors(quiet.errors()).find("fdi.supervisor"), std::string::npos) << io::format_errors(quiet.errors());
}

}  // namespace
}  // namespace chaser::sim
