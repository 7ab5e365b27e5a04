// The deficit detector in COMRADE's synchronised flight with the impulse statistic
// (fdi.deficit.detection_statistic: impulse; flight/fdi/impulse_detector.hpp; docs/fdi.md, "Turning
// flight: the impulse statistic"): the nominal run, which the gain statistic alarms in (the slosh
// masses' strikes on their walls), stays far under the threshold; a stuck-open and a leaking
// thruster are named within seconds, against the truth's thruster and fault.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "flight/diagnosis_schemes.hpp"
#include "flight/flight_software.hpp"
#include "io/scenario_loader.hpp"
#include "sim/run.hpp"
#include "tests/support/scenario_refusal.hpp"

namespace chaser::sim {
namespace {

model::Scenario sync_with(const std::string& statistic) {
  return testing::load_with("scenarios/comrade_sync.yaml",
                            {"fdi.deficit.detection=true", "fdi.deficit.detection_statistic=" + statistic});
}

// The largest statistic of the deficit scheme over the run (per-second maxima).
double largest_statistic(const RunResult& r) {
  double largest = 0.0;
  for (const auto& second : r.glr_max_per_s) largest = std::max(largest, double(second[flight::kDeficitScheme]));
  return largest;
}

// Nominal run (seed 1): the impulse statistic reaches 4.1 N m s at most (in the spin-up and the
// transfer), a tenth of its threshold, 40; the gain statistic alarms, at 1,587 s.
TEST(SyncImpulseDetection, AFaultFreeSynchronisationStaysFarUnderTheThreshold) {
  const RunResult impulse = run_scenario(sync_with("impulse"), {.record_glr_per_second = true});
  EXPECT_LT(impulse.fdir.schemes[flight::kDeficitScheme].alarm_s, 0.0);
  EXPECT_GT(largest_statistic(impulse), 0.5);  // it does see the liquid and the thrust's changes
  EXPECT_LT(largest_statistic(impulse), 10.0);
  EXPECT_GT(run_scenario(sync_with("gain")).fdir.schemes[flight::kDeficitScheme].alarm_s, 0.0);
}

// The paper's four hardest thrusters (COMRADE 2018, sec. 6.3: 1, 5, 13, 17) stuck open at 1,500 s,
// in the turning hold: each is detected within 5 s (its ~20 N m reaches 40 N m s in ~2 s) and the
// deficit bank names it and its fault within 10 s (50 dispersed runs: 2.0 s and 2.9 s on average).
TEST(SyncImpulseDetection, AStuckOpenThrusterIsNamedWithinSeconds) {
  for (const int thruster : {0, 4, 12, 16}) {
    model::Scenario s = sync_with("impulse");
    s.faults = {model::FaultParams{.kind = model::FaultKind::kStuckOpen, .thruster = thruster, .onset_s = 1500.0}};
    s.duration_s = 1530.0;
    const SchemeResult& d = run_scenario(s).fdir.schemes[flight::kDeficitScheme];
    EXPECT_GT(d.alarm_s, 1500.0) << thruster;
    EXPECT_LT(d.alarm_s, 1505.0) << thruster;
    EXPECT_EQ(d.isolated_thruster, thruster);
    EXPECT_LT(d.isolated_s, 1510.0) << thruster;
    EXPECT_EQ(d.diagnosed_kind, model::FaultKind::kStuckOpen) << thruster;
  }
}

// A 20 % leak on T5 at 1,500 s: its ~4 N m takes ~10 s to reach 40 N m s (50 dispersed leaks of
// 10-30 %: 11.2 s to detect, 15.0 s to isolate on average).
TEST(SyncImpulseDetection, ALeakIsNamedWithinAMinute) {
  model::Scenario s = sync_with("impulse");
  s.faults = {model::FaultParams{.kind = model::FaultKind::kLeak, .thruster = 4, .onset_s = 1500.0}};
  s.duration_s = 1600.0;
  const SchemeResult& d = run_scenario(s).fdir.schemes[flight::kDeficitScheme];
  EXPECT_GT(d.alarm_s, 1500.0);
  EXPECT_LT(d.alarm_s, 1530.0);
  EXPECT_EQ(d.isolated_thruster, 4);
  EXPECT_LT(d.isolated_s, 1560.0);
  EXPECT_EQ(d.diagnosed_kind, model::FaultKind::kLeak);
}

// The scenario's seconds become whole blocks of a second (T = 0.1 s: ten periods) as the flight
// software takes them, and what validation passes fits the detector's ring.
TEST(SyncImpulseDetection, WindowsBecomeWholeBlocks) {
  const flight::fdi::ImpulseDetectorParams p = flight::make_flight_params(sync_with("impulse")).fdir.impulse;
  EXPECT_EQ(p.block, 10);
  EXPECT_EQ(p.window_blocks, 20);
  EXPECT_EQ(p.baseline_blocks, 100);
  EXPECT_EQ(p.threshold_Nms, 40.0);
  EXPECT_TRUE(flight::fdi::validate(p).empty());
  // 300.5 s rounds to 301 blocks: with 299.9 s (300 blocks) one more than the ring's 600.
  const io::LoadResult over = io::load_scenario_file(
      "scenarios/comrade_sync.yaml", {"fdi.deficit.impulse_window_s=300.5", "fdi.deficit.impulse_baseline_s=299.9"});
  EXPECT_NE(io::format_errors(over.errors).find("(got 601 blocks)"), std::string::npos) << io::format_errors(over.errors);
  const io::LoadResult fits = io::load_scenario_file(
      "scenarios/comrade_sync.yaml", {"fdi.deficit.impulse_window_s=300.4", "fdi.deficit.impulse_baseline_s=299.9"});
  EXPECT_TRUE(fits.errors.empty()) << io::format_errors(fits.errors);
  EXPECT_TRUE(flight::fdi::validate(flight::make_flight_params(*fits.scenario).fdir.impulse).empty());
}

// The keys' checks name the key and the allowed range.
TEST(SyncImpulseDetection, BadKeysAreRefusedByName) {
  const auto refused = [](std::vector<std::string> sets, const std::string& key, const std::string& says) {
    testing::expect_refused("scenarios/comrade_sync.yaml", sets, key, says);
  };
  refused({"fdi.deficit.impulse_window_s=0.5"}, "fdi.deficit.impulse_window_s", ">= one block");
  refused({"fdi.deficit.impulse_baseline_s=590"}, "fdi.deficit.impulse_baseline_s", "<= 600");
  refused({"fdi.deficit.impulse_threshold_Nms=-1"}, "fdi.deficit.impulse_threshold_Nms", "");
  refused({"fdi.deficit.detection_statistic=mean"}, "fdi.deficit.detection_statistic", "gain");
}

}  // namespace
}  // namespace chaser::sim
