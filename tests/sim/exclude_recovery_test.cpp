// fdi.recovery: exclude in the closed loop: a single-set layout (twelve thrusters, two per face of
// the bus, no standby group to switch to) flies MSR's approach; a thruster fault is diagnosed by the
// deficit scheme, and the flight software flies on without the thruster, cancelling the thrust a
// stuck-open one keeps giving (model/recovery.hpp, flight/thruster_management.hpp).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/scenario_loader.hpp"
#include "sim/run.hpp"

namespace chaser::sim {
namespace {

// Two 22 N thrusters on each face of MSR's bus, pushing inwards, offset so that each pair turns the
// bus both ways about one axis: every set without one thruster still pushes and turns everywhere.
const char* const kTwelveOnSixFaces =
    "thrusters.list=["
    "{name: T1, position_body_m: [1.0, 0.5, 0.0], direction_body: [-1, 0, 0], max_thrust_N: 22.0},"
    "{name: T2, position_body_m: [1.0, -0.5, 0.0], direction_body: [-1, 0, 0], max_thrust_N: 22.0},"
    "{name: T3, position_body_m: [-1.0, 0.0, 0.5], direction_body: [1, 0, 0], max_thrust_N: 22.0},"
    "{name: T4, position_body_m: [-1.0, 0.0, -0.5], direction_body: [1, 0, 0], max_thrust_N: 22.0},"
    "{name: T5, position_body_m: [0.0, 0.8, 0.5], direction_body: [0, -1, 0], max_thrust_N: 22.0},"
    "{name: T6, position_body_m: [0.0, 0.8, -0.5], direction_body: [0, -1, 0], max_thrust_N: 22.0},"
    "{name: T7, position_body_m: [0.5, -0.8, 0.0], direction_body: [0, 1, 0], max_thrust_N: 22.0},"
    "{name: T8, position_body_m: [-0.5, -0.8, 0.0], direction_body: [0, 1, 0], max_thrust_N: 22.0},"
    "{name: T9, position_body_m: [0.5, 0.0, 0.8], direction_body: [0, 0, -1], max_thrust_N: 22.0},"
    "{name: T10, position_body_m: [-0.5, 0.0, 0.8], direction_body: [0, 0, -1], max_thrust_N: 22.0},"
    "{name: T11, position_body_m: [0.0, 0.5, -0.8], direction_body: [0, 0, 1], max_thrust_N: 22.0},"
    "{name: T12, position_body_m: [0.0, -0.5, -0.8], direction_body: [0, 0, 1], max_thrust_N: 22.0}]";

model::Scenario twelve_thrusters(const std::string& recovery, const std::string& fault) {
  const std::vector<std::string> overrides{kTwelveOnSixFaces,
                                           "thrusters.standby_groups=[]",
                                           "thrusters.tolerates_single_loss=true",
                                           "fdi.position.enabled=false",
                                           "fdi.attitude.enabled=false",
                                           "fdi.deficit.detection=true",
                                           "fdi.recovery=" + recovery,
                                           "faults=[" + fault + "]"};
  const io::LoadResult loaded = io::load_scenario_file("scenarios/msr_terminal.yaml", overrides);
  EXPECT_TRUE(loaded.errors.empty()) << io::format_errors(loaded.errors);
  return *loaded.scenario;
}

const SchemeResult& deficit_scheme(const RunResult& r) { return scheme_result(r.fdir, "deficit"); }

// T3 stuck open at 800 s. Diagnosed within seconds as stuck open on T3 either way; without a
// recovery its 22 N hard-over loses the approach; excluded, the others cancel its force and torque
// (the price is propellant) and the chaser is captured inside the corridor. The FDI watches on, T3's
// lane read at its known on-time: no alarm follows.
TEST(ExcludeRecovery, AStuckOpenThrusterIsExcludedAndItsThrustCancelled) {
  const std::string fault = "{thruster: T3, kind: stuck_open, onset_s: 800}";
  const RunResult lost = run_scenario(twelve_thrusters("none", fault));
  const RunResult kept = run_scenario(twelve_thrusters("exclude", fault));
  for (const RunResult* r : {&lost, &kept}) {
    EXPECT_EQ(deficit_scheme(*r).isolated_thruster, 2);
    ASSERT_TRUE(deficit_scheme(*r).diagnosed_kind.has_value());
    EXPECT_EQ(*deficit_scheme(*r).diagnosed_kind, model::FaultKind::kStuckOpen);
    EXPECT_GE(r->fdir.isolation_s, 800.0);
    EXPECT_LT(r->fdir.isolation_s, 805.0);
  }
  EXPECT_FALSE(lost.figures.capture_achieved);
  EXPECT_LT(lost.fdir.recovery_s, 0.0);
  EXPECT_EQ(kept.fdir.recovered_thruster, 2);
  EXPECT_GE(kept.fdir.recovery_s, kept.fdir.isolation_s);
  EXPECT_TRUE(kept.figures.capture_achieved) << "final position error " << kept.figures.final_position_error_m
                                             << " m, attitude " << kept.figures.final_attitude_error_rad << " rad";
  EXPECT_EQ(kept.figures.corridor_violation_periods, 0) << kept.figures.max_corridor_angle_rad;
  EXPECT_FALSE(kept.figures.diverged);
  ASSERT_EQ(kept.fdir.episodes.size(), 2u);  // the watch after the recovery, with no alarm
  EXPECT_LT(kept.fdir.episodes[1].detection_s, 0.0);
}

// The FDI watches on after excluding a stuck-open T3: a second fault, T8 stuck closed at 900 s, is
// diagnosed right within seconds (and reported: exclusion acts once per run).
TEST(ExcludeRecovery, AfterExcludingAStuckOpenThrusterASecondFaultIsDiagnosed) {
  const RunResult r = run_scenario(twelve_thrusters(
      "exclude", "{thruster: T3, kind: stuck_open, onset_s: 800}, {thruster: T8, kind: stuck_closed, onset_s: 900}"));
  EXPECT_EQ(r.fdir.recovered_thruster, 2);
  ASSERT_EQ(r.fdir.episodes.size(), 2u);
  EXPECT_EQ(r.fdir.episodes[1].isolated_thruster, 7);
  EXPECT_GE(r.fdir.episodes[1].detection_s, 900.0);
  EXPECT_LT(r.fdir.episodes[1].isolation_s, 910.0);
  EXPECT_LT(r.fdir.episodes[1].recovery_s, 0.0);
}

// T1 stuck closed at 800 s: the approach first commands T1 at about 1,004 s, so that is when the
// deficit scheme sees it (isolated at about 1,006 s, read stuck closed); excluded with nothing to
// cancel, the FDI watches the eleven others, and the chaser is still captured.
TEST(ExcludeRecovery, AStuckClosedThrusterIsExcludedAndTheOthersWatched) {
  const RunResult r = run_scenario(twelve_thrusters("exclude", "{thruster: T1, kind: stuck_closed, onset_s: 800}"));
  ASSERT_GE(r.fdir.recovered_thruster, 0) << "T1 was not diagnosed";
  EXPECT_EQ(r.fdir.recovered_thruster, 0);
  EXPECT_TRUE(r.figures.capture_achieved);
  EXPECT_EQ(r.figures.corridor_violation_periods, 0);
  EXPECT_GE(r.fdir.episodes.size(), 2u);  // a second watch, on T2..T12
}

}  // namespace
}  // namespace chaser::sim
