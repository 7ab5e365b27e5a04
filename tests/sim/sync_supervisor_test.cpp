// The multi-estimator supervisor (fdi.supervisor; flight/fdi/mode_supervisor.hpp, flight/supervision.hpp;
// docs/fdi.md, "The supervisor") in COMRADE's synchronised flight, accommodating (fdi.recovery: none):
// fault-free it never leaves the nominal mode; T5 stuck open in the hold switches it once to "T5
// stuck open" within seconds, after which the allocation flies without T5 and cancels its thrust,
// and the hold ends on its marks; bad keys are refused by name.
#include <gtest/gtest.h>

#include <string>
#include <vector>

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
// COMRADE Table 1's 0.2 m of its reference, its thrust cancelled. The mode's allocation meets every
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
  EXPECT_LT(run.figures.final_position_error_m, 0.2);
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

}  // namespace
}  // namespace chaser::sim
