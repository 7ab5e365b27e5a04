#include "invsim/layout_study.hpp"

#include <set>
#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "io/invsim_loader.hpp"
#include "model/invsim_study.hpp"

namespace chaser::invsim {
namespace {

io::InvSimLoadResult shipped() {
  io::InvSimLoadResult loaded = io::load_invsim_file("scenarios/manual_rvd.yaml");
  EXPECT_TRUE(loaded.errors.empty()) << io::format_errors(loaded.errors);
  return loaded;
}

model::InvSimConfiguration option(std::string name, std::size_t thruster, double thrust_N) {
  model::InvSimConfiguration c;
  c.name = std::move(name);
  model::InvSimThrusterChange change;
  change.thruster = thruster;
  change.thrust_N = thrust_N;
  c.changes.push_back(change);
  return c;
}

// Applying a configuration changes exactly the fields it sets (and renormalises a direction).
TEST(LayoutStudy, ApplyChangesOnlyTheGivenFields) {
  const model::InvSimParams base = *shipped().params;
  model::InvSimConfiguration c = option("x", 1, 50.0);
  model::InvSimThrusterChange moved;
  moved.thruster = 7;
  moved.position_body_m = Vec3(-1.5, 0.0, 0.7);
  moved.direction_body = Vec3(2.0, 0.0, 0.0);
  c.changes.push_back(moved);
  const model::InvSimParams p = model::apply_configuration(base, c);
  EXPECT_EQ(p.thrusters[1].thrust_N, 50.0);
  EXPECT_EQ(p.thrusters[1].position_body_m, base.thrusters[1].position_body_m);
  EXPECT_EQ(p.thrusters[7].position_body_m, Vec3(-1.5, 0.0, 0.7));
  EXPECT_EQ(p.thrusters[7].direction_body, Vec3(1.0, 0.0, 0.0));
  EXPECT_EQ(p.thrusters[7].thrust_N, base.thrusters[7].thrust_N);
  for (std::size_t i = 8; i < p.thrusters.size(); ++i) EXPECT_EQ(p.thrusters[i].position_body_m, base.thrusters[i].position_body_m);
}

// Candidates enumerate the product in mixed radix, the first choice varying slowest; each takes the
// changes of its options in order; the count saturates above the cap.
TEST(LayoutStudy, CandidatesEnumerateTheProduct) {
  std::vector<model::InvSimFreeChoice> choices(2);
  choices[0] = {"level", {option("low", 1, 25.0), option("high", 1, 50.0)}};
  choices[1] = {"d", {model::InvSimConfiguration{"keep", "", {}}, option("a", 7, 30.0), option("b", 7, 90.0)}};
  ASSERT_EQ(model::candidate_count(choices), 6u);
  EXPECT_EQ(model::candidate(choices, 0).name, "level=low, d=keep");
  EXPECT_EQ(model::candidate(choices, 2).name, "level=low, d=b");
  EXPECT_EQ(model::candidate(choices, 3).name, "level=high, d=keep");
  const model::InvSimConfiguration last = model::candidate(choices, 5);
  EXPECT_EQ(last.name, "level=high, d=b");
  ASSERT_EQ(last.changes.size(), 2u);
  EXPECT_EQ(last.changes[0].thrust_N, 50.0);
  EXPECT_EQ(last.changes[1].thrust_N, 90.0);
  std::vector<model::InvSimFreeChoice> many(13, model::InvSimFreeChoice{"c", {option("p", 1, 25.0), option("q", 1, 30.0)}});
  EXPECT_EQ(model::candidate_count(many), model::kMaxOptimizeCandidates + 1);
}

FmeaRow row(std::uint64_t failed_mask, RiskClass risk, double propellant_kg) {
  FmeaRow r;
  r.fmea_case.mode.faults.failed_mask = failed_mask;
  r.risk = risk;
  r.controllable = risk != RiskClass::kUncontrollable;
  r.result.propellant_kg = propellant_kg;
  r.result.k_p = 0.1;
  return r;
}

// The summary counts fault modes (not the nominal row) per class, the most failed thrusters in a
// controllable mode and the fewest in a lost one, and sums the propellant of every row.
TEST(LayoutStudy, SummaryCountsClassesAndTolerance) {
  const std::vector<FmeaRow> rows{row(0, RiskClass::kSmallDeviation, 4.0), row(0b1, RiskClass::kSmallDeviation, 4.5),
                                  row(0b1111, RiskClass::kLargeDeviation, 5.0),
                                  row(0b111, RiskClass::kUncontrollable, 6.0),
                                  row(0b1111'0000, RiskClass::kUncontrollable, 6.0)};
  const LayoutSummary s = summarize_layout(rows);
  EXPECT_TRUE(s.nominal_controllable);
  EXPECT_EQ(s.fault_modes, 4);
  EXPECT_EQ(s.per_class[0], 1);
  EXPECT_EQ(s.per_class[1], 1);
  EXPECT_EQ(s.per_class[2], 2);
  EXPECT_EQ(s.controllable, 2);
  EXPECT_EQ(s.most_failed_tolerated, 4);
  EXPECT_EQ(s.fewest_failed_lost, 3);
  EXPECT_DOUBLE_EQ(s.propellant_kg, 25.5);
  EXPECT_DOUBLE_EQ(s.mean_k_p, 0.1);
}

// Better first: a nominal run that docks, more controllable modes, fewer Class II, less propellant.
TEST(LayoutStudy, OrderPrefersControllabilityThenPropellant) {
  LayoutSummary a, b, c, d;
  a.nominal_controllable = b.nominal_controllable = c.nominal_controllable = true;
  a.controllable = 40, a.per_class = {30, 10, 0}, a.propellant_kg = 100.0;
  b.controllable = 40, b.per_class = {40, 0, 0}, b.propellant_kg = 200.0;
  c.controllable = 40, c.per_class = {40, 0, 0}, c.propellant_kg = 150.0;
  d.controllable = 40, d.per_class = {40, 0, 0}, d.propellant_kg = 10.0;  // but the nominal run fails
  EXPECT_EQ(layout_order({a, b, c, d}), (std::vector<std::size_t>{2, 1, 0, 3}));
}

// The search over the shipped choices restricted to two (attitude level x d_forward plane, 6
// candidates) on a few modes returns every candidate once, best first, and does not depend on the
// number of workers.
TEST(LayoutStudy, SearchIsCompleteOrderedAndThreadIndependent) {
  const io::InvSimLoadResult loaded = shipped();
  std::vector<model::InvSimFreeChoice> choices(loaded.study.free_choices.begin(), loaded.study.free_choices.begin() + 2);
  std::vector<FmeaCase> cases = fmea_cases(*loaded.params, {});
  cases = {cases[0], cases[31]};  // nominal and d1/d2~+e2/e1~, Class III in the baseline layout
  const std::vector<LayoutCandidate> one = search_layouts(*loaded.params, choices, cases, 1);
  const std::vector<LayoutCandidate> two = search_layouts(*loaded.params, choices, cases, 2);
  ASSERT_EQ(one.size(), 6u);
  ASSERT_EQ(two.size(), 6u);
  std::vector<LayoutSummary> summaries;
  for (std::size_t k = 0; k < one.size(); ++k) {
    EXPECT_EQ(one[k].configuration.name, two[k].configuration.name);
    EXPECT_EQ(one[k].summary.propellant_kg, two[k].summary.propellant_kg);  // bitwise: same runs
    summaries.push_back(one[k].summary);
    if (k > 0) {
      EXPECT_FALSE(better_layout(one[k].summary, one[k - 1].summary)) << k;
    }
  }
  // Only the baseline's candidate (25 N, x-o-y) loses the mode; it must come last.
  EXPECT_EQ(one.back().configuration.name, "attitude_thrust=25N, d_forward=xoy");
  EXPECT_EQ(one.back().summary.per_class[2], 1);
}

}  // namespace
}  // namespace chaser::invsim

namespace chaser::invsim {
namespace {

std::vector<model::InvSimParams> all_candidates(const io::InvSimLoadResult& loaded) {
  std::vector<model::InvSimParams> layouts;
  for (std::size_t i = 0; i < model::candidate_count(loaded.study.free_choices); ++i)
    layouts.push_back(model::apply_configuration(*loaded.params, model::candidate(loaded.study.free_choices, i)));
  return layouts;
}

void expect_same_result(const InvSimResult& a, const InvSimResult& b, const std::string& what) {
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_EQ(a.pulses[axis].count, b.pulses[axis].count) << what;
    EXPECT_EQ(a.pulses[axis].on_time_s, b.pulses[axis].on_time_s) << what;  // bitwise
  }
  EXPECT_EQ(a.k_p, b.k_p) << what;
  EXPECT_EQ(a.propellant_kg, b.propellant_kg) << what;
  EXPECT_EQ(a.attitude_propellant_kg, b.attitude_propellant_kg) << what;
  EXPECT_EQ(a.peak_azimuth_rad, b.peak_azimuth_rad) << what;
  EXPECT_EQ(a.peak_elevation_rad, b.peak_elevation_rad) << what;
  EXPECT_EQ(a.peak_attitude_rad, b.peak_attitude_rad) << what;
  EXPECT_EQ(a.attitude_on_time_s, b.attitude_on_time_s) << what;
  EXPECT_EQ(a.final_r_hill_m, b.final_r_hill_m) << what;
  EXPECT_EQ(a.final_v_hill_mps, b.final_v_hill_mps) << what;
  EXPECT_EQ(std::make_tuple(a.target_always_in_view, a.attitude_within_limits, a.docked, a.diverged),
            std::make_tuple(b.target_always_in_view, b.attitude_within_limits, b.docked, b.diverged))
      << what;
}

// Moving both thrusters of a healthy pair (d1, d2 from the x-o-y into the x-o-z plane, Scheme II)
// leaves every group's wrench as it was: the signatures are equal and the runs agree bit for bit.
// With d1 lost the pair is no longer balanced, and the signature tells the layouts apart.
TEST(LayoutStudy, AHealthyBalancedPairMovedKeepsTheSignatureAndTheFlight) {
  const model::InvSimParams base = *shipped().params;
  model::InvSimParams moved = base;
  std::size_t d1 = 0;
  for (std::size_t i = 0; i < moved.thrusters.size(); ++i) {
    if (moved.thrusters[i].name == "d1") moved.thrusters[i].position_body_m = Vec3(-1.5, 0.0, 0.7), d1 = i;
    if (moved.thrusters[i].name == "d2") moved.thrusters[i].position_body_m = Vec3(-1.5, 0.0, -0.7);
  }
  const model::InvSimFaultSet healthy{}, e1_lost{1ULL << (d1 + 4)}, d1_lost{1ULL << d1};
  ASSERT_EQ(base.thrusters[d1 + 4].name, "e1");
  for (const model::InvSimFaultSet& f : {healthy, e1_lost}) {
    EXPECT_EQ(thruster_signature(base, f), thruster_signature(moved, f));
    expect_same_result(run_inverse_simulation(base, f), run_inverse_simulation(moved, f), "d pair moved");
  }
  EXPECT_NE(thruster_signature(base, d1_lost), thruster_signature(moved, d1_lost));
  EXPECT_NE(run_inverse_simulation(base, d1_lost).peak_attitude_rad, run_inverse_simulation(moved, d1_lost).peak_attitude_rad);
}

// How many distinct flights the shipped choices leave, counted from the choices without the
// signature: a choice changes a mode's run when an option sets a thrust (the attitude couples act in
// every mode) or moves a thruster the mode lost; the shipped plane choices move both thrusters of a
// pair symmetrically, so a healthy pair moved stays balanced and changes nothing. A mode then has
// the product of the option counts of the choices that matter: 3 for the nominal and the z rows, up
// to 3 x 2^4 = 48 for a Table 5 row that loses a thruster of each of d, d~, e, e~.
std::size_t flights_by_the_choices(const std::vector<model::InvSimFreeChoice>& choices,
                                   const std::vector<FmeaCase>& cases) {
  std::size_t flights = 0;
  for (const FmeaCase& c : cases) {
    std::size_t n = 1;
    for (const model::InvSimFreeChoice& choice : choices) {
      bool matters = false;
      for (const model::InvSimConfiguration& option : choice.options)
        for (const model::InvSimThrusterChange& change : option.changes)
          matters = matters || change.thrust_N.has_value() || c.mode.faults.failed(change.thruster);
      if (matters) n *= choice.options.size();
    }
    flights += n;
  }
  return flights;
}

// The search's shared flights give run_fmea's rows bit for bit (every shipped candidate; the
// nominal, Table 2's first seven rows and Table 5's first six), and the signatures tell apart exactly
// the flights the choices make different: 939 of the 48 x 41 (invsim/fmea.hpp).
TEST(LayoutStudy, SharedFlightsGiveTheRowsOfEveryFlight) {
  const io::InvSimLoadResult loaded = shipped();
  const std::vector<model::InvSimParams> layouts = all_candidates(loaded);
  const std::vector<FmeaCase> all = fmea_cases(*loaded.params, {});
  std::set<std::vector<double>> distinct;
  for (const model::InvSimParams& p : layouts)
    for (const FmeaCase& c : all) distinct.insert(thruster_signature(p, c.mode.faults));
  EXPECT_EQ(layouts.size() * all.size(), 1968u);
  EXPECT_EQ(distinct.size(), flights_by_the_choices(loaded.study.free_choices, all));
  EXPECT_EQ(distinct.size(), 939u);
  std::vector<FmeaCase> cases(all.begin(), all.begin() + 8);
  cases.insert(cases.end(), all.begin() + 25, all.begin() + 31);
  ASSERT_EQ(cases.back().table, FmeaTable::kMultiAxis);
  const auto every = run_fmea(layouts, cases, 2);
  const auto shared = run_fmea_of_configurations(layouts, cases, 2);
  for (std::size_t l = 0; l < layouts.size(); ++l)
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const std::string what = std::to_string(l) + " " + cases[i].mode.label;
      expect_same_result(shared[l][i].result, every[l][i].result, what);
      EXPECT_EQ(shared[l][i].rank, every[l][i].rank) << what;
      EXPECT_EQ(shared[l][i].risk, every[l][i].risk) << what;
    }
}

}  // namespace
}  // namespace chaser::invsim
