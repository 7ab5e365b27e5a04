// One core for any thruster set: the MSR scenario flown with a set other than its two branches of
// eight, through the same loader, validation, allocator and plant.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/scenario_loader.hpp"
#include "model/thrusters.hpp"
#include "sim/run.hpp"
#include "tests/sim/thruster_layouts.hpp"

namespace chaser::sim {
namespace {

using testing::one_set_overrides;
using testing::thruster_list;


// 24 thrusters in one set (COMRADE's count): the scenario validates, the width-32 allocator flies
// the approach to capture inside the corridor, and the thrusters beyond the first eight fire.
TEST(ThrusterSets, TwentyFourThrustersFlyToCapture) {
  const io::LoadResult loaded = io::load_scenario_file("scenarios/msr_terminal.yaml", one_set_overrides(24));
  ASSERT_TRUE(loaded.scenario.has_value()) << io::format_errors(loaded.errors);
  const model::Scenario& s = *loaded.scenario;
  EXPECT_EQ(s.thrusters.count, 24);
  EXPECT_EQ(model::initial_active_set(s.thrusters), model::first_thrusters(24));
  const RunResult r = run_scenario(s);
  EXPECT_TRUE(r.figures.capture_achieved);
  EXPECT_EQ(r.figures.corridor_violation_periods, 0);
  EXPECT_FALSE(r.figures.diverged);
  EXPECT_EQ(r.infeasible_allocations, 0);
}

// The same approach flown by MSR's branch A alone (the first eight) and by all 24: more thrusters
// give the allocator cheaper combinations, so the 24-thruster run uses no more propellant (within
// 1 %: the closed loops differ, so the demands do).
TEST(ThrusterSets, MoreThrustersNeedNoMorePropellant) {
  const io::LoadResult eight = io::load_scenario_file("scenarios/msr_terminal.yaml", one_set_overrides(8));
  const io::LoadResult all = io::load_scenario_file("scenarios/msr_terminal.yaml", one_set_overrides(24));
  ASSERT_TRUE(eight.scenario && all.scenario);
  const RunResult a = run_scenario(*eight.scenario);
  const RunResult b = run_scenario(*all.scenario);
  EXPECT_TRUE(a.figures.capture_achieved && b.figures.capture_achieved);
  EXPECT_LT(b.propellant_used_kg, 1.01 * a.propellant_used_kg) << a.propellant_used_kg << " kg with 8";
}

// Sets that cannot push and turn in every direction are refused before any run, at thrusters.list:
// one thruster, and six (positively spanning R^6 takes at least seven vectors, so no layout of six
// can).
TEST(ThrusterSets, SetsThatCannotSpanAreRefused) {
  for (const int count : {1, 6}) {
    std::vector<std::string> overrides = one_set_overrides(8);
    overrides[0] = thruster_list(count);
    const io::LoadResult r = io::load_scenario_file("scenarios/msr_terminal.yaml", overrides);
    EXPECT_FALSE(r.scenario.has_value()) << count;
    ASSERT_EQ(r.errors.size(), 1u) << io::format_errors(r.errors);
    EXPECT_EQ(r.errors[0].key_path, "thrusters.list");
    EXPECT_NE(r.errors[0].message.find("cannot produce force and torque in every direction"), std::string::npos)
        << r.errors[0].message;
  }
}

// 33 thrusters exceed the capacity: refused with the allowed range.
TEST(ThrusterSets, MoreThanThirtyTwoAreRefused) {
  std::vector<std::string> overrides = one_set_overrides(8);
  overrides[0] = thruster_list(33);
  const io::LoadResult r = io::load_scenario_file("scenarios/msr_terminal.yaml", overrides);
  ASSERT_EQ(r.errors.size(), 1u) << io::format_errors(r.errors);
  EXPECT_EQ(r.errors[0].key_path, "thrusters.list");
  EXPECT_NE(r.errors[0].message.find("1..32"), std::string::npos) << r.errors[0].message;
}

// Fonod 2015's schemes (eight lanes) refuse a set of 24 with a message that names only their keys
// and says what to change; the deficit detector alone watches the 24.
TEST(ThrusterSets, EightLaneSchemesRefuseTwentyFourTheDeficitDetectorWatchesThem) {
  std::vector<std::string> overrides = one_set_overrides(24);
  overrides.resize(3);  // FDI left on: position, attitude and deficit detection
  const io::LoadResult r = io::load_scenario_file("scenarios/msr_terminal.yaml", overrides);
  ASSERT_EQ(r.errors.size(), 1u) << io::format_errors(r.errors);
  EXPECT_EQ(r.errors[0].key_path, "fdi");
  const std::string& m = r.errors[0].message;
  EXPECT_NE(m.find("fdi.position and fdi.attitude (the Fonod 2015 schemes) watch exactly 8 active thrusters"),
            std::string::npos) << m;
  EXPECT_NE(m.find("has 24"), std::string::npos) << m;
  EXPECT_NE(m.find("disable fdi.position and fdi.attitude"), std::string::npos) << m;

  overrides.insert(overrides.end(), {"fdi.position.enabled=false", "fdi.attitude.enabled=false"});
  const io::LoadResult deficit_only = io::load_scenario_file("scenarios/msr_terminal.yaml", overrides);
  EXPECT_TRUE(deficit_only.scenario.has_value()) << io::format_errors(deficit_only.errors);
  EXPECT_TRUE(deficit_only.scenario && deficit_only.scenario->fdi.deficit.detection);
}

}  // namespace
}  // namespace chaser::sim
