// The observer bank in COMRADE's synchronised flight (fdi.observer_bank; flight/fdi/observer_bank.hpp;
// docs/fdi.md, "The observer bank"), alone (the deficit detector off): the nominal run stays under
// its threshold through the turning hold; a stuck-open thruster of the paper's four alarms within
// seconds and is named by the deficit bank among the hypotheses the rates leave; bad keys are
// refused by name.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "flight/diagnosis_schemes.hpp"
#include "flight/flight_software.hpp"
#include "io/scenario_loader.hpp"
#include "io/scenario_sections.hpp"
#include "sim/run.hpp"
#include "tests/support/scenario_refusal.hpp"

namespace chaser::sim {
namespace sync_observer_bank_test {

model::Scenario sync_with_bank() {
  return testing::load_with("scenarios/comrade_sync.yaml", {"fdi.observer_bank.enabled=true", "fdi.deficit.detection=false",
                                                            "fdi.active_check.enabled=false", "fdi.rate_check.enabled=false"});
}

double largest_statistic(const RunResult& r) {
  double largest = 0.0;
  for (const auto& second : r.glr_max_per_s) largest = std::max(largest, double(second[flight::kBankScheme]));
  return largest;
}

// Seed 1: the statistic stays well under its 1.5 N m (200 dispersed runs: 1.34 at most), but it
// does move: the liquid and the thrust's changes.
TEST(SyncObserverBank, AFaultFreeSynchronisationStaysUnderTheThreshold) {
  RunOptions options;
  options.record_glr_per_second = true;
  const RunResult r = run_scenario(sync_with_bank(), options);
  ASSERT_EQ(flight::diagnosis_schemes()[flight::kBankScheme].name, "bank");
  EXPECT_TRUE(r.fdir.schemes[flight::kBankScheme].enabled);
  EXPECT_LT(r.fdir.schemes[flight::kBankScheme].alarm_s, 0.0);
  EXPECT_GT(largest_statistic(r), 0.05);
  EXPECT_LT(largest_statistic(r), 1.0);
}

// T1, T5, T13, T17 stuck open at 1,500 s in the hold: ~30 N m against 1.5 N m alarms at the first
// block (50 dispersed runs: 1.9 s on average); the rates leave the thruster's torque line and the
// deficit bank names the thruster and its fault among them within 10 s.
TEST(SyncObserverBank, AStuckOpenThrusterIsNamedWithinSeconds) {
  for (const int thruster : {0, 4, 12, 16}) {
    model::Scenario s = sync_with_bank();
    s.faults = {model::FaultParams{.kind = model::FaultKind::kStuckOpen, .thruster = thruster, .onset_s = 1500.0}};
    s.duration_s = 1530.0;
    const SchemeResult& b = run_scenario(s).fdir.schemes[flight::kBankScheme];
    EXPECT_GT(b.alarm_s, 1500.0) << thruster;
    EXPECT_LT(b.alarm_s, 1503.0) << thruster;
    EXPECT_EQ(b.isolated_thruster, thruster);
    EXPECT_LT(b.isolated_s, 1510.0) << thruster;
    EXPECT_EQ(b.diagnosed_kind, model::FaultKind::kStuckOpen) << thruster;
  }
}

// The seconds become whole blocks as the flight software takes them, and the design is the bank's.
TEST(SyncObserverBank, TheFlightSoftwareFliesTheScenariosBank) {
  const flight::FdirParams p = flight::make_flight_params(sync_with_bank()).fdir;
  ASSERT_TRUE(p.bank_enabled);
  EXPECT_EQ(p.bank.block, 10);
  EXPECT_EQ(p.bank.window_blocks, 20);
  EXPECT_EQ(p.bank.baseline_blocks, 100);
  EXPECT_EQ(p.bank.threshold_Nm, 1.5);
  EXPECT_EQ(p.bank.columns, 24);
  EXPECT_EQ(p.bank.observers.size(), 24u);
  EXPECT_EQ(p.bank.n, 9);  // the reduced rate model's order (docs/fdi_design.md)
}

// The keys' checks name the key and the allowed range.
TEST(SyncObserverBank, BadKeysAreRefusedByName) {
  const auto refused = [](std::vector<std::string> sets, const std::string& key, const std::string& says) {
    testing::expect_refused("scenarios/comrade_sync.yaml", sets, key, says);
  };
  refused({"fdi.observer_bank.window_s=0.5"}, "fdi.observer_bank.window_s", ">= one block");
  refused({"fdi.observer_bank.baseline_s=590"}, "fdi.observer_bank.baseline_s", "<= 600");
  refused({"fdi.observer_bank.threshold_Nm=0"}, "fdi.observer_bank.threshold_Nm", "");
  refused({"fdi.observer_bank.isolation_ratio=1"}, "fdi.observer_bank.isolation_ratio", "(0, 1)");
  refused({"fdi.observer_bank.gamma_backoff=1"}, "fdi.observer_bank.gamma_backoff", "(1, 10]");
  refused({"fdi.observer_bank.disturbance_torque_Nm=-0.1"}, "fdi.observer_bank.disturbance_torque_Nm", "");
  // The rate model needs the tanks.
  model::Scenario s = sync_with_bank();
  s.chaser.slosh.reset();
  io::Diagnostics d;
  io::validate_scenario(s, d);
  EXPECT_NE(io::format_errors(d.errors()).find("fdi.observer_bank.enabled: needs chaser.slosh"), std::string::npos)
      << io::format_errors(d.errors());
}

}  // namespace sync_observer_bank_test
}  // namespace chaser::sim
