#pragma once
// Linear design models shared by navigation, control and fault diagnosis (continuous and
// zero-order-hold discrete).
//
// HCW (Clohessy-Wiltshire) relative motion in the MSR LVLH frame, x radial out, y along-track,
// z orbit normal (Fonod 2015, section III.A, linearised about the target's circular orbit):
//   x'' = 3 n^2 x + 2 n y' + a_x,   y'' = -2 n x' + a_y,   z'' = -n^2 z + a_z.
// Rigid-body attitude linearised about a reference (small error): theta' = delta_omega,
// I delta_omega' = C, i.e. a double integrator per axis driven by torque through I^-1.
#include "core/types.hpp"

namespace chaser {

using Mat63 = Eigen::Matrix<double, 6, 3>;
using Mat36 = Eigen::Matrix<double, 3, 6>;

struct DiscreteLinear6 {
  Mat6 Ad;   // transition over one control period
  Mat63 Bd;  // response to an input held over the period
};

// Continuous HCW: state [r_lvlh; v_lvlh], input acceleration [m/s^2].
Mat6 hcw_state_matrix(double mean_motion_radps);
Mat63 hcw_input_matrix();

// The HCW acceleration (gravity gradient plus frame terms) at a state: rows 4-6 of A [r; v].
Vec3 hcw_acceleration(double mean_motion_radps, const Vec3& r_lvlh_m, const Vec3& v_lvlh_mps);

// HCW discretised with a held acceleration input.
DiscreteLinear6 discrete_hcw(double mean_motion_radps, double period_s);

// Linearised attitude: state [theta_body; delta_omega_body], input torque [N m].
DiscreteLinear6 discrete_attitude(const Mat3& inertia_kgm2, double period_s);

}  // namespace chaser
