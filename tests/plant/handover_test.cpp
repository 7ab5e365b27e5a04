// The plant seam's hand-over: the bodies handed from one motion model to the other arrive where
// they left, to rounding, and what is the plant's own (thrusters, faults, sensors, streams,
// propellant) carries on.
#include "plant/handover.hpp"

#include <gtest/gtest.h>

#include "core/constants.hpp"
#include "plant/plant.hpp"
#include "tests/plant/earth_orbit_scenario.hpp"

namespace chaser::plant {
namespace {

// testing::tumbling_target_scenario: with orbit.earth the perturbed Earth-orbit plant, without it the circle.
model::Scenario earth_scenario() { return testing::tumbling_target_scenario(); }

model::Scenario circle_scenario() {
  model::Scenario s = earth_scenario();
  s.orbit.earth.reset();
  return s;
}

RigidState start() {
  return testing::chaser_start(1600.0);
}

// Flies n periods of a gentle command (T1 and T3 a tenth of each period).
void fly(Plant& plant, int n, TimeNs& t) {
  model::ThrusterCommand command;
  command.ton[0] = command.ton[2] = 0.1;
  for (int k = 0; k < n; ++k, t += plant.params.period_ns) {
    sense_plant(plant.params, plant.state, t, Quat::Identity());  // for its effect on the state only
    step_plant(plant.params, plant.state, command, t);
  }
}

void expect_same_bodies(const HandoverState& a, const HandoverState& b, double tol_m, double tol_rad) {
  EXPECT_LT((a.r_lvlh_m - b.r_lvlh_m).norm(), tol_m);
  EXPECT_LT((a.v_lvlh_mps - b.v_lvlh_mps).norm(), tol_m);
  EXPECT_LT(a.q_lvlh_from_body.angularDistance(b.q_lvlh_from_body), tol_rad);
  EXPECT_LT((a.omega_body_radps - b.omega_body_radps).norm(), 1e-18);
  EXPECT_EQ(a.mass_kg, b.mass_kg);
  EXPECT_LT(a.q_lvlh_from_target.angularDistance(b.q_lvlh_from_target), tol_rad);
  EXPECT_LT((a.omega_target_body_radps - b.omega_target_body_radps).norm(), 1e-17);
}

// At the start the circle hands over to the Earth-orbit plant: the result is the Earth plant built
// from the same start, to rounding (1e-12 m: the ECI round trip of 100 m at 7,100 km, a few ulps
// of the orbit radius relative to it; 1e-15 rad: two quaternion products).
TEST(Handover, CircleToEarthOrbitAtTheStartIsTheEarthPlantsOwnStart) {
  const model::Scenario circle_s = circle_scenario(), earth_s = earth_scenario();
  const model::TargetOrbit circle(circle_s.orbit);
  Plant handed = make_plant(circle_s, start(), 7);
  const Plant built = make_plant(earth_s, start(), 7);
  ASSERT_TRUE(std::holds_alternative<CircularOrbitParams>(handed.params.motion));
  const HandoverState h = handover_state(handed, circle, 0.0);
  ASSERT_FALSE(hand_over(handed, earth_s, h, circle));
  ASSERT_TRUE(std::holds_alternative<EarthOrbitParams>(handed.params.motion));
  expect_same_bodies(handover_state(handed, circle, 0.0), handover_state(built, circle, 0.0), 1e-12, 1e-15);
  expect_same_bodies(handover_state(handed, circle, 0.0), h, 1e-12, 1e-15);
  // Flown on, the two are one plant: the same bits.
  TimeNs t_handed = 0, t_built = 0;
  Plant built_flown = built;
  fly(handed, 100, t_handed);
  fly(built_flown, 100, t_built);
  const HandoverState a = handover_state(handed, circle, 10.0), b = handover_state(built_flown, circle, 10.0);
  expect_same_bodies(a, b, 1e-9, 1e-12);
  EXPECT_EQ(handed.state.propellant_used_kg, built_flown.state.propellant_used_kg);
}

// Mid-run the Earth-orbit plant hands over to the circle: the circle's bodies are the Earth
// plant's at that time (read back through the circle's own frame), the stuck-open fault injected
// before it still acts after it, and propellant, noise streams and sensors carry on.
TEST(Handover, EarthOrbitToCircleMidRunKeepsTheBodiesAndWhatThePlantOwns) {
  const model::Scenario circle_s = circle_scenario(), earth_s = earth_scenario();
  const model::TargetOrbit circle(circle_s.orbit);
  Plant plant = make_plant(earth_s, start(), 7);
  TimeNs t = 0;
  fly(plant, 300, t);  // 30 s: the fault at T3 began at 5 s
  const double t_s = to_seconds(t);
  const HandoverState before = handover_state(plant, circle, t_s);
  const double propellant_before = plant.state.propellant_used_kg;
  ASSERT_FALSE(hand_over(plant, circle_s, before, circle));
  ASSERT_TRUE(std::holds_alternative<CircularOrbitParams>(plant.params.motion));
  // 1e-15 rad: the frames multiplied out and back.
  expect_same_bodies(handover_state(plant, circle, t_s), before, 1e-15, 1e-15);
  EXPECT_EQ(plant.state.propellant_used_kg, propellant_before);
  ASSERT_EQ(plant.state.faults.size(), 1u);
  fly(plant, 10, t);
  // T3 stuck open: it burns the whole period whatever the command (T1 a tenth): its column is the
  // larger one in the last profile's realised on-times.
  EXPECT_GT(plant.state.last_profile.ton_realised[2], 0.9);
  EXPECT_GT(plant.state.propellant_used_kg, propellant_before);
}

// The Earth-orbit plant's target starts from orbit.earth's elements, so it takes over at t = 0
// only: later it says why instead of starting the target in the wrong place.
TEST(Handover, EarthOrbitTakesOverAtTheStartOnly) {
  const model::Scenario circle_s = circle_scenario(), earth_s = earth_scenario();
  const model::TargetOrbit circle(circle_s.orbit);
  Plant plant = make_plant(circle_s, start(), 7);
  TimeNs t = 0;
  fly(plant, 10, t);
  const auto refused = hand_over(plant, earth_s, handover_state(plant, circle, to_seconds(t)), circle);
  ASSERT_TRUE(refused);
  EXPECT_NE(refused->find("t = 0 only"), std::string::npos) << *refused;
  EXPECT_TRUE(std::holds_alternative<CircularOrbitParams>(plant.params.motion));
}

}  // namespace
}  // namespace chaser::plant
