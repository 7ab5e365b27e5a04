#pragma once
// Continuous linear models on which the delay-robust residual generator is designed
// (Fonod 2015, eq. 18: x' = A x + B u + E_f f, y = C x). Offline design: dynamic sizes.
#include <Eigen/Core>

#include "core/types.hpp"

namespace chaser::flight::fdi {

struct LinearModel {
  Eigen::MatrixXd A;  // [n_x x n_x] state matrix
  Eigen::MatrixXd B;  // [n_x x n_u] input matrix
  Eigen::MatrixXd C;  // [n_y x n_x] output matrix
};

// HCW position model in MSR LVLH (x radial out, y along-track, z orbit normal), Fonod 2015 eq. 12:
//   x'' = 3 n^2 x + 2 n y' + u_x / m,  y'' = -2 n x' + u_y / m,  z'' = -n^2 z + u_z / m.
// State [r_lvlh; v_lvlh] [m, m/s], input u = R M_F T_on, a force in LVLH [N], output r_lvlh [m].
LinearModel hcw_position_model(double mean_motion_radps, double mass_kg);

// Attitude model (Fonod 2015, eqs. 13-15): Euler's equations and the attitude kinematics linearised
// about a reference that turns at the constant body rate omega_ref (the paper: omega_ref = 0, which
// gives the double integrator). State [theta; delta_omega] [rad, rad/s] with theta the small
// rotation vector from the reference to the body, delta_omega = omega - omega_ref; input a body
// torque M_C T_on [N m]; output theta [rad]. Linearisation:
//   theta' = delta_omega - omega_ref x theta
//   I delta_omega' = (skew(I omega_ref) - skew(omega_ref) I) delta_omega + torque
// Gravity-gradient torque (order n^2) is left out, as in the paper.
LinearModel linear_attitude_model(const Mat3& inertia_kgm2,
                                  const Vec3& omega_ref_body_radps = Vec3::Zero());

}  // namespace chaser::flight::fdi
