// ASSIST's berthing flown whole (scenarios/comrade_berth.yaml, docs/servicing.md "ASSIST's
// berthing"): the probe into the drogue, the latches, the retraction, the pins.
//  - Nominal (arm camera 1 mm noise, 3 mm of clearance in the drogue's throat): the tip reaches the
//    socket without touching the walls, the latches close within their 5 mm, inside the pins'
//    envelope, and the hard dock comes retraction_duration_s later; every phase met.
//  - The cone's job: a 20 mm calibration error of the arm camera aims the tip at the wall; the cone
//    and the insertion's overtravel put it in the socket with a contact force of tens of newtons
//    (measured 33 N), inside Chaser's 50 N bound. 40 mm is beyond what the tool's stiffness can press
//    through: no latch, the berthing not met (so the check above can fail).
//  - The retraction's forces are internal: over it (thrusters inhibited, the arm holding its shape)
//    the scene's linear momentum changes by the environment's impulse alone (the disturbance noise
//    and the tides over 20 s: measured 0.001-0.002 N s, asserted under 0.01), while half way the
//    target alone has received 6.5 N s from the mechanism (asserted over 5); and the hold ends within
//    1 mm and 1 mrad of the mated pose (measured 0.02 mm, 0.007 mrad: the soft hold's lag).
#include <cmath>

#include <gtest/gtest.h>

#include "flight/flight_software.hpp"
#include "io/scenario_loader.hpp"
#include "plant/arm_joints.hpp"
#include "plant/multibody_motion.hpp"
#include "sim/run.hpp"
#include "sim/run_phases.hpp"
#include "sim/simulation.hpp"

namespace chaser::sim {
namespace {

constexpr const char* kBerth = "scenarios/comrade_berth.yaml";

model::Scenario berth(std::vector<std::string> overrides = {}) {
  const io::LoadResult loaded = io::load_scenario_file(kBerth, overrides);
  EXPECT_TRUE(loaded.scenario) << io::format_errors(loaded.errors);
  return *loaded.scenario;
}

const PhaseVerdict* verdict(const std::vector<PhaseVerdict>& verdicts, const char* phase) {
  for (const PhaseVerdict& v : verdicts)
    if (v.phase == phase) return &v;
  return nullptr;
}

TEST(Berthing, TheProbeDocksWithTheCompliantLaw) {
  const model::Scenario s = berth();
  const RunResult r = run_scenario(s);
  const BerthResult& b = r.reach.berthing;
  ASSERT_TRUE(b.flown);
  const double insertion_start_s = s.capture->approach_start_s();
  EXPECT_GT(b.soft_dock_s, insertion_start_s);
  EXPECT_LT(b.soft_dock_s, insertion_start_s + s.capture->approach_duration_s);
  EXPECT_LE(b.latch_offset_m.norm(), s.capture->berthing->latch_radius_m);
  EXPECT_LT(b.latch_attitude_deg, s.capture->berthing->pin_attitude_tol_deg);
  EXPECT_FALSE(b.pins_jammed);
  // The retraction begins at the end of the joint step after the latch's and the pins engage at the
  // end of the step its duration ends in: two 1 ms joint steps at most.
  EXPECT_NEAR(b.hard_dock_s, b.soft_dock_s + s.capture->berthing->retraction_duration_s, 2e-3);
  // No wall touched: the camera's 1 mm noise is inside the throat's 3 mm clearance (measured 0 N).
  EXPECT_LT(b.peak_contact_N, 1.0);
  EXPECT_TRUE(berth_meets_requirements(b));
  EXPECT_STREQ(r.reach.grasp.outcome, "captured");
  EXPECT_GT(r.reach.rigidise.brakes_s, b.hard_dock_s);  // the brakes wait for the pins
  const std::vector<PhaseVerdict> verdicts = phase_verdicts(s, run_phases(s), r);
  ASSERT_NE(verdict(verdicts, "capture"), nullptr);
  EXPECT_TRUE(verdict(verdicts, "capture")->met());
  EXPECT_TRUE(mission_met(verdicts));
}

TEST(Berthing, TheConeCentresATipTheCameraMisplaces) {
  const RunResult off = run_scenario(berth({"sensors.arm_camera.position_bias_m=[0, 0.02, 0]"}));
  EXPECT_TRUE(std::isfinite(off.reach.berthing.hard_dock_s));
  // The wall was met (measured 33 N; the nominal run's is 0), and within the bound.
  EXPECT_GT(off.reach.berthing.peak_contact_N, 5.0);
  EXPECT_LE(off.reach.berthing.peak_contact_N, 50.0);
  EXPECT_TRUE(berth_meets_requirements(off.reach.berthing));

  const RunResult far = run_scenario(berth({"sensors.arm_camera.position_bias_m=[0, 0.04, 0]", "duration_s=360"}));
  EXPECT_FALSE(std::isfinite(far.reach.berthing.soft_dock_s));
  EXPECT_STREQ(far.reach.grasp.outcome, "abandoned");
  EXPECT_FALSE(berth_meets_requirements(far.reach.berthing));
}

TEST(Berthing, TheRetractionsForcesAreInternal) {
  const model::Scenario s = berth();
  const flight::FlightParams flight = flight::make_flight_params(s);
  Simulation sim(s, flight, RunOptions{});
  const auto berth_state = [&] { return *plant::berth_truth(sim.plant()); };
  const auto momentum = [&] {
    plant::multibody::MujocoModel copy = std::get<plant::MultibodyMotionState>(sim.plant().state.motion).world;
    return copy.momentum();
  };
  const auto target_momentum = [&] {
    const auto& world = std::get<plant::MultibodyMotionState>(sim.plant().state.motion).world;
    const auto& p = std::get<plant::MultibodyMotionParams>(sim.plant().params.motion);
    return Vec3(s.target.body->mass_kg * Vec3(world.data().qvel + p.index.target_dof));
  };
  while (!sim.done() && !(plant::arm_awake(sim.plant()) && berth_state().retract_from_s >= 0.0)) sim.step();
  ASSERT_FALSE(sim.done());
  const double retract_from_s = berth_state().retract_from_s;
  const plant::multibody::Momentum before = momentum();
  const Vec3 target_before = target_momentum();
  // Half way, the target moves fastest towards the chaser: the impulse the mechanism gave it.
  while (!sim.done() && sim.period() * s.control_period_s < retract_from_s + 0.5 * s.capture->berthing->retraction_duration_s)
    sim.step();
  EXPECT_GT((target_momentum() - target_before).norm(), 5.0);
  EXPECT_LT((momentum().linear_kgmps - before.linear_kgmps).norm(), 0.01);
  while (!sim.done() && !berth_state().hard_docked) sim.step();
  ASSERT_TRUE(berth_state().hard_docked);
  EXPECT_LT((momentum().linear_kgmps - before.linear_kgmps).norm(), 0.01);
  EXPECT_LT(berth_state().mate_offset_m, 1e-3);
  EXPECT_LT(berth_state().mate_attitude_rad, 1e-3);
}

}  // namespace
}  // namespace chaser::sim
