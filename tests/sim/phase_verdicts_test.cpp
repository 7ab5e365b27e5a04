// The mission judged phase by phase (sim/phase_verdicts.hpp): each phase gets the requirements that
// apply to it, with the limits of the scenario and of COMRADE's tables, and fails on the figure that
// breaks one.
#include "sim/phase_verdicts.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "io/scenario_loader.hpp"
#include "sim/run.hpp"
#include "sim/run_phases.hpp"

namespace chaser::sim {
namespace {

model::Scenario capture_scenario() {
  const io::LoadResult loaded = io::load_scenario_file("scenarios/comrade_capture.yaml");
  EXPECT_TRUE(loaded.scenario) << io::format_errors(loaded.errors);
  return *loaded.scenario;
}

const Requirement* find(const PhaseVerdict& v, const std::string& name) {
  for (const Requirement& r : v.requirements)
    if (r.name == name) return &r;
  return nullptr;
}

TEST(PhaseVerdicts, APeriodKeepsTheLeastClearanceAndTheLastErrors) {
  PhaseFigures f;
  MonitorSample s{};
  s.r_lvlh_m = Vec3(1.0, 2.0, 2.0);
  s.r_ref_lvlh_m = Vec3::Zero();
  s.v_lvlh_mps = Vec3(0.0, 0.3, 0.4);
  s.v_ref_lvlh_mps = Vec3::Zero();
  s.q_inertial_from_body = Quat(Eigen::AngleAxisd(0.1, Vec3::UnitZ()));
  s.q_ref_inertial_from_body = Quat::Identity();
  s.omega_body_radps = Vec3(0.0, 0.0, 0.02);
  s.omega_ref_body_radps = Vec3::Zero();
  add_phase_period(f, s, 2.0);
  add_phase_period(f, s, std::nan(""));  // without a keep-out volume: no clearance
  add_phase_period(f, s, 3.0);
  EXPECT_EQ(f.periods, 3);
  EXPECT_EQ(f.min_clearance_m, 2.0);
  EXPECT_NEAR(f.final_position_error_m, 3.0, 1e-15);
  EXPECT_NEAR(f.final_speed_error_mps, 0.5, 1e-15);
  EXPECT_NEAR(f.final_attitude_error_rad, 0.1, 1e-12);
  EXPECT_NEAR(f.final_rate_error_radps, 0.02, 1e-15);
}

// A capture mission's phases, flown with figures that meet every requirement, then one broken in each.
TEST(PhaseVerdicts, EachPhaseIsJudgedOnItsOwnRequirements) {
  const model::Scenario s = capture_scenario();
  const PhaseSequenceParams params = run_phases(s);
  RunResult r;
  r.phase_figures.assign(params.phases.size(), PhaseFigures{});
  for (const char* name : {"transfer", "capture_point_hold", "reach", "capture", "rigidisation", "stabilisation"}) {
    const int i = phase_index(params, name);
    ASSERT_GE(i, 0) << name;
    r.phases.push_back({.name = name, .start_s = 10.0 * i, .end_s = 10.0 * i + 10.0, .end_reason = "time"});
    PhaseFigures& f = r.phase_figures[static_cast<std::size_t>(i)];
    f.periods = 100;
    f.min_clearance_m = 0.6;
  }
  r.reach.flown = true;
  r.reach.hold_periods = 200;  // the gripper's largest errors zero: inside Table 2
  r.reach.grasp.outcome = "captured";
  r.reach.grasp.judged = true;  // at the closure: the gripper on the fixture, the chaser's errors small
  r.reach.grasp.chaser_position_m = 0.01;
  r.reach.grasp.chaser_velocity_mps = 0.001;
  r.reach.grasp.chaser_attitude_deg = 0.1;
  r.reach.grasp.chaser_rate_deg_s = 0.01;
  r.reach.rigidise.brakes_s = 100.0;
  r.reach.peak_joint_torque_Nm.fill(20.0);
  r.reach.rigidise.peak_torque_Nm.fill(30.0);
  r.reach.rigidise.peak_brake_load_Nm.fill(90.0);
  r.reach.stabilise.flown = true;
  r.reach.stabilise.final_rate_target_degps = Vec3(0.001, 0.002, 0.0);
  std::vector<PhaseVerdict> v = phase_verdicts(s, params, r);
  ASSERT_EQ(v.size(), 6u);
  // The hold's Table 1, the stabilisation's Table 3 and the clearance met; the reach's gripper (its
  // figures zero: inside the envelope) and the grasp's closure too.
  for (const PhaseVerdict& p : v) EXPECT_TRUE(p.met()) << p.phase;
  EXPECT_TRUE(mission_met(v));
  const Requirement* clearance = find(v[0], "clearance_m");
  ASSERT_NE(clearance, nullptr);
  EXPECT_EQ(clearance->limit, 0.5);  // synchronised: Table 4's 0.5 m
  const Requirement* position = find(v[1], "position_error_m");
  ASSERT_NE(position, nullptr);
  EXPECT_EQ(position->limit, s.guidance.capture_position_tol_m);
  ASSERT_NE(find(v[1], "rate_error_deg_s"), nullptr);
  EXPECT_EQ(find(v[1], "rate_error_deg_s")->limit, kTable1RateDegps);
  EXPECT_EQ(find(v[4], "peak_joint_torque_Nm")->limit, s.chaser.arm->torque_repeated_peak_Nm);
  EXPECT_EQ(find(v[5], "final_rate_deg_s")->limit, model::kStabilisedRateDegps);

  // Broken one at a time: each fails its phase alone.
  r.phase_figures[static_cast<std::size_t>(phase_index(params, "transfer"))].min_clearance_m = 0.4;
  r.phase_figures[static_cast<std::size_t>(phase_index(params, "capture_point_hold"))].final_speed_error_mps = 0.02;
  r.reach.grasp.outcome = "abandoned";
  r.reach.rigidise.peak_torque_Nm[3] = 200.0;
  r.reach.stabilise.final_rate_target_degps = Vec3(0.6, 0.0, 0.0);
  v = phase_verdicts(s, params, r);
  EXPECT_FALSE(find(v[0], "clearance_m")->met);
  EXPECT_FALSE(find(v[1], "speed_error_mps")->met);
  EXPECT_TRUE(find(v[1], "position_error_m")->met);
  EXPECT_TRUE(v[2].met());
  EXPECT_FALSE(find(v[3], "captured")->met);
  EXPECT_FALSE(find(v[4], "peak_joint_torque_Nm")->met);
  EXPECT_TRUE(find(v[4], "brakes_engaged")->met);
  EXPECT_FALSE(find(v[5], "final_rate_deg_s")->met);
  EXPECT_FALSE(mission_met(v));
}

// Before the rotation's synchronisation the clearance asked is Table 4's 3 m.
TEST(PhaseVerdicts, TheUnsynchronisedPhasesAskForThreeMetres) {
  const model::Scenario s = capture_scenario();
  const PhaseSequenceParams params = run_phases(s);
  RunResult r;
  r.phase_figures.assign(params.phases.size(), PhaseFigures{});
  const int i = phase_index(params, "fly_around");
  r.phases.push_back({.name = "fly_around", .start_s = 1200.0, .end_s = 1800.0, .end_reason = "time"});
  r.phase_figures[static_cast<std::size_t>(i)] = {.periods = 6000, .min_clearance_m = 2.9};
  const std::vector<PhaseVerdict> v = phase_verdicts(s, params, r);
  ASSERT_EQ(v.size(), 1u);
  ASSERT_EQ(v[0].requirements.size(), 1u);
  EXPECT_EQ(v[0].requirements[0].limit, 3.0);
  EXPECT_FALSE(v[0].met());
}

}  // namespace
}  // namespace chaser::sim
