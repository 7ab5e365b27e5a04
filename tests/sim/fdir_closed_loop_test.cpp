// The FDI schemes in the closed loop of the MSR scenario (recovery off, so each scheme is judged on
// its own): detection of a stuck-open thruster, the fault the paper detects fastest.
#include <gtest/gtest.h>

#include <limits>

#include <tuple>

#include "flight/flight_software.hpp"
#include "io/scenario_loader.hpp"
#include "sim/run.hpp"

namespace chaser::sim {
namespace {

model::Scenario msr_without_recovery() {
  const io::LoadResult loaded = io::load_scenario_file("scenarios/msr_terminal.yaml");
  EXPECT_TRUE(loaded.errors.empty()) << io::format_errors(loaded.errors);
  model::Scenario s = *loaded.scenario;
  s.fdi.recovery = model::RecoveryPolicy::kNone;
  s.duration_s = 1020.0;  // 20 s after the onset is enough to judge detection
  return s;
}

// A campaign run's truth, from its runs.csv row: its seed and dispersed chaser (mass, principal
// inertia, centre of mass), flying `fault` for `duration_s`; a campaign flies it with flight
// software designed for the nominal chaser.
model::Scenario campaign_truth(const model::Scenario& nominal, std::uint64_t seed, double mass_kg,
                               const Vec3& inertia_kgm2, const Vec3& com_body_m, const model::FaultParams& fault,
                               double duration_s) {
  model::Scenario truth = nominal;
  truth.duration_s = duration_s;
  truth.seed = seed;
  truth.chaser.mass_kg = mass_kg;
  truth.chaser.inertia_kgm2.diagonal() = inertia_kgm2;
  truth.chaser.com_body_m = com_body_m;
  truth.faults = {fault};
  return truth;
}

// The deficit detector's gains are evaluated every second period when its window is an even number
// of periods (the shipped 10 s: 100), else every period; both are valid parameters.
TEST(FdirClosedLoop, DetectorCadenceFollowsTheWindowsParity) {
  model::Scenario s = msr_without_recovery();
  for (const auto& [window_s, periods, every] : {std::tuple{10.0, 100, 2}, std::tuple{10.1, 101, 1}}) {
    s.fdi.deficit.detection_window_s = window_s;
    const flight::FdirParams p = flight::make_flight_params(s).fdir;
    EXPECT_EQ(p.detector.window, periods);
    EXPECT_EQ(p.detector.evaluate_every, every);
    EXPECT_TRUE(flight::fdi::validate(p.detector).empty()) << window_s;
  }
}

// Every thruster stuck open at 1000 s is detected by both schemes within a few seconds (measured
// 2.1-2.9 s position, 0.2-0.7 s attitude; bounds 4 s and 1.5 s). The position bound also checks
// that the position scheme is designed for the attitude flown: designed for body axes along LVLH,
// four thrusters took 5.8-12.2 s.
TEST(FdirClosedLoop, StuckOpenIsDetectedByBothSchemesWithinSeconds) {
  model::Scenario scenario = msr_without_recovery();
  for (int thruster = 0; thruster < 8; ++thruster) {
    scenario.faults = {model::FaultParams{.kind = model::FaultKind::kStuckOpen, .thruster = thruster}};
    const RunResult r = run_scenario(scenario);
    EXPECT_GE(scheme_result(r.fdir, "position").alarm_s, 1000.0) << "T" << thruster + 1;
    EXPECT_LT(scheme_result(r.fdir, "position").alarm_s, 1004.0) << "T" << thruster + 1;
    EXPECT_GE(scheme_result(r.fdir, "attitude").alarm_s, 1000.0) << "T" << thruster + 1;
    EXPECT_LT(scheme_result(r.fdir, "attitude").alarm_s, 1001.5) << "T" << thruster + 1;
  }
}

// A LIDAR gap erases no conclusion: T1 stuck open with no recovery tumbles the chaser until the
// LIDAR loses the target (measured: 190 s out of view, from about 40 s after the onset), and every
// scheme's alarm, isolation and the bank's diagnosis, all made within 3 s, stand at the run's end.
TEST(FdirClosedLoop, ALidarGapErasesNoConclusion) {
  model::Scenario scenario = msr_without_recovery();
  scenario.faults = {model::FaultParams{.kind = model::FaultKind::kStuckOpen, .thruster = 0}};
  const RunResult r = run_scenario(scenario);
  EXPECT_GT(r.figures.out_of_view_periods, 100);
  for (const char* name : {"position", "attitude", "deficit"}) {
    const SchemeResult& scheme = scheme_result(r.fdir, name);
    EXPECT_GE(scheme.alarm_s, 1000.0) << name;
    EXPECT_LT(scheme.isolated_s, 1003.0) << name;
    EXPECT_EQ(scheme.isolated_thruster, 0) << name;
  }
  EXPECT_EQ(scheme_result(r.fdir, "deficit").diagnosed_kind, model::FaultKind::kStuckOpen);
}

// Issue 3's acceptance, in the loop with nominal parameters: every thruster of branch A and each of
// the four fault cases of Fonod 2015 (sizes in the middle of the paper's ranges), fault at 1000 s:
// some scheme detects the fault and every scheme that confirms a thruster names the right one, and
// the deficit bank reads the fault kind. Measured (docs/fdi.md): all 32 detected and isolated, 66
// isolations right, 66/66 kinds right (65/66 in an earlier version: a blocked T6 read as a 0.94
// loss; the bound below keeps that margin). The run ends 180 s after the onset: a blocked or
// weakened T4 is not commanded before 1168 s and cannot be seen earlier by any method (docs/fdi.md,
// "Deficit detector").
TEST(FdirClosedLoop, EveryThrusterAndFaultCaseIsDetectedAndIsolatedRight) {
  model::Scenario scenario = msr_without_recovery();
  scenario.duration_s = 1180.0;
  const model::FaultKind kinds[] = {model::FaultKind::kStuckOpen, model::FaultKind::kStuckClosed,
                                    model::FaultKind::kLeak, model::FaultKind::kLoss};
  int kinds_right = 0, diagnoses = 0;
  for (const model::FaultKind kind : kinds) {
    for (int thruster = 0; thruster < 8; ++thruster) {
      scenario.faults = {model::FaultParams{
          .kind = kind, .thruster = thruster, .onset_s = 1000.0, .leak_size = 0.2, .loss_size = 0.65}};
      const RunResult r = run_scenario(scenario);
      const std::string name = std::string(model::to_string(kind)) + " T" + std::to_string(thruster + 1);
      EXPECT_GE(r.fdir.detection_s, 1000.0) << name;
      EXPECT_EQ(r.fdir.isolated_thruster, thruster) << name;
      for (const SchemeResult* scheme : {&r.fdir.schemes[0], &r.fdir.schemes[1], &r.fdir.schemes[2]}) {
        if (scheme->isolated_thruster == model::kNoThruster) continue;
        EXPECT_EQ(scheme->isolated_thruster, thruster) << name;
        ASSERT_TRUE(scheme->diagnosed_kind.has_value()) << name;
        ++diagnoses;
        kinds_right += *scheme->diagnosed_kind == kind;
      }
    }
  }
  EXPECT_GE(diagnoses, 64);
  EXPECT_GE(kinds_right, diagnoses - 2);
}

// A leak ramps up (slope 0.1 /s), which the bank's step model fits badly; with a dispersed centre of
// mass the torque rows misfit further. Without rescaling their weights by the misfit, those rows
// told the partners T6 and T2 (same torque, opposite force) apart by chance and named T2: this is
// run 113 of a leak campaign (campaign seed 1), dispersed truth flown by flight software designed
// for the nominal chaser, as a campaign flies it. With the rescaling the position rows decide: T6.
// (Over 300 dispersed leak runs: 8 partner confusions before, none after; docs/fdi.md.)
TEST(FdirClosedLoop, DispersedLeakIsNotConfusedWithItsPartner) {
  const model::Scenario nominal = msr_without_recovery();
  const model::Scenario truth = campaign_truth(
      nominal, 909671271867787876ULL, 2540.5443396736609,
      Vec3(1919.8415318487027, 2571.8417331612186, 3176.1935241906131),
      Vec3(0.0040326617792807206, 0.00094635353984032819, -0.020779295416637047),
      model::FaultParams{.kind = model::FaultKind::kLeak, .thruster = 5, .onset_s = 1000.0,
                         .leak_size = 0.19181456441143682, .leak_slope_per_s = 0.1},
      1010.0);
  const RunResult r = run_scenario(truth, flight::make_flight_params(nominal));
  EXPECT_EQ(scheme_result(r.fdir, "deficit").isolated_thruster, 5);  // T6
  EXPECT_EQ(scheme_result(r.fdir, "attitude").isolated_thruster, 5);
  ASSERT_TRUE(scheme_result(r.fdir, "deficit").diagnosed_kind.has_value());
  EXPECT_EQ(*scheme_result(r.fdir, "deficit").diagnosed_kind, model::FaultKind::kLeak);
}

// Issue 20's active checks in the loop. T4 is not commanded between about 56 s and 1168 s of the
// approach (docs/fdi.md), so a stuck-closed T4 at 1000 s stays unseen by every scheme without
// checks; with them (bound 25 s, 7.5 ms pulses) its next check leaves a deficit and the FDI detects
// and names it within 30 s of the onset.
TEST(FdirClosedLoop, ActiveChecksFindAStuckClosedDormantThrusterWithin30s) {
  model::Scenario scenario = msr_without_recovery();
  scenario.duration_s = 1060.0;
  scenario.faults = {model::FaultParams{.kind = model::FaultKind::kStuckClosed, .thruster = 3, .onset_s = 1000.0}};
  scenario.fdi.active_check = {
      .enabled = false, .max_unverified_s = 25.0, .informative_on_time_s = 0.005, .pulse_s = 0.0075, .keep_quiet_range_m = 2.0};
  const RunResult passive = run_scenario(scenario);
  EXPECT_EQ(passive.active_checks, 0);
  EXPECT_EQ(passive.fdir.detection_s, -1.0);
  EXPECT_EQ(passive.fdir.isolated_thruster, model::kNoThruster);

  scenario.fdi.active_check.enabled = true;
  const RunResult active = run_scenario(scenario);
  EXPECT_GT(active.active_checks, 0);
  EXPECT_GE(active.fdir.detection_s, 1000.0);
  EXPECT_LE(active.fdir.detection_s, 1030.0);
  EXPECT_EQ(active.fdir.isolated_thruster, 3);
}

// Armed only for the last approach (arm_range_m 3: MSR reaches 3 m at about 1,005 s and the 2 m
// keep-quiet range at 1,063 s), the checks find the same fault (the window opens after its onset)
// and, over the fault-free approach, fire only inside the window: far fewer than all along.
TEST(FdirClosedLoop, ArmedChecksWaitForTheLastApproach) {
  model::Scenario scenario = msr_without_recovery();
  scenario.duration_s = 1060.0;
  scenario.faults = {model::FaultParams{.kind = model::FaultKind::kStuckClosed, .thruster = 3, .onset_s = 1000.0}};
  scenario.fdi.active_check = {.enabled = true, .max_unverified_s = 25.0, .informative_on_time_s = 0.005,
                               .pulse_s = 0.0075, .keep_quiet_range_m = 2.0, .arm_range_m = 3.0};
  const RunResult armed = run_scenario(scenario);
  EXPECT_GT(armed.active_checks, 0);
  EXPECT_GE(armed.fdir.detection_s, 1000.0);
  EXPECT_LE(armed.fdir.detection_s, 1030.0);
  EXPECT_EQ(armed.fdir.isolated_thruster, 3);

  scenario.faults.clear();
  scenario.duration_s = 1200.0;
  const RunResult quiet = run_scenario(scenario);
  scenario.fdi.active_check.arm_range_m = std::numeric_limits<double>::infinity();
  const RunResult all_along = run_scenario(scenario);
  EXPECT_EQ(quiet.fdir.detection_s, -1.0);
  EXPECT_TRUE(quiet.figures.capture_achieved);
  // 58 s of window: each of the 8 at most 3 times (0, 25, 50 s after it opens).
  EXPECT_GT(quiet.active_checks, 0);
  EXPECT_LE(quiet.active_checks, 3 * 8);
  EXPECT_GT(all_along.active_checks, 3 * quiet.active_checks);
}

// One 7.5 ms check of a 46 % weaker T4 leaves the deficit detector just short of its threshold (gain
// 95 against 100): run 5341 of the Table 2 preset (campaign seed 1, dispersed truth flown by the
// nominal flight software), checks armed at 3 m. Without rechecks the second look waited the 25 s
// bound (detected 30.8 s after the onset); with them the suspect is checked again at once.
TEST(FdirClosedLoop, AnInconclusiveCheckIsRepeatedAtOnce) {
  const model::Scenario nominal = msr_without_recovery();
  const model::Scenario truth = campaign_truth(
      nominal, 6880154054337862346ULL, 2435.3981246670201,
      Vec3(2122.6950054398922, 2445.9381260284263, 2662.004407342969),
      Vec3(-0.0075013290838678364, -0.02752715779982538, 0.0079851558499976303),
      model::FaultParams{.kind = model::FaultKind::kLoss, .thruster = 3, .onset_s = 1000.0,
                         .loss_size = 0.45861967708549783},
      1040.0);
  model::Scenario flown = nominal;
  flown.fdi.active_check = {.enabled = true, .max_unverified_s = 25.0, .informative_on_time_s = 0.005,
                            .pulse_s = 0.0075, .keep_quiet_range_m = 2.0, .arm_range_m = 3.0, .recheck_fraction = 1.0};
  const RunResult once = run_scenario(truth, flight::make_flight_params(flown));
  flown.fdi.active_check.recheck_fraction = 0.5;
  const RunResult rechecked = run_scenario(truth, flight::make_flight_params(flown));
  EXPECT_GT(once.fdir.detection_s, 1025.0);  // the second check, 25 s after the first (1005.5 s)
  EXPECT_EQ(once.fdir.isolated_thruster, 3);
  EXPECT_GE(rechecked.fdir.detection_s, 1005.0);
  EXPECT_LE(rechecked.fdir.detection_s, 1010.0);
  EXPECT_EQ(rechecked.fdir.isolated_thruster, 3);
}

// The checks themselves raise no alarm over the whole fault-free approach, and the chaser still
// captures the target.
TEST(FdirClosedLoop, ActiveChecksRaiseNoFalseAlarm) {
  model::Scenario scenario = msr_without_recovery();
  scenario.duration_s = 1200.0;
  scenario.fdi.active_check = {
      .enabled = true, .max_unverified_s = 25.0, .informative_on_time_s = 0.005, .pulse_s = 0.0075, .keep_quiet_range_m = 2.0};
  const RunResult r = run_scenario(scenario);
  EXPECT_EQ(r.fdir.detection_s, -1.0);
  EXPECT_TRUE(r.figures.capture_achieved);
  // A check resets its thruster's clock: at most one per active thruster (8) per 25 s.
  EXPECT_GT(r.active_checks, 0);
  EXPECT_LE(r.active_checks, 1200 / 25 * 8);
}

}  // namespace
}  // namespace chaser::sim
