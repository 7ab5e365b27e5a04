// A capture's state forked (sim::Simulation's fork) and started anew with given joint rates
// (plant::set_closed_chain_joint_rates), as --preset comrade-rigidise flies COMRADE Table 7's starts:
// the fork flies on as the original does, bit for bit; the new start keeps the weld (the gripper
// moves with the fixture), keeps the scene's momentum (MuJoCo's own, by mj_subtreeVel) and sets the
// joints' rates exactly.
#include <cmath>
#include <memory>
#include <numbers>

#include <gtest/gtest.h>

#include "flight/flight_software.hpp"
#include "io/scenario_loader.hpp"
#include <mujoco/mujoco.h>

#include "plant/arm_joints.hpp"
#include "plant/multibody_motion.hpp"
#include "sim/simulation.hpp"

namespace chaser::sim {
namespace {

// comrade_capture flown once to the rigidisation's first period (the capture confirmed), brakes
// held off; shared by the tests below.
struct Captured {
  model::Scenario scenario;
  flight::FlightParams flight;
  std::unique_ptr<Simulation> base;
};

const Captured& captured() {
  static const Captured c = [] {
    Captured out;
    const io::LoadResult loaded = io::load_scenario_file(
        "scenarios/comrade_capture.yaml", {"capture.rigidise.brake_dwell_s=1000", "duration_s=3000"});
    EXPECT_TRUE(loaded.scenario) << io::format_errors(loaded.errors);
    out.scenario = *loaded.scenario;
    out.scenario.capture->stabilise.reset();
    out.flight = flight::make_flight_params(out.scenario);
    out.base = std::make_unique<Simulation>(out.scenario, out.flight, RunOptions{});
    int rigidisation = -1;
    for (std::size_t i = 0; i < out.base->phases().phases.size(); ++i)
      if (out.base->phases().phases[i].name == "rigidisation") rigidisation = static_cast<int>(i);
    while (!out.base->done() && out.base->phase() != rigidisation) out.base->step();
    EXPECT_EQ(out.base->phase(), rigidisation);
    return out;
  }();
  return c;
}

const plant::MultibodyMotionState& multibody(const Simulation& s) {
  return std::get<plant::MultibodyMotionState>(s.plant().state.motion);
}

RunResult fly(Simulation& s) {
  while (!s.done()) s.step();
  return s.finish();
}

TEST(ClosedChainStart, AForkFliesOnAsTheOriginalDoes) {
  const Captured& c = captured();
  const std::int64_t periods = c.base->period() + 100;  // 10 s of the rigidisation
  Simulation a(*c.base, periods), b(*c.base, periods);
  const RunResult ra = fly(a), rb = fly(b);
  // A run never forked, flown from the start to the same period, ends in the same bits.
  Simulation whole(c.scenario, c.flight, RunOptions{});
  while (whole.period() < periods) whole.step();
  const RunResult rw = whole.finish();
  EXPECT_EQ(rw.propellant_used_kg, ra.propellant_used_kg);
  EXPECT_EQ(rw.reach.rigidise.final_angle_error_rad, ra.reach.rigidise.final_angle_error_rad);
  EXPECT_EQ(rw.reach.rigidise.final_rate_radps, ra.reach.rigidise.final_rate_radps);
  EXPECT_EQ(rw.reach.rigidise.peak_torque_Nm, ra.reach.rigidise.peak_torque_Nm);
  EXPECT_EQ(ra.periods, periods);
  EXPECT_EQ(ra.propellant_used_kg, rb.propellant_used_kg);
  EXPECT_EQ(ra.reach.rigidise.final_angle_error_rad, rb.reach.rigidise.final_angle_error_rad);
  EXPECT_EQ(ra.reach.rigidise.peak_torque_Nm, rb.reach.rigidise.peak_torque_Nm);
  EXPECT_TRUE(ra.reach.rigidise.flown);
  // The base itself is untouched by its forks: a third one from it is the same again.
  Simulation third(*c.base, periods);
  EXPECT_EQ(fly(third).reach.rigidise.final_rate_radps, ra.reach.rigidise.final_rate_radps);
  EXPECT_THROW(Simulation(*c.base, c.base->periods() + 1), std::invalid_argument);
}

TEST(ClosedChainStart, SetsTheJointRatesKeepsTheWeldAndTheMomentum) {
  const Captured& c = captured();
  Simulation s(*c.base, c.base->period() + 10);
  plant::multibody::MujocoModel before = multibody(s).world;  // a deep copy
  const plant::multibody::Momentum p0 = before.momentum();
  const std::array<double, model::kArmJoints> rates = {0.017, -0.017, 0.017, 0.017, -0.017, 0.017, -0.017};  // ~1 deg/s
  s.set_closed_chain_joint_rates(rates);
  const plant::PlantParams& params = s.plant().params;
  const auto& motion = std::get<plant::MultibodyMotionParams>(params.motion);
  const std::array<double, model::kArmJoints> set = plant::joint_rates_radps(motion, multibody(s));
  for (std::size_t j = 0; j < rates.size(); ++j) EXPECT_DOUBLE_EQ(set[j], rates[j]) << j;
  plant::multibody::MujocoModel after = multibody(s).world;
  const plant::multibody::Momentum p1 = after.momentum();
  // Linear ~ 9,500 kg at cm/s; angular ~ 1e5 kg m^2 at 0.044 rad/s: kept to rounding.
  EXPECT_LT((p1.linear_kgmps - p0.linear_kgmps).norm(), 1e-9 * std::max(1.0, p0.linear_kgmps.norm()));
  EXPECT_LT((p1.angular_kgm2ps - p0.angular_kgm2ps).norm(), 1e-9 * p0.angular_kgm2ps.norm());
  // The gripper moves with the target as one body: the same angular velocity, and its velocity
  // carried to the target's origin is the target's (MuJoCo's body velocities, mj_objectVelocity from
  // the spatial velocities of mj_comVel: another path than the Jacobians the start solved with).
  after.forward();
  const mjModel& m = after.model();
  const mjData& d = after.data();
  const int gripper = after.body("gripper"), target = after.body("target");
  double vg[6], vt[6];
  mj_objectVelocity(&m, &d, mjOBJ_BODY, gripper, vg, 0);
  mj_objectVelocity(&m, &d, mjOBJ_BODY, target, vt, 0);
  const Vec3 wg(vg[0], vg[1], vg[2]), wt(vt[0], vt[1], vt[2]);
  const Vec3 lever = Vec3(d.xipos + 3 * target) - Vec3(d.xipos + 3 * gripper);  // a body's velocity is at its CoM
  const Vec3 gripper_at_target = Vec3(vg[3], vg[4], vg[5]) + wg.cross(lever);
  EXPECT_LT((wg - wt).norm(), 1e-12) << wg.transpose() << " / " << wt.transpose();
  EXPECT_LT((gripper_at_target - Vec3(vt[3], vt[4], vt[5])).norm(), 1e-11);
  // And the chain flies from there: the rigidisation damps what was set (1 s here).
  const RunResult r = fly(s);
  EXPECT_TRUE(r.reach.rigidise.flown);
  for (std::size_t j = 0; j < rates.size(); ++j) EXPECT_LT(std::abs(r.reach.rigidise.final_rate_radps[j]), 0.017) << j;
}

}  // namespace
}  // namespace chaser::sim
