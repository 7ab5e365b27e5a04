#include "invsim/noise_draws.hpp"

#include <string>

#include <gtest/gtest.h>

#include "io/invsim_loader.hpp"

namespace chaser::invsim {
namespace {

InvSimResult draw_result(int y_pos, double peak_az, bool docked, double propellant) {
  InvSimResult r;
  r.pulses[1].count[0] = y_pos;
  r.pulses[1].on_time_s[0] = 0.1 * y_pos;
  r.total_pulses = y_pos;
  r.k_p = y_pos / 3000.0;
  r.peak_azimuth_rad = peak_az;
  r.docked = docked;
  r.propellant_kg = propellant;
  r.final_r_hill_m = Vec3(y_pos, 0.0, 0.0);
  return r;
}

// The combination (invsim/noise_draws.hpp): mean workload (counts rounded, k_p of the unrounded
// mean P), worst deviation, a limit kept only if kept in every draw, the first draw's end state.
TEST(NoiseDraws, MeanWorkloadWorstDeviation) {
  const InvSimResult r = combine_draws({draw_result(100, 0.01, true, 4.0), draw_result(103, 0.03, false, 5.0),
                                        draw_result(101, 0.02, true, 6.0)},
                                       3000.0);
  EXPECT_EQ(r.pulses[1].count[0], 101);  // 304 / 3 = 101.33
  EXPECT_NEAR(r.pulses[1].on_time_s[0], 10.1333333333333, 1e-12);
  EXPECT_EQ(r.total_pulses, 101);
  EXPECT_DOUBLE_EQ(r.k_p, 304.0 / 3.0 / 3000.0);
  EXPECT_EQ(r.peak_azimuth_rad, 0.03);
  EXPECT_FALSE(r.docked);
  EXPECT_DOUBLE_EQ(r.propellant_kg, 5.0);
  EXPECT_EQ(r.final_r_hill_m.x(), 100.0);
}

model::InvSimParams shipped_paper(const std::string& draws, const std::string& seed) {
  const auto loaded = io::load_invsim_file(
      "scenarios/manual_rvd.yaml", {"pulses.reading=paper", "pulses.paper.measurement_noise.draws=" + draws,
                                    "pulses.paper.measurement_noise.seed=" + seed});
  EXPECT_TRUE(loaded.errors.empty());
  return *loaded.params;
}

// One draw is the plain run bit for bit; three draws are the combination of the three plain runs
// with seeds seed, seed + 1, seed + 2 (recomputed here one by one), for a fault mode too.
TEST(NoiseDraws, ThreeDrawsAreThreeSeedsCombined) {
  model::InvSimFaultSet e1n;
  const auto loaded = io::load_invsim_file("scenarios/manual_rvd.yaml", {"faults=[e1~]"});
  ASSERT_TRUE(loaded.errors.empty());
  e1n = loaded.faults;
  const InvSimResult one = run_over_noise_draws(shipped_paper("1", "5"), e1n);
  const InvSimResult plain = run_inverse_simulation(shipped_paper("1", "5"), e1n);
  EXPECT_EQ(one.k_p, plain.k_p);
  EXPECT_EQ(one.peak_azimuth_rad, plain.peak_azimuth_rad);
  const InvSimResult three = run_over_noise_draws(shipped_paper("3", "5"), e1n);
  std::vector<InvSimResult> runs;
  for (const char* seed : {"5", "6", "7"}) runs.push_back(run_inverse_simulation(shipped_paper("1", seed), e1n));
  const InvSimResult expected = combine_draws(runs, 3000.0);
  EXPECT_EQ(three.k_p, expected.k_p);
  EXPECT_EQ(three.total_pulses, expected.total_pulses);
  EXPECT_EQ(three.pulses[1].count, expected.pulses[1].count);
  EXPECT_EQ(three.peak_azimuth_rad, expected.peak_azimuth_rad);
  EXPECT_EQ(three.propellant_kg, expected.propellant_kg);
  EXPECT_NE(runs[0].total_pulses, runs[1].total_pulses);  // the draws differ
}

// draws is a count in [1, 1000], named with its key otherwise.
TEST(NoiseDraws, DrawsOutOfRangeIsNamed) {
  for (const char* bad : {"0", "1001", "2.5"}) {
    const auto r = io::load_invsim_file("scenarios/manual_rvd.yaml",
                                        {std::string("pulses.paper.measurement_noise.draws=") + bad});
    ASSERT_FALSE(r.errors.empty()) << bad;
    EXPECT_NE(io::format_errors(r.errors).find("pulses.paper.measurement_noise.draws"), std::string::npos) << bad;
  }
}

}  // namespace
}  // namespace chaser::invsim
