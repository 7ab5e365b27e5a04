#pragma once
// Gravity-gradient torque of the central body on the chaser (a disturbance named in Fonod 2015,
// sec. II, part of C_dis in eq. 13):
//   C_gg = 3 mu / R^3 (r_hat x I r_hat) = 3 mu / R^5 (r x I r)
// r: the chaser's centre of mass from the planet centre, body axes; R = |r|; I about the centre of
// mass. It vanishes when r lies along a principal axis of I, and it is independent of the sign of r.
//
// The gain 3 mu / R^5 is a separate function because R^2 does not depend on the frame: the
// propagator forms it from LVLH components, so its sqrt and division run alongside the attitude
// rotation of r instead of after it (10% of a propagation substep).
#include <cmath>

#include "core/types.hpp"

namespace chaser::plant {

// Inline: every Runge-Kutta stage of both plants calls them.

// 3 mu / R^5 [1/(s^2 m^2)] from mu_m3ps2 [m^3/s^2] and R^2 = r_squared_m2 [m^2].
inline double gravity_gradient_gain(double mu_m3ps2, double r_squared_m2) {
  return 3.0 * mu_m3ps2 / (r_squared_m2 * r_squared_m2 * std::sqrt(r_squared_m2));
}

// C_gg = gain (r x I r) [N m], body axes; r_body_m [m] from the planet centre, body axes.
inline Vec3 gravity_gradient_torque_body(double gain, const Vec3& r_body_m, const Mat3& inertia_kgm2) {
  return gain * r_body_m.cross(inertia_kgm2 * r_body_m);
}

}  // namespace chaser::plant
