#include "sim/phase_sequence.hpp"

#include <gtest/gtest.h>

#include <functional>

namespace chaser::sim {
namespace {

constexpr TimeNs kPeriodNs = 100'000'000;  // the control period, 0.1 s
constexpr TimeNs s(std::int64_t seconds) { return seconds * kNsPerSecond; }
constexpr TimeNs ms(std::int64_t milliseconds) { return milliseconds * 1'000'000; }

// Steps every period from 0 to t_end (exclusive), then finishes the run at t_end; returns the changes.
using Bits = std::function<std::uint64_t(TimeNs)>;
std::vector<PhaseChange> fly(const PhaseSequenceParams& params, PhaseSequenceState& state, TimeNs t_end,
                             const Bits& flags = {}, const Bits& events = {}) {
  std::vector<PhaseChange> changes;
  for (TimeNs t = 0; t < t_end; t += kPeriodNs)
    if (auto change = step_phases(params, state, t, flags ? flags(t) : 0, events ? events(t) : 0))
      changes.push_back(*change);
  finish_phases(params, state, t_end);
  return changes;
}

// The synchronised approach as time steps: line, fly-around, axis approach, rotation sync, transfer, hold.
PhaseSequenceParams sync_approach() {
  PhaseSequenceParams params;
  const std::vector<std::string> names = {"line", "fly_around", "axis_approach", "rotation_sync", "transfer", "hold"};
  const std::vector<TimeNs> starts = {s(100), s(400), s(700), s(900), s(1000)};
  for (std::size_t p = 0; p < names.size(); ++p) {
    params.phases.push_back({.name = names[p]});
    if (p < starts.size()) params.phases[p].exits.push_back({at_time(starts[p]), static_cast<int>(p + 1), "time"});
  }
  return params;
}

TEST(PhaseSequence, TimeTransitionsReproduceTheSyncApproachSteps) {
  const PhaseSequenceParams params = sync_approach();
  ASSERT_TRUE(validate(params).empty());
  PhaseSequenceState state = init_phases(params, 0);
  const std::vector<PhaseChange> changes = fly(params, state, s(3000));

  const std::vector<TimeNs> starts = {0, s(100), s(400), s(700), s(900), s(1000)};
  ASSERT_EQ(changes.size(), 5U);
  ASSERT_EQ(state.log_size, 6);
  for (int p = 0; p < 6; ++p) {
    EXPECT_EQ(state.log[p].phase, p);
    EXPECT_EQ(state.log[p].start_ns, starts[p]) << params.phases[p].name;  // exactly, in integer ns
    EXPECT_EQ(state.log[p].end_ns, p < 5 ? starts[p + 1] : s(3000));
  }
  const std::vector<FlownPhase> flown = flown_phases(params, state);
  ASSERT_EQ(flown.size(), 6U);
  for (int p = 0; p < 5; ++p) EXPECT_EQ(flown[p].end_reason, "time");
  EXPECT_EQ(flown[5].name, "hold");
  EXPECT_EQ(flown[5].start_s, 1000.0);  // exactly: summary.json shows 1000
  EXPECT_EQ(flown[5].end_s, 3000.0);
  EXPECT_EQ(flown[5].end_reason, kRunEndReason);
  EXPECT_EQ(phase_index(params, "rotation_sync"), 3);
  EXPECT_EQ(phase_index(params, "capture"), -1);
}

// reach -> capture once the capture point has been held for the dwell.
PhaseSequenceParams reach_capture(TimeNs dwell_ns) {
  return {.phases = {{"reach", {{held_for(0, dwell_ns), 1, "capture point held 5 s"}}}, {"capture", {}}},
          .flag_names = {"at_capture_point"}};
}

TEST(PhaseSequence, HeldForRestartsItsDwellWhenTheFlagDrops) {
  const PhaseSequenceParams params = reach_capture(s(5));
  PhaseSequenceState state = init_phases(params, 0);
  // True from 10 s, false in [12 s, 12.5 s), true again from 12.5 s.
  const auto at_point = [](TimeNs t) -> std::uint64_t { return (t >= s(10) && t < s(12)) || t >= ms(12'500); };
  const std::vector<PhaseChange> changes = fly(params, state, s(30), at_point);
  ASSERT_EQ(changes.size(), 1U);
  EXPECT_EQ(changes[0].t_ns, ms(17'500));  // 5 s after 12.5 s, not 5 s after 10 s
  EXPECT_EQ(flown_phases(params, state)[0].end_reason, "capture point held 5 s");
}

TEST(PhaseSequence, HeldForCountsOnlyTheTimeInThePhase) {
  PhaseSequenceParams params = reach_capture(s(5));
  params.phases.insert(params.phases.begin(), {"synchronisation", {{at_time(s(10)), 1, "time"}}});
  params.phases[1].exits[0].to_phase = 2;
  ASSERT_TRUE(validate(params).empty());
  PhaseSequenceState state = init_phases(params, 0);
  const std::vector<PhaseChange> changes = fly(params, state, s(30), [](TimeNs) -> std::uint64_t { return 1; });
  ASSERT_EQ(changes.size(), 2U);
  EXPECT_EQ(changes[1].t_ns, s(15));  // the flag was true from 0 s, but reach began at 10 s
}

TEST(PhaseSequence, EventFiresInItsStepAndTheFirstListedExitWins) {
  // capture: an abort is listed first, so it wins over a grasp closing in the same step.
  const PhaseSequenceParams params = {
      .phases = {{"capture", {{on_event(0), 2, "abort"}, {on_event(1), 1, "grasp closed"}}},
                 {"rigidisation", {}},
                 {"escape", {}}},
      .event_names = {"abort", "grasp_closed"}};
  ASSERT_TRUE(validate(params).empty());

  PhaseSequenceState grasp = init_phases(params, 0);
  auto changes = fly(params, grasp, s(10), {}, [](TimeNs t) -> std::uint64_t { return t == s(5) ? 0b10 : 0; });
  ASSERT_EQ(changes.size(), 1U);
  EXPECT_EQ(changes[0].t_ns, s(5));
  EXPECT_EQ(changes[0].to_phase, 1);

  PhaseSequenceState both = init_phases(params, 0);
  changes = fly(params, both, s(10), {}, [](TimeNs t) -> std::uint64_t { return t == s(5) ? 0b11 : 0; });
  ASSERT_EQ(changes.size(), 1U);
  EXPECT_EQ(changes[0].to_phase, 2);
  EXPECT_EQ(flown_phases(params, both)[0].end_reason, "abort");
}

TEST(PhaseSequence, AfterIsMeasuredFromThePhasesOwnStart) {
  const PhaseSequenceParams params = {
      .phases = {{"stabilisation", {{on_event(0), 1, "stable"}}},
                 {"escape", {{after(s(10)), 2, "time"}}},
                 {"free", {}}},
      .event_names = {"stable"}};
  PhaseSequenceState state = init_phases(params, 0);
  const auto changes = fly(params, state, s(30), {}, [](TimeNs t) -> std::uint64_t { return t == ms(3'300); });
  ASSERT_EQ(changes.size(), 2U);
  EXPECT_EQ(changes[0].t_ns, ms(3'300));
  EXPECT_EQ(changes[1].t_ns, ms(13'300));  // 10 s after escape began, not at 10 s run time
}

TEST(PhaseSequence, OneTransitionPerStepSoEveryPhaseIsFlownForAPeriod) {
  // Every exit holds at once; the chain still advances one phase per period.
  const PhaseSequenceParams params = {
      .phases = {{"a", {{after(0), 1, "now"}}},
                 {"b", {{at_time(0), 2, "now"}}},
                 {"c", {{held_for(0, 0), 3, "now"}}},
                 {"d", {}}},
      .flag_names = {"ready"}};
  PhaseSequenceState state = init_phases(params, 0);
  const auto changes = fly(params, state, s(1), [](TimeNs) -> std::uint64_t { return 1; });
  ASSERT_EQ(changes.size(), 3U);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(changes[i].t_ns, i * kPeriodNs);
  EXPECT_EQ(state.phase, 3);
}

bool has_problem(const std::vector<std::string>& problems, const std::string& text) {
  for (const std::string& p : problems)
    if (p.find(text) != std::string::npos) return true;
  return false;
}

TEST(PhaseSequence, ValidateNamesThePhaseAndFieldOfEveryProblem) {
  const PhaseSequenceParams params = {
      .phases = {{"reach", {{after(-1), 7, "time"}, {held_for(3, -s(1)), 1, ""}}},
                 {"reach", {{on_event(2), 0, "grasp closed"}, {at_time(-5), 0, "time"}}},
                 {"a b", {}},
                 {"..", {}}},
      .initial = 4,
      .flag_names = {"at_point", "at_point"},
      .event_names = {"grasp/closed"}};
  const std::vector<std::string> problems = validate(params);
  for (const char* expected : {"initial: unknown phase 4",
                               "phases[0] (reach).exits[0].to_phase: unknown phase 7",
                               "phases[0] (reach).exits[0].condition.duration_ns: must be >= 0",
                               "phases[0] (reach).exits[1].condition.dwell_ns: must be >= 0",
                               "phases[0] (reach).exits[1].condition.index: flag 3",
                               "phases[0] (reach).exits[1].reason: must not be empty",
                               "phases[1] (reach).name: repeats phases[0]",
                               "phases[1] (reach).exits[0].condition.index: event 2",
                               "phases[1] (reach).exits[1].condition.at_ns: must be >= 0",
                               "phases[2] (a b).name: 'a b' is not a plain name",
                               "phases[3] (..).name: '..' is not a plain name",
                               "flag_names[1]: 'at_point' repeats flag_names[0]",
                               "event_names[0]: 'grasp/closed' is not a plain name"})
    EXPECT_TRUE(has_problem(problems, expected)) << expected;
  EXPECT_EQ(problems.size(), 13U);
  EXPECT_TRUE(validate(sync_approach()).empty());
  EXPECT_TRUE(has_problem(validate(PhaseSequenceParams{}), "phases: must list at least one phase"));
}

TEST(PhaseSequence, SteppingTwiceFromOneStateGivesTheSameLog) {
  const PhaseSequenceParams params = {
      .phases = {{"synchronisation", {{held_for(0, s(2)), 1, "synchronised 2 s"}}},
                 {"reach", {{on_event(0), 5, "abort"}, {held_for(1, s(1)), 2, "capture point held 1 s"}}},
                 {"capture", {{on_event(1), 3, "grasp closed"}, {after(s(20)), 5, "capture timed out"}}},
                 {"rigidisation", {{after(s(5)), 4, "time"}}},
                 {"stabilisation", {}},
                 {"escape", {}}},
      .flag_names = {"synchronised", "at_capture_point"},
      .event_names = {"abort", "grasp_closed"}};
  ASSERT_TRUE(validate(params).empty());
  const auto flags = [](TimeNs t) -> std::uint64_t { return (t >= s(3) ? 1 : 0) | ((t / ms(700)) % 3 != 0 ? 2 : 0); };
  const auto events = [](TimeNs t) -> std::uint64_t { return t == ms(17'300) ? 0b10 : 0; };
  PhaseSequenceState start = init_phases(params, 0);
  step_phases(params, start, 0, 0, 0);
  PhaseSequenceState first = start, second = start;
  fly(params, first, s(60), flags, events);
  fly(params, second, s(60), flags, events);
  EXPECT_EQ(first.log, second.log);
  EXPECT_EQ(first.log_size, 5);
  EXPECT_EQ(flown_phases(params, first), flown_phases(params, second));
  EXPECT_EQ(flown_phases(params, first).back().name, "stabilisation");
}

TEST(PhaseSequence, LogKeepsTheFirstPhasesFlownAndCountsTheRest) {
  const PhaseSequenceParams params = {
      .phases = {{"hold", {{after(s(1)), 1, "time"}}}, {"retry", {{after(s(1)), 0, "time"}}}}};
  PhaseSequenceState state = init_phases(params, 0);
  fly(params, state, s(100));
  EXPECT_EQ(state.log_size, kMaxPhaseLog);
  EXPECT_EQ(state.log[kMaxPhaseLog - 1].end_ns, s(kMaxPhaseLog));  // closed at its exit, not at the run end
  EXPECT_EQ(state.unlogged_phases, 100 - kMaxPhaseLog);
  EXPECT_EQ(state.phase, 1);  // 99 transitions (at 1..99 s), an odd number
}

}  // namespace
}  // namespace chaser::sim
