#pragma once
// MSR-like design inputs for the FDI tests, built from numbers (scenarios/msr_terminal.yaml is not
// read here): Mars orbit at 500 km, T = 0.1 s, 2,500 kg, inertia diag(2000, 2500, 3000) kg m^2, and
// eight 22 N thrusters in four partner pairs: thruster i + 4 sits at -p_i firing along -d_i, so it
// has the same torque about the centre of mass and the opposite force (as in the MSR branch).
#include <array>
#include <cmath>

#include "model/scenario.hpp"
#include "flight/fdi/watched_set.hpp"
#include "model/thruster_geometry.hpp"

namespace chaser::flight::fdi::testing {

inline model::Scenario msr_test_scenario() {
  model::Scenario s;
  s.orbit.mu_m3ps2 = 4.282837e13;
  s.orbit.body_radius_m = 3389.5e3;
  s.orbit.altitude_m = 500e3;
  s.control_period_s = 0.1;
  s.chaser.mass_kg = 2500.0;
  s.chaser.inertia_kgm2 = Vec3(2000.0, 2500.0, 3000.0).asDiagonal();
  s.chaser.com_body_m = Vec3::Zero();
  const std::array<Vec3, 4> position_m = {Vec3(1.2, 0.8, 0.0), Vec3(-1.2, 0.8, 0.0),
                                          Vec3(0.0, -0.8, 1.0), Vec3(0.0, 0.8, -1.0)};
  const std::array<Vec3, 4> direction = {Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1),
                                         Vec3(-1, -1, 1)};
  s.thrusters.count = 16;
  s.thrusters.groups = {{"A", false}, {"B", true}};
  for (int branch = 0; branch < 2; ++branch)
    for (int i = 0; i < 4; ++i) {
      auto& a = s.thrusters.thrusters[static_cast<std::size_t>(8 * branch + i)];
      auto& b = s.thrusters.thrusters[static_cast<std::size_t>(8 * branch + i + 4)];
      a.group = b.group = branch;
      a.position_body_m = position_m[i];
      a.direction_body = direction[i].normalized();
      b.position_body_m = -position_m[i];
      b.direction_body = -direction[i].normalized();
    }
  return s;
}

inline SchemeConfig msr_test_configuration(const model::Scenario& s) {
  return model::configuration_matrix(s.thrusters, model::initial_active_set(s.thrusters), s.chaser.com_body_m)
      .leftCols<kSchemeThrusters>();
}

}  // namespace chaser::flight::fdi::testing
