#pragma once
// The MSR branch A thruster layout of scenarios/msr_terminal.yaml (Fonod 2015 section II.B, Fig. 3),
// built from its numbers for tests and benchmarks that must not read files: T1..T4, and their
// partners T5..T8 mirrored through the reference point (same torque, opposite force). 22 N each.
#include "model/thrusters.hpp"

namespace chaser::testing {

inline model::ThrusterSetParams msr_branch_a_thrusters() {
  const Vec3 positions_m[4] = {{1.0, 0.8, 0.8}, {-1.0, 0.8, -0.8}, {-1.0, 0.8, 0.8}, {-1.0, -0.8, 0.8}};
  const Vec3 directions[4] = {{0.36, 0.36, -1.0}, {0.36, 1.0, 0.36}, {-1.0, 0.36, -0.36}, {0.36, -1.0, -0.36}};
  model::ThrusterSetParams set;
  set.count = 8;
  for (int i = 0; i < 4; ++i) {
    const Vec3 dir = directions[i].normalized();
    set.thrusters[i] = {positions_m[i], dir, 22.0};
    set.thrusters[i + 4] = {-positions_m[i], -dir, 22.0};
  }
  return set;
}

}  // namespace chaser::testing
