#pragma once
// The parallel-axis term: the inertia [kg m^2] of a point mass about a point d_m away from it
// (Steiner's theorem: m (|d|^2 I - d d^T)), added to a body's inertia about its CoM to move it.
#include "core/types.hpp"

namespace chaser {

inline Mat3 point_inertia(double mass_kg, const Vec3& d_m) {
  return mass_kg * (d_m.squaredNorm() * Mat3::Identity() - d_m * d_m.transpose());
}

}  // namespace chaser
