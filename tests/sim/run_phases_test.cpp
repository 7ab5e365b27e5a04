// The run's phases: summary.json's plan and the phase sequence are one list, and in COMRADE's
// synchronisation the phases switch in the very periods the flight software's guidance switches
// its steps (flight/sync_approach.hpp), so a phase names what the chaser was doing.
#include "sim/run_phases.hpp"

#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "flight/sync_approach.hpp"
#include "io/scenario_loader.hpp"
#include "sim/mission_monitor.hpp"
#include "sim/simulation.hpp"

namespace chaser::sim {
namespace {

model::Scenario load(const char* path) {
  const io::LoadResult loaded = io::load_scenario_file(path);
  EXPECT_TRUE(loaded.scenario) << io::format_errors(loaded.errors);
  return *loaded.scenario;
}

TEST(RunPhases, ThePlanAndThePhaseSequenceAreOneList) {
  for (const char* path : {"scenarios/msr_terminal.yaml", "scenarios/comrade_sync.yaml", "scenarios/comrade_assist.yaml"}) {
    const model::Scenario s = load(path);
    const std::vector<PlannedPhase> plan = planned_phases(s);
    const PhaseSequenceParams p = run_phases(s);
    EXPECT_TRUE(validate(p).empty()) << path;
    ASSERT_EQ(p.phases.size(), plan.size()) << path;
    for (std::size_t i = 0; i < plan.size(); ++i) {
      EXPECT_EQ(p.phases[i].name, plan[i].name);
      if (i + 1 < plan.size()) {
        ASSERT_EQ(p.phases[i].exits.size(), 1u);
        EXPECT_EQ(p.phases[i].exits[0].condition.at_ns, from_seconds(plan[i + 1].start_s));
        EXPECT_EQ(p.phases[i].exits[0].to_phase, static_cast<int>(i + 1));
      } else {
        EXPECT_TRUE(p.phases[i].exits.empty());  // the last lasts to the run's end
      }
    }
  }
}

// The guidance's five steps over the eight phases: the line and its hold are its line, the axis
// hold, the transfer and the capture point's hold its transfer.
flight::SyncStep step_of(const std::string& phase) {
  if (phase == "line" || phase == "line_end_hold") return flight::SyncStep::kLine;
  if (phase == "fly_around") return flight::SyncStep::kFlyAround;
  if (phase == "axis_approach") return flight::SyncStep::kAxisApproach;
  if (phase == "rotation_synchronisation") return flight::SyncStep::kRotationSync;
  return flight::SyncStep::kTransfer;
}

TEST(RunPhases, ComradeSyncPhasesSwitchInThePeriodsTheGuidanceSwitchesItsSteps) {
  const model::Scenario s = load("scenarios/comrade_sync.yaml");
  const flight::FlightParams flight_params = flight::make_flight_params(s);
  ASSERT_TRUE(flight_params.approach);
  Simulation sim(s, flight_params, {});
  int mismatches = 0;
  while (!sim.done()) {
    sim.begin_period();
    const std::string& phase = sim.phases().phases[static_cast<std::size_t>(sim.phase())].name;
    mismatches += step_of(phase) != flight::sync_step(*flight_params.approach, sim.t_s());
    sim.step();
  }
  EXPECT_EQ(mismatches, 0);
  const RunResult r = sim.finish();
  const std::vector<PlannedPhase> plan = planned_phases(s);
  ASSERT_EQ(r.phases.size(), plan.size());
  for (std::size_t i = 0; i < plan.size(); ++i) {
    EXPECT_EQ(r.phases[i].name, plan[i].name);
    EXPECT_EQ(r.phases[i].start_s, plan[i].start_s);
    EXPECT_EQ(r.phases[i].end_s, plan[i].start_s + plan[i].duration_s);
    EXPECT_EQ(r.phases[i].end_reason, i + 1 < plan.size() ? "time" : std::string(kRunEndReason));
  }
}

// A run ended early (diverged, or stepped from outside and finished) ends its phase there.
TEST(RunPhases, ARunStoppedEarlyEndsItsLastPhaseThere) {
  const model::Scenario s = load("scenarios/msr_terminal.yaml");
  const flight::FlightParams flight_params = flight::make_flight_params(s);  // outlives the simulation
  Simulation sim(s, flight_params, {});
  for (int k = 0; k < 50; ++k) sim.step();
  const RunResult r = sim.finish();
  ASSERT_EQ(r.phases.size(), 1u);
  EXPECT_EQ(r.phases[0].name, "line");
  EXPECT_EQ(r.phases[0].end_s, 5.0);
  EXPECT_EQ(r.phases[0].end_reason, kRunEndReason);
}

// With an escape: "escape" (synchronised) from the reach or the capture once triggered, its exit
// first so that it wins over the planned one in the same period, then "escape_retreat" (not
// synchronised: Table 4's 3 m) once desynchronised; both with the arm awake.
TEST(RunPhases, AnEscapeLeavesTheReachOrTheCaptureForItsTwoPhases) {
  const io::LoadResult loaded =
      io::load_scenario_file("scenarios/comrade_capture.yaml", {"capture.escape={command_s: 2870}"});
  ASSERT_TRUE(loaded.scenario) << io::format_errors(loaded.errors);
  const PhaseSequenceParams p = run_phases(*loaded.scenario);
  EXPECT_TRUE(validate(p).empty());
  const int escape = phase_index(p, "escape"), retreat = phase_index(p, "escape_retreat");
  ASSERT_GE(escape, 0);
  EXPECT_EQ(retreat, escape + 1);
  ASSERT_EQ(p.flag_names.size(), 4u);
  EXPECT_EQ(p.flag_names[kEscapingFlag], "escaping");
  EXPECT_EQ(p.flag_names[kDesynchronisedFlag], "desynchronised");
  for (const char* from : {"reach", "capture"}) {
    const PhaseSpec& phase = p.phases[static_cast<std::size_t>(phase_index(p, from))];
    ASSERT_FALSE(phase.exits.empty()) << from;
    EXPECT_EQ(phase.exits.front().to_phase, escape) << from;
    EXPECT_EQ(phase.exits.front().condition.index, kEscapingFlag) << from;
  }
  const PhaseSpec& escaping = p.phases[static_cast<std::size_t>(escape)];
  ASSERT_EQ(escaping.exits.size(), 1u);
  EXPECT_EQ(escaping.exits.front().condition.index, kDesynchronisedFlag);
  EXPECT_TRUE(p.phases[static_cast<std::size_t>(retreat)].exits.empty());
  const std::vector<ConditionalPhase> conditional = conditional_phases(*loaded.scenario);
  ASSERT_EQ(conditional.size(), 4u);
  EXPECT_TRUE(conditional[2].requirements.synchronised);
  EXPECT_FALSE(conditional[3].requirements.synchronised);
  EXPECT_TRUE(conditional[3].configuration.arm_awake);
}

}  // namespace
}  // namespace chaser::sim

