#pragma once
// The impulse-deficit bank's parameters for the MSR chaser, for tests: branch A of
// msr_branch_a.hpp (T5..T8 mirror T1..T4: same torque, opposite force about the origin = CoM),
// inertia diag(2000, 2500, 3000) kg m^2, 2500 kg, T = 0.1 s; the rest at the header's defaults.
#include "flight/fdi/deficit_isolation.hpp"
#include "model/thruster_geometry.hpp"
#include "tests/support/msr_branch_a.hpp"

namespace chaser::testing {

// The bank watching the first `count` thrusters of `set` on MSR's chaser (the mass properties above).
inline flight::fdi::DeficitIsolationParams deficit_params_for(const model::ThrusterSetParams& set, int count) {
  const model::ConfigMatrix m = model::configuration_matrix(set, model::first_thrusters(count), Vec3::Zero());
  flight::fdi::DeficitIsolationParams p;
  p.inertia_kgm2 = Vec3(2000.0, 2500.0, 3000.0).asDiagonal();
  p.mass_kg = 2500.0;
  flight::fdi::set_deficit_columns(p, m.leftCols(count));
  p.period_s = 0.1;
  return p;
}

inline flight::fdi::DeficitIsolationParams msr_deficit_params() { return deficit_params_for(msr_branch_a_thrusters(), 8); }

}  // namespace chaser::testing
