#pragma once
// A 24-thruster set for the deficit bank's and detector's tests (the size of COMRADE's set): at
// each corner of a 2 x 1.6 x 1.6 m box, three 22 N thrusters pushing inward along the body axes;
// lane 3 corner + axis. As in MSR's branch (and COMRADE's layout), thrusters mirrored through the
// centre are partners: same torque, opposite force (box_24_partner), told apart by the position
// rows only. MSR's chaser otherwise
// (tests/support/deficit_msr.hpp): inertia diag(2000, 2500, 3000) kg m^2, 2500 kg, T = 0.1 s.
#include "flight/fdi/deficit_isolation.hpp"
#include "model/thruster_geometry.hpp"
#include "tests/support/deficit_msr.hpp"

namespace chaser::testing {

inline model::ThrusterSetParams box_24_thrusters() {
  model::ThrusterSetParams set;
  set.count = 24;
  int k = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 c((corner & 1) ? 1.0 : -1.0, (corner & 2) ? 0.8 : -0.8, (corner & 4) ? 0.8 : -0.8);
    for (int axis = 0; axis < 3; ++axis) {
      Vec3 dir = Vec3::Zero();
      dir(axis) = c(axis) > 0.0 ? -1.0 : 1.0;
      set.thrusters[static_cast<std::size_t>(k++)] = {c, dir, 22.0};
    }
  }
  return set;
}

// The lane with the same torque and the opposite force: the thruster of the opposite corner, same axis.
inline int box_24_partner(int lane) { return (7 - lane / 3) * 3 + lane % 3; }

inline flight::fdi::DeficitIsolationParams box_24_deficit_params() { return deficit_params_for(box_24_thrusters(), 24); }

}  // namespace chaser::testing
