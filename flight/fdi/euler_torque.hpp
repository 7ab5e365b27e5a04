#pragma once
// The torque a rigid body's measured rates say acted on it over one period: Euler's equation,
// I domega/dt + omega x I omega, with the rate's change over the period T for its derivative and the
// gyroscopic term at the period's start (first order in T). The deficit schemes' torque rows and
// the rate check's residuals both read what the thrusters did not do from it.
#include "core/types.hpp"

namespace chaser::flight::fdi {

inline Vec3 euler_torque_Nm(const Mat3& inertia_kgm2, const Vec3& omega_radps, const Vec3& omega_next_radps,
                            double period_s) {
  const Vec3 d_omega_dt = (omega_next_radps - omega_radps) * (1.0 / period_s);  // one division, not three
  return inertia_kgm2 * d_omega_dt + omega_radps.cross(inertia_kgm2 * omega_radps);
}

}  // namespace chaser::flight::fdi
