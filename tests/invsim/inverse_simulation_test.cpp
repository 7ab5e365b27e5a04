#include "invsim/inverse_simulation.hpp"

#include <cstdio>

#include <gtest/gtest.h>

#include "core/constants.hpp"
#include "io/invsim_loader.hpp"

namespace chaser::invsim {
namespace {

model::InvSimParams load_nominal() {
  const io::InvSimLoadResult loaded = io::load_invsim_file("scenarios/manual_rvd.yaml");
  EXPECT_TRUE(loaded.errors.empty()) << io::format_errors(loaded.errors);
  return *loaded.params;
}

void print(const char* label, const InvSimResult& r) {
  std::printf("%s: x %d/%d y %d/%d z %d/%d  kp %.3f  az %.2f el %.2f att %.2f %.2f %.2f deg  "
              "docked %d view %d att_ok %d  final [%.2f %.2f %.2f] v [%.3f %.3f %.3f] prop %.1f kg (att %.1f)\n",
              label, r.pulses[0].count[0], r.pulses[0].count[1], r.pulses[1].count[0],
              r.pulses[1].count[1], r.pulses[2].count[0], r.pulses[2].count[1], r.k_p,
              r.peak_azimuth_rad / kDegToRad, r.peak_elevation_rad / kDegToRad,
              r.peak_attitude_rad.x() / kDegToRad, r.peak_attitude_rad.y() / kDegToRad,
              r.peak_attitude_rad.z() / kDegToRad, r.docked, r.target_always_in_view,
              r.attitude_within_limits, r.final_r_hill_m.x(), r.final_r_hill_m.y(),
              r.final_r_hill_m.z(), r.final_v_hill_mps.x(), r.final_v_hill_mps.y(),
              r.final_v_hill_mps.z(), r.propellant_kg, r.attitude_propellant_kg);
}

// The nominal run of Zhou 2018, Fig. 6: the inverse model flies the chaser into the docking
// envelope (2.42 x 2.42 x 4 m) with the target in view (|az|, |el| <= 10 deg) and the attitude
// within +-1 deg throughout.
TEST(InverseSimulation, NominalRunDocksWithTargetInView) {
  const model::InvSimParams p = load_nominal();
  const InvSimResult r = run_inverse_simulation(p, model::InvSimFaultSet{});
  print("nominal", r);
  EXPECT_FALSE(r.diverged);
  EXPECT_TRUE(r.docked);
  EXPECT_TRUE(r.target_always_in_view);
  EXPECT_TRUE(r.attitude_within_limits);
}

// A lost +x thruster (d1) halves the +x group's thrust: the inverse model compensates with longer
// +x opening time (impulse conservation: about twice the nominal, 1.4-2.5x allowing for the changed
// path) and the approach still docks; the yaw moment it leaves stays within the attitude limit.
TEST(InverseSimulation, LostThrusterIsCompensatedByLongerOpening) {
  const model::InvSimParams p = load_nominal();
  const InvSimResult nominal = run_inverse_simulation(p, model::InvSimFaultSet{});
  model::InvSimFaultSet d1;
  d1.failed_mask = std::uint64_t{1} << 7;
  ASSERT_EQ(p.thrusters[7].name, "d1");
  const InvSimResult r = run_inverse_simulation(p, d1);
  print("d1 lost", r);
  const double ratio = r.pulses[0].on_time_s[0] / nominal.pulses[0].on_time_s[0];
  EXPECT_GT(ratio, 1.4);
  EXPECT_LT(ratio, 2.5);
  EXPECT_TRUE(r.docked);
  EXPECT_TRUE(r.attitude_within_limits);
  EXPECT_GT(r.peak_attitude_rad.z(), 0.1 * kDegToRad);  // the Mz disturbance is felt
  EXPECT_EQ(nominal.peak_attitude_rad.z(), 0.0);        // and absent when healthy
}

// A run is a pure function of its inputs (bit-identical twice), and the history has one sample
// per IS step starting at t = 0.
TEST(InverseSimulation, DeterministicWithOneSamplePerStep) {
  const model::InvSimParams p = load_nominal();
  std::vector<InvSimSample> history;
  const InvSimResult a = run_inverse_simulation(p, {}, &history);
  const InvSimResult b = run_inverse_simulation(p, {});
  EXPECT_EQ(a.final_r_hill_m, b.final_r_hill_m);
  EXPECT_EQ(a.propellant_kg, b.propellant_kg);
  EXPECT_EQ(a.total_pulses, b.total_pulses);
  ASSERT_EQ(history.size(), 1300u);
  EXPECT_EQ(history.front().t_s, 0.0);
  EXPECT_EQ(history.front().r_hill_m, p.r0_hill_m);
  EXPECT_EQ(history.back().t_s, 1299.0);
  EXPECT_NEAR(a.k_p, a.total_pulses / 3000.0, 1e-15);
}

}  // namespace
}  // namespace chaser::invsim
