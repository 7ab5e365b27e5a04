// Blocks at their own rates beside the flight software's period (sim/rate_schedule.hpp, driven by
// Simulation::add_block): a platform loop at 1/3 s and a 1 kHz inner block run at their rates, in
// the declared order at shared times, after the flight software, each seeing the truth of its own
// time; the flight software's run is the one it flies alone, to the integration's rounding.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "io/scenario_loader.hpp"
#include "sim/simulation.hpp"

namespace chaser::sim {
namespace {

model::Scenario msr(double duration_s) {
  const io::LoadResult loaded = io::load_scenario_file("scenarios/msr_terminal.yaml");
  EXPECT_TRUE(loaded.errors.empty()) << io::format_errors(loaded.errors);
  model::Scenario s = *loaded.scenario;
  s.duration_s = duration_s;
  return s;
}

struct Seen {
  std::string block;
  TimeNs t = 0;
  Vec3 r_lvlh_m = Vec3::Zero();
};

// Flies `s` with the given blocks; returns what each saw, in call order, and the telemetry rows.
std::vector<Seen> fly(const model::Scenario& s, const std::vector<std::pair<std::string, Rate>>& blocks,
                      TelemetryRows& rows) {
  const flight::FlightParams flight_params = flight::make_flight_params(s);
  Simulation sim(s, flight_params, {.telemetry_path = {}, .telemetry_channels = {}, .telemetry_rows = &rows,
                                    .record_glr_per_second = false});
  std::vector<Seen> seen;
  for (const auto& [name, rate] : blocks)
    sim.add_block(name, rate, [&seen, name](TimeNs t, const plant::Plant& plant) {
      seen.push_back({name, t, plant::chaser_state(plant).r_lvlh_m});
    });
  while (!sim.done()) sim.step();
  sim.finish();
  return seen;
}

std::vector<TimeNs> times_of(const std::vector<Seen>& seen, const std::string& block) {
  std::vector<TimeNs> t;
  for (const Seen& s : seen)
    if (s.block == block) t.push_back(s.t);
  return t;
}

TEST(MultiRate, AThirdOfASecondPlatformAndAKilohertzInnerBlockRunAtTheirRatesInOrder) {
  const model::Scenario s = msr(2.0);
  TelemetryRows rows;
  const std::vector<Seen> seen =
      fly(s, {{"platform", Rate{kNsPerSecond, 3, 0}}, {"inner", rate_of_hz(1000)}}, rows);
  EXPECT_EQ(times_of(seen, "platform"),
            (std::vector<TimeNs>{0, 333'333'334, 666'666'667, 1'000'000'000, 1'333'333'334, 1'666'666'667}));
  const std::vector<TimeNs> inner = times_of(seen, "inner");
  ASSERT_EQ(inner.size(), 2000u);
  for (std::size_t m = 0; m < inner.size(); ++m) ASSERT_EQ(inner[m], static_cast<TimeNs>(m) * 1'000'000);
  // Calls in time order; at a shared time (0 s, 1 s) the platform first, as declared.
  for (std::size_t i = 1; i < seen.size(); ++i) {
    ASSERT_GE(seen[i].t, seen[i - 1].t);
    if (seen[i].t == seen[i - 1].t) {
      EXPECT_EQ(seen[i - 1].block, "platform") << seen[i].t;
    }
  }
  // At a period's start the plant has not moved since the flight software sensed it: the inner
  // block sees exactly the truth telemetry records for that period.
  const std::size_t width = rows.channels.size();
  const auto x = static_cast<std::size_t>(std::find(rows.channels.begin(), rows.channels.end(), "r_lvlh_x_m") -
                                          rows.channels.begin());
  for (std::size_t k = 0; k < 20; ++k) {
    const Seen& at_start = seen[static_cast<std::size_t>(std::find_if(seen.begin(), seen.end(), [&](const Seen& e) {
                                                           return e.block == "inner" &&
                                                                  e.t == static_cast<TimeNs>(k) * 100'000'000;
                                                         }) - seen.begin())];
    EXPECT_EQ(at_start.r_lvlh_m.x(), rows.values[k * width + x]) << k;
  }
}

// Each block sees the truth of its own time: a 500 Hz block and the 1 kHz block, whose stops differ,
// see the same truth at the times they share, and the flight software flies the run it flies alone.
// What may differ is the RK4 steps' split at a stop (kDefaultMaxSubstepS substeps of a 22 N pulse on
// 2,500 kg; measured 4.6e-14 m between the blocks, 2.5e-14 m in telemetry); a block seeing another
// time would be off by v dt, 2e-5 m
// for 1 ms at 2 cm/s.
TEST(MultiRate, EachBlockSeesTheTruthOfItsOwnTime) {
  const model::Scenario s = msr(5.0);
  TelemetryRows alone_rows, fast_rows, slow_rows;
  fly(s, {}, alone_rows);
  const std::vector<Seen> fast = fly(s, {{"probe", rate_of_hz(1000)}}, fast_rows);
  const std::vector<Seen> slow = fly(s, {{"probe", rate_of_hz(500)}}, slow_rows);
  ASSERT_EQ(fast.size(), 5000u);
  ASSERT_EQ(slow.size(), 2500u);
  double largest = 0.0;
  for (std::size_t m = 0; m < slow.size(); ++m) {
    ASSERT_EQ(slow[m].t, fast[2 * m].t);
    largest = std::max(largest, (slow[m].r_lvlh_m - fast[2 * m].r_lvlh_m).norm());
  }
  EXPECT_LT(largest, 1e-12);
  ASSERT_EQ(fast_rows.values.size(), alone_rows.values.size());
  double telemetry = 0.0;
  for (std::size_t i = 0; i < alone_rows.values.size(); ++i)
    if (alone_rows.channels[i % alone_rows.channels.size()].rfind("r_lvlh_", 0) == 0)
      telemetry = std::max(telemetry, std::abs(fast_rows.values[i] - alone_rows.values[i]));
  EXPECT_LT(telemetry, 1e-12);
}

TEST(MultiRate, ABadRateOrALateBlockIsRefused) {
  const model::Scenario s = msr(1.0);
  const flight::FlightParams flight_params = flight::make_flight_params(s);
  Simulation sim(s, flight_params, {});
  EXPECT_THROW(sim.add_block("zero", Rate{0, 1, 0}, [](TimeNs, const plant::Plant&) {}), std::invalid_argument);
  sim.step();
  EXPECT_THROW(sim.add_block("late", rate_of_hz(10), [](TimeNs, const plant::Plant&) {}), std::invalid_argument);
}

}  // namespace
}  // namespace chaser::sim
