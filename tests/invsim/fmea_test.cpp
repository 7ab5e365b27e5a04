#include "invsim/fmea.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "core/constants.hpp"
#include "io/invsim_loader.hpp"
#include "invsim/noise_draws.hpp"
#include "model/invsim_study.hpp"

namespace chaser::invsim {
namespace fmea_test {

model::InvSimParams scenario() {
  const io::InvSimLoadResult loaded = io::load_invsim_file("scenarios/manual_rvd.yaml");
  EXPECT_TRUE(loaded.errors.empty()) << io::format_errors(loaded.errors);
  return *loaded.params;
}

model::InvSimSensorParams limits() {
  model::InvSimSensorParams s;
  s.azimuth_limit_rad = 10.0 * kDegToRad;
  s.elevation_limit_rad = 10.0 * kDegToRad;
  s.attitude_limit_rad = 1.0 * kDegToRad;
  return s;
}

// A controllable result with the given peaks [deg].
InvSimResult result(double az_deg, double el_deg, double yaw_deg) {
  InvSimResult r;
  r.docked = true;
  r.peak_azimuth_rad = az_deg * kDegToRad;
  r.peak_elevation_rad = el_deg * kDegToRad;
  r.peak_attitude_rad = Vec3(0.0, 0.0, yaw_deg * kDegToRad);
  return r;
}

// The case list is the nominal run, Table 2's 24 modes, Table 5's 16 modes and the scenario's own
// fault set (only when it is not empty), in that order.
TEST(Fmea, CasesAreNominalTable2Table5ThenScenario) {
  const model::InvSimParams p = scenario();
  const std::vector<FmeaCase> cases = fmea_cases(p, {});
  ASSERT_EQ(cases.size(), 41u);
  EXPECT_EQ(cases[0].mode.label, "nominal");
  EXPECT_EQ(cases[0].mode.faults.failed_mask, 0u);
  EXPECT_EQ(cases[1].table, FmeaTable::kSingleAxis);
  EXPECT_EQ(cases[1].mode.label, "d1");
  EXPECT_EQ(cases[25].table, FmeaTable::kMultiAxis);
  EXPECT_EQ(cases[25].mode.label, "d1/d1~+e1/e1~");
  const std::vector<FmeaCase> with_user = fmea_cases(p, model::InvSimFaultSet{0b11});
  ASSERT_EQ(with_user.size(), 42u);
  EXPECT_EQ(with_user.back().table, FmeaTable::kScenario);
  EXPECT_EQ(failed_names(p, with_user.back().mode.faults), "engine a");
}

// The deviation ratio is the larger line-of-sight peak over its limit (azimuth 4 of 10 deg: 0.4;
// elevation 6 of 10: 0.6); the attitude, held at the phase-plane opening line, is not in it.
// Ratios of degrees converted the same way: exact up to rounding (1e-12).
TEST(Fmea, DeviationRatioIsTheLargerLineOfSightPeakOverItsLimit) {
  EXPECT_NEAR(deviation_ratio(limits(), result(4.0, 2.0, 0.7)), 0.4, 1e-12);
  EXPECT_NEAR(deviation_ratio(limits(), result(4.0, 6.0, 0.1)), 0.6, 1e-12);
  InvSimResult diverged = result(0.0, 0.0, 0.0);
  diverged.peak_azimuth_rad = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(std::isinf(deviation_ratio(limits(), diverged)));
}

// Class boundaries: half the az/el limit separates small from large, and so does the attitude
// limit (the paper's Class II: "a large deviation of the yaw and the azimuth"); losing the docking
// or the target (or diverging) is uncontrollable whatever the peaks.
TEST(Fmea, RiskClassBoundaries) {
  EXPECT_EQ(classify_risk(limits(), result(4.9, 4.9, 0.9)), RiskClass::kSmallDeviation);
  EXPECT_EQ(classify_risk(limits(), result(5.1, 0.0, 0.0)), RiskClass::kLargeDeviation);
  EXPECT_EQ(classify_risk(limits(), result(0.0, 5.1, 0.0)), RiskClass::kLargeDeviation);
  InvSimResult r = result(1.0, 1.0, 0.1);
  r.docked = false;
  EXPECT_EQ(classify_risk(limits(), r), RiskClass::kUncontrollable);
  r = result(1.0, 1.0, 0.1);
  r.target_always_in_view = false;
  EXPECT_EQ(classify_risk(limits(), r), RiskClass::kUncontrollable);
  r = result(1.0, 1.0, 1.5);
  r.attitude_within_limits = false;
  EXPECT_TRUE(is_controllable(r));
  EXPECT_EQ(classify_risk(limits(), r), RiskClass::kLargeDeviation);
  r = result(1.0, 1.0, 0.1);
  r.diverged = true;
  EXPECT_FALSE(is_controllable(r));
}

// Ranking: class first (III before II before I), then the workload k_p, then the deviation.
TEST(Fmea, RankingOrdersByClassThenWorkloadThenDeviation) {
  std::vector<FmeaRow> rows(4);
  rows[0].risk = RiskClass::kSmallDeviation;
  rows[0].result.k_p = 0.9;
  rows[1].risk = RiskClass::kUncontrollable;
  rows[1].result.k_p = 0.1;
  rows[2].risk = RiskClass::kSmallDeviation;
  rows[2].result.k_p = 0.9;
  rows[2].deviation_ratio = 0.3;
  rows[3].risk = RiskClass::kLargeDeviation;
  rank_by_risk(rows);
  EXPECT_EQ(rows[1].rank, 1);
  EXPECT_EQ(rows[3].rank, 2);
  EXPECT_EQ(rows[2].rank, 3);
  EXPECT_EQ(rows[0].rank, 4);
}

// The draw a row's history shows: the most severe class, then the largest deviation ratio, then the
// largest attitude peak; the first of equals; a diverged draw's non-finite peaks are the worst.
TEST(Fmea, WorstDrawIsTheMostSevereClassThenDeviationThenAttitude) {
  const model::InvSimSensorParams s = limits();
  EXPECT_EQ(worst_draw(s, {result(2.0, 1.0, 0.5)}), 0u);
  EXPECT_EQ(worst_draw(s, {result(2.0, 1.0, 0.5), result(6.0, 1.0, 0.5), result(4.0, 1.0, 0.5)}), 1u);
  // Class II by the attitude (1.2 deg) outranks a larger line-of-sight peak still in Class I.
  InvSimResult turned = result(2.0, 1.0, 1.2);
  turned.attitude_within_limits = false;
  EXPECT_EQ(worst_draw(s, {result(4.9, 1.0, 0.5), turned}), 1u);
  InvSimResult lost = result(3.0, 1.0, 0.5);
  lost.target_always_in_view = false;  // Class III, whatever its peaks
  EXPECT_EQ(worst_draw(s, {result(9.0, 1.0, 3.0), lost, result(9.5, 1.0, 3.0)}), 1u);
  EXPECT_EQ(worst_draw(s, {result(6.0, 1.0, 0.5), result(6.0, 1.0, 0.8), result(6.0, 1.0, 0.8)}), 1u);
  EXPECT_EQ(worst_draw(s, {result(6.0, 1.0, 0.5), result(6.0, 1.0, 0.5)}), 0u);
  InvSimResult diverged = result(1.0, 1.0, 0.5);
  diverged.diverged = true;
  diverged.peak_azimuth_rad = std::numeric_limits<double>::quiet_NaN();
  diverged.peak_attitude_rad.z() = std::numeric_limits<double>::quiet_NaN();
  InvSimResult lost_far = lost;
  lost_far.peak_azimuth_rad = 50.0 * kDegToRad;
  EXPECT_EQ(worst_draw(s, {lost_far, diverged}), 1u);
}

// With several noise draws a row's history is the draw its class comes from, flown again with its
// seed: the draw's class is the row's (the combination keeps a limit only if every draw keeps it),
// its seed is given, and its peaks are within the row's (the row's are the draws' maxima).
// Shipped paper reading, 4 draws, on the modes whose classes differ most (I, II, III).
TEST(Fmea, AHistoryWithSeveralDrawsIsTheDrawTheRowsClassComesFrom) {
  const io::InvSimLoadResult loaded = io::load_invsim_file(
      "scenarios/manual_rvd.yaml", {"pulses.reading=paper", "pulses.paper.measurement_noise.draws=4",
                                    "pulses.paper.measurement_noise.seed=7"});
  ASSERT_TRUE(loaded.errors.empty()) << io::format_errors(loaded.errors);
  const model::InvSimParams& p = *loaded.params;
  std::vector<FmeaCase> cases;
  for (const FmeaCase& c : fmea_cases(p, {}))
    for (const char* label : {"nominal", "e1/e1~", "d1/d2~+e2/e1~", "d2/d2~+e2/e1~"})
      if (c.mode.label == label) cases.push_back(c);
  ASSERT_EQ(cases.size(), 4u);
  std::vector<std::vector<FmeaHistory>> histories;
  const std::vector<FmeaRow> rows = run_fmea(std::vector<model::InvSimParams>{p}, cases, 2, &histories).front();
  const std::vector<FmeaRow> plain = run_fmea(p, cases, 2);
  std::vector<RiskClass> classes;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    SCOPED_TRACE(cases[i].mode.label);
    const FmeaHistory& h = histories[0][i];
    EXPECT_EQ(rows[i].result.k_p, plain[i].result.k_p);  // asking for the history changes no row
    EXPECT_EQ(rows[i].result.peak_azimuth_rad, plain[i].result.peak_azimuth_rad);
    ASSERT_EQ(h.draws, 4u);
    ASSERT_TRUE(h.seed.has_value());
    ASSERT_GE(*h.seed, 7u);
    const std::size_t shown = *h.seed - 7u;  // the seeds of the 4 draws are 7, 8, 9, 10
    ASSERT_LT(shown, 4u);
    const std::vector<InvSimResult> draws = fly_noise_draws(p, cases[i].mode.faults);
    EXPECT_EQ(classify_risk(p.sensor, draws[shown]), rows[i].risk);
    for (const InvSimResult& d : draws)  // of the draws in the row's class, none deviates more
      if (classify_risk(p.sensor, d) == rows[i].risk) {
        EXPECT_LE(deviation_ratio(p.sensor, d), deviation_ratio(p.sensor, draws[shown]));
      }
    ASSERT_EQ(h.samples.size(), 1300u);
    double peak_az = 0.0;
    for (const InvSimSample& sample : h.samples) peak_az = std::max(peak_az, std::abs(sample.azimuth_rad));
    EXPECT_LE(peak_az, rows[i].result.peak_azimuth_rad);
    EXPECT_EQ(peak_az > p.sensor.azimuth_limit_rad, rows[i].risk == RiskClass::kUncontrollable);
    classes.push_back(rows[i].risk);
  }
  EXPECT_EQ(classes.front(), RiskClass::kSmallDeviation);
  EXPECT_EQ(classes[2], RiskClass::kUncontrollable);
}

// The runs are independent, so the rows must not depend on the number of workers; the nominal run
// of the shipped scenario docks with the target in view (docs/invsim.md), hence Class I.
TEST(Fmea, RowsDoNotDependOnThreadsAndNominalIsClassI) {
  const model::InvSimParams p = scenario();
  std::vector<FmeaCase> cases = fmea_cases(p, {});
  cases.resize(6);
  const std::vector<FmeaRow> one = run_fmea(p, cases, 1);
  const std::vector<FmeaRow> three = run_fmea(p, cases, 3);
  ASSERT_EQ(one.size(), cases.size());
  ASSERT_EQ(three.size(), cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) {
    EXPECT_EQ(one[i].fmea_case.mode.label, cases[i].mode.label);
    EXPECT_EQ(three[i].fmea_case.mode.label, cases[i].mode.label);
    EXPECT_EQ(one[i].result.total_pulses, three[i].result.total_pulses);
    EXPECT_EQ(one[i].result.propellant_kg, three[i].result.propellant_kg);  // bitwise: same arithmetic
    EXPECT_EQ(one[i].rank, three[i].rank);
  }
  EXPECT_TRUE(one[0].controllable);
  EXPECT_EQ(one[0].risk, RiskClass::kSmallDeviation);
}

// Zhou 2018's findings on the shipped scenario (docs/invsim.md, "Calibration"): in the original
// layout exactly the four multi-axis modes the paper prints as `---` in Table 5 are uncontrollable
// (their lost thrusters' yaw moments add up while -x and -y fire together at the start and the
// target leaves the 10 deg field of view), every single-axis mode is controllable; Schemes I and II
// make every mode controllable, and Scheme II needs less propellant than Scheme I.
TEST(Fmea, PaperFindingsHoldOnTheShippedScenario) {
  const io::InvSimLoadResult loaded = io::load_invsim_file("scenarios/manual_rvd.yaml");
  ASSERT_TRUE(loaded.errors.empty()) << io::format_errors(loaded.errors);
  std::vector<model::InvSimParams> layouts{*loaded.params};
  for (const auto& c : loaded.study.configurations) layouts.push_back(model::apply_configuration(*loaded.params, c));
  ASSERT_EQ(layouts.size(), 3u);
  const auto rows = run_fmea(layouts, fmea_cases(*loaded.params, {}), 2);
  std::vector<std::string> lost;
  for (const FmeaRow& row : rows[0]) {
    if (row.fmea_case.table == FmeaTable::kSingleAxis) {
      EXPECT_TRUE(row.controllable) << row.fmea_case.mode.label;
    }
    if (row.risk == RiskClass::kUncontrollable) {
      lost.push_back(row.fmea_case.mode.label);
      EXPECT_FALSE(row.result.target_always_in_view) << row.fmea_case.mode.label;
      EXPECT_TRUE(row.result.docked) << row.fmea_case.mode.label;
    }
  }
  EXPECT_EQ(lost, (std::vector<std::string>{"d1/d2~+e2/e1~", "d1/d2~+e2/e2~", "d2/d1~+e1/e1~", "d2/d1~+e1/e2~"}));
  double propellant[3] = {0.0, 0.0, 0.0};
  for (std::size_t l = 0; l < 3; ++l)
    for (const FmeaRow& row : rows[l]) {
      if (l > 0) {
        EXPECT_TRUE(row.controllable) << l << " " << row.fmea_case.mode.label;
      }
      propellant[l] += row.result.propellant_kg;
    }
  EXPECT_LT(propellant[2], propellant[1]);
}

}  // namespace fmea_test
}  // namespace chaser::invsim
