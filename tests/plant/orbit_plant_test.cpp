#include "plant/orbit_plant.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "plant/plant.hpp"
#include "tests/plant/earth_orbit_scenario.hpp"

namespace chaser::plant {
namespace {

model::TargetParams spinning(model::SpinCase spin) {
  model::TargetParams t;
  t.body.emplace();
  t.body->spin_case = spin;
  t.body->spin_rate_radps = 2.5 * kDegToRad;
  return t;
}

// COMRADE 2018, sec. 7.1, in MSR LVLH (x zenith, z along h; the ESA H-bar is -z, R-bar -x): the
// spin axis where the paper puts it, the rate 2.5 deg/s about it, inertial. Exact up to rounding.
TEST(OrbitPlant, SpinCasesPutTheAxisWhereThePaperSays) {
  const double rate = 2.5 * kDegToRad;
  const Vec3 h_bar = -Vec3::UnitZ();
  const TargetSpin s1 = initial_target_spin(spinning(model::SpinCase::s1));
  EXPECT_LT((s1.q_inertial_from_target * Vec3::UnitY() - h_bar).norm(), 1e-15);  // +Y along +H-bar
  EXPECT_LT((s1.q_inertial_from_target * s1.omega_target_body_radps - rate * h_bar).norm(), 1e-17);

  const TargetSpin s2 = initial_target_spin(spinning(model::SpinCase::s2));
  const Vec3 axis_s2 = Vec3(0.0, 1.0, 1.0).normalized();  // 45 deg from +Y and +Z
  EXPECT_LT((s2.q_inertial_from_target * axis_s2 - h_bar).norm(), 1e-15);
  EXPECT_LT((s2.omega_target_body_radps - rate * axis_s2).norm(), 1e-17);

  const TargetSpin s3 = initial_target_spin(spinning(model::SpinCase::s3));
  const Vec3 axis_s3 = s3.q_inertial_from_target * Vec3::UnitZ();
  EXPECT_NEAR(std::acos(axis_s3.dot(h_bar)), 0.25 * kPi, 1e-12);  // 45 deg from the orbit normal
  EXPECT_NEAR(axis_s3.y(), 0.0, 1e-15);                          // in the normal / radial plane
  EXPECT_LT(axis_s3.x(), 0.0);                                   // towards R-bar
  EXPECT_LT((s3.omega_target_body_radps - rate * Vec3::UnitZ()).norm(), 1e-17);

  model::TargetParams given;
  given.q_inertial_from_target = Quat(Eigen::AngleAxisd(0.3, Vec3(1.0, 2.0, 3.0).normalized()));
  given.omega_inertial_radps = Vec3(0.01, -0.02, 0.03);
  const TargetSpin g = initial_target_spin(given);
  EXPECT_LT((g.q_inertial_from_target * g.omega_target_body_radps - given.omega_inertial_radps).norm(), 1e-17);
}

// The Earth-orbit plant starts where the scenario says: the target on its circular orbit, the
// chaser at the given LVLH position and rotating-frame velocity (read back through the ECI state).
TEST(OrbitPlant, InitialStateReadsBackInLvlh) {
  model::Scenario s = testing::leo_earth_orbit_scenario();
  s.target = spinning(model::SpinCase::s1);
  RigidState initial;
  initial.mass_kg = 1600.0;
  initial.r_lvlh_m = Vec3(3.0, -100.0, 2.0);
  initial.v_lvlh_mps = Vec3(0.01, 0.02, -0.03);
  const Plant plant = make_plant(s, initial, 1);
  ASSERT_TRUE(std::holds_alternative<EarthOrbitParams>(plant.params.motion));
  EXPECT_NEAR(std::get<EarthOrbitState>(plant.state.motion).orbit.r_t_eci_m.norm(), 6378137.0 + 765e3, 1e-6);
  EXPECT_LT((chaser_state(plant).r_lvlh_m - initial.r_lvlh_m).norm(), 1e-12);
  EXPECT_LT((chaser_state(plant).v_lvlh_mps - initial.v_lvlh_mps).norm(), 1e-15);
  // The run's inertial axes are the target's LVLH at t = 0.
  const Quat q0 = q_inertial_from_lvlh(plant, model::TargetOrbit(s.orbit), 0.0);
  EXPECT_LT(q0.angularDistance(Quat::Identity()), 1e-15);
}

// The plant's ephemeris (the Sun and the Moon interpolated between samples kEphemerisSampleS
// apart) against each model evaluated at the time, over two days at an awkward 7.3 s step: the
// chord's error (w dt)^2 / 8 of the radius, 1.2 m for the Moon, 2e-11 of 1 AU (3 m) for the Sun;
// bounds 3 m and 10 m. The Earth's turn is its model's, exactly. And the answer depends on the time
// alone: from fresh samples it is the same, bit for bit, as from a run's.
TEST(OrbitPlant, InterpolatedEphemerisFollowsTheModels) {
  OrbitPlantParams p;
  p.epoch_jd_tt = 2460400.5;
  EphemerisSamples samples;
  double moon_m = 0.0, sun_m = 0.0;
  for (double t = 0.0; t < 2.0 * 86400.0; t += 7.3) {
    const Ephemeris exact = ephemeris_at_run_time(p, t);
    const Ephemeris fast = ephemeris_at_run_time(p, t, samples);
    moon_m = std::max(moon_m, (fast.moon_eci_m - exact.moon_eci_m).norm());
    sun_m = std::max(sun_m, (fast.sun_eci_m - exact.sun_eci_m).norm());
    ASSERT_EQ(fast.ecef_from_eci, exact.ecef_from_eci);
    EphemerisSamples fresh;
    const Ephemeris again = ephemeris_at_run_time(p, t, fresh);
    ASSERT_EQ(again.moon_eci_m, fast.moon_eci_m);
    ASSERT_EQ(again.sun_eci_m, fast.sun_eci_m);
  }
  std::printf("largest interpolation error: Moon %.3f m, Sun %.3f m\n", moon_m, sun_m);
  EXPECT_LT(moon_m, 3.0);
  EXPECT_LT(sun_m, 10.0);
}

// The slosh masses taken out of the chaser (chaser_slosh) and put back at rest give the scenario's
// mass, centre of mass and inertia again, to rounding (1e-12 relative).
TEST(OrbitPlant, SloshMassesAndTheBodyMakeTheWholeChaser) {
  model::SpacecraftParams chaser;
  chaser.mass_kg = 1600.0;
  chaser.inertia_kgm2 << 1500.0, 12.0, -8.0, 12.0, 1700.0, 5.0, -8.0, 5.0, 1300.0;
  chaser.com_body_m = Vec3(0.02, -0.01, 0.05);
  chaser.slosh.emplace();
  chaser.slosh->tanks.resize(2);
  chaser.slosh->tanks[0].bottom_centre_body_m = Vec3(0.5, 0.1, -0.45);
  chaser.slosh->tanks[1].bottom_centre_body_m = Vec3(-0.5, 0.0, -0.40);
  chaser.slosh->tanks[1].axis_body = Vec3(0.0, 0.6, 0.8);
  chaser.slosh->tanks[1].liquid_mass_kg = 220.0;
  const model::ChaserSloshParams s = model::chaser_slosh(chaser);
  ASSERT_EQ(s.count, 2);
  const double body_kg = chaser.mass_kg - s.mass_kg;
  double mass_kg = body_kg;
  Vec3 moment_kgm = body_kg * s.body_com_body_m;
  for (int i = 0; i < s.count; ++i) {
    mass_kg += s.tanks[i].mass_kg;
    moment_kgm += s.tanks[i].mass_kg * s.tanks[i].anchor_body_m;
  }
  const Vec3 com_m = moment_kgm / mass_kg;
  const auto about_com = [&](double m, const Vec3& at) {
    const Vec3 d = at - com_m;
    return Mat3(m * (d.squaredNorm() * Mat3::Identity() - d * d.transpose()));
  };
  Mat3 inertia = s.body_inertia_kgm2 + about_com(body_kg, s.body_com_body_m);
  for (int i = 0; i < s.count; ++i) inertia += about_com(s.tanks[i].mass_kg, s.tanks[i].anchor_body_m);
  EXPECT_GT(s.mass_kg, 100.0);
  EXPECT_NEAR(mass_kg, chaser.mass_kg, 1e-12 * chaser.mass_kg);
  EXPECT_LT((com_m - chaser.com_body_m).norm(), 1e-12);
  EXPECT_LT((inertia - chaser.inertia_kgm2).cwiseAbs().maxCoeff(), 1e-12 * 1700.0);
}

}  // namespace
}  // namespace chaser::plant