namespace chaser::sim {
namespace {

// The synchronisation's requirements are a phase's: they apply from the phase that starts at
// synchronised_from_s on, and in no phase before it (so the monitor's judgement, read from the phase
// flown, switches in the same period as a judgement of the time would).
TEST(RunPhases, TheSynchronisationIsJudgedFromThePhaseStartingWhenTheChaserTurnsWithTheTarget) {
  const std::pair<const char*, const char*> cases[] = {
      {"scenarios/msr_terminal.yaml", ""},                  // never: the target does not turn with LVLH
      {"scenarios/comrade_sync.yaml", "transfer"},          // when the rotation is synchronised (no axis hold)
      {"scenarios/comrade_assist.yaml", "line"},            // ASSIST turns with LVLH: from the start
  };
  for (const auto& [path, first] : cases) {
    const model::Scenario s = load(path);
    const double from_s = synchronised_from_s(s);
    bool seen = false;
    for (const PlannedPhase& p : planned_phases(s)) {
      if (p.name == std::string(first)) {
        EXPECT_EQ(p.start_s, from_s) << path;
        seen = true;
      }
      EXPECT_EQ(p.requirements.synchronised, seen) << path << ": " << p.name;
    }
    EXPECT_EQ(seen, *first != '\0') << path;
  }
}

}  // namespace
}  // namespace chaser::sim

namespace chaser::sim {
namespace {

// A capture's plan ends with the reach and the capture, the two phases whose plant configuration
// has the arm awake; the synchronisation's phases before them are comrade_sync's.
TEST(RunPhases, TheCapturesReachAndCaptureAreThePhasesWithTheArmAwake) {
  const model::Scenario capture = load("scenarios/comrade_capture.yaml");
  const std::vector<PlannedPhase> plan = planned_phases(capture);
  ASSERT_GE(plan.size(), 2u);
  const PlannedPhase& reach = plan[plan.size() - 2];
  EXPECT_STREQ(reach.name, "reach");
  EXPECT_EQ(reach.start_s, capture.capture->start_s);
  EXPECT_STREQ(plan.back().name, "capture");
  EXPECT_EQ(plan.back().start_s, capture.capture->approach_start_s());
  for (const PlannedPhase* p : {&reach, &plan.back()}) {
    EXPECT_TRUE(p->configuration.arm_awake) << p->name;
    EXPECT_TRUE(p->requirements.synchronised) << p->name;
  }
  const std::vector<PlannedPhase> sync = planned_phases(load("scenarios/comrade_sync.yaml"));
  ASSERT_EQ(plan.size(), sync.size() + 2);
  for (std::size_t i = 0; i + 2 < plan.size(); ++i) {
    EXPECT_STREQ(plan[i].name, sync[i].name);
    EXPECT_FALSE(plan[i].configuration.arm_awake) << plan[i].name;
  }
}

}  // namespace
}  // namespace chaser::sim
