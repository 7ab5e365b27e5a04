#pragma once
// COMRADE's chaser as comrade_sync.yaml has it, for the rate model's and the observer bank's tests:
// 1,600 kg, two 150 kg tanks either side of the CoM below it, 24 thrusters (the tests' box layout).
#include "model/scenario.hpp"
#include "tests/support/deficit_24.hpp"

namespace chaser::testing {

inline model::Scenario two_tank_chaser(double mass_kg = 1600.0, const Vec3& inertia = Vec3(1500.0, 1700.0, 1300.0)) {
  model::Scenario s;
  s.chaser.mass_kg = mass_kg;
  s.chaser.inertia_kgm2 = inertia.asDiagonal();
  model::SloshParams slosh;
  slosh.model = model::SloshModel::pendulum;
  slosh.g_eff_mps2 = 0.005;
  for (const double x : {0.5, -0.5})
    slosh.tanks.push_back({.bottom_centre_body_m = Vec3(x, 0.0, -0.45), .axis_body = Vec3::UnitZ(), .radius_m = 0.45,
                           .height_m = 0.9, .liquid_mass_kg = 150.0, .damping_ratio = 0.005});
  s.chaser.slosh = slosh;
  s.thrusters = box_24_thrusters();
  return s;
}

}  // namespace chaser::testing
