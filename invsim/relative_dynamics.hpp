#pragma once
// Truth model of the forward simulation (Zhou 2018, eqs. 1, 10-11): nonlinear relative motion
// about a circular target orbit in the manual-RVD Hill frame, and the chaser's rigid-body attitude,
// driven by a body-fixed force and torque held constant over a piece of time.
//
//   x'' =  2 n z' + n^2 x - mu x / r^3                                  + a_x
//   y'' =                 - mu y / r^3                                  + a_y
//   z'' = -2 n x' + n^2 z - mu / R^2 + mu (R - z) / r^3                 + a_z
// with r = |(x, y, R - z)| (eq. 1 with omega_tar' = 0), a = C_hb(q) F / m (eq. 8, exact rotation).
// Attitude: q_hill_from_body with the body rate relative to the Hill frame,
//   q' = q (x) [0, omega - C_bh omega_hill],  omega_hill = (0, -n, 0) in Hill axes (eq. 11),
//   I omega' + omega x (I omega) = M  (eq. 10; omega inertial, body axes).
// A piece is integrated by one classic RK4 step; the run keeps pieces at most one attitude period
// long and splits them at every valve edge, so the held force is exact on each piece.
#include "core/types.hpp"

namespace chaser::invsim {

struct RvdConstants {
  double mu_m3ps2;          // [m^3/s^2]
  double radius_m;          // [m] target orbit radius R
  double mean_motion_radps; // [rad/s] n = sqrt(mu / R^3)
  double mass_kg;           // [kg]
  Mat3 inertia_kgm2;        // [kg m^2]
  Mat3 inertia_inv;         // [1/(kg m^2)]
};

struct RvdState {
  Vec3 r_hill_m = Vec3::Zero();        // [m] chaser from target
  Vec3 v_hill_mps = Vec3::Zero();      // [m/s] in the rotating Hill frame
  Quat q_hill_from_body = Quat::Identity();
  Vec3 omega_body_radps = Vec3::Zero();  // [rad/s] inertial rate, body axes
};

RvdConstants make_rvd_constants(double mu_m3ps2, double radius_m, double mass_kg,
                                const Mat3& inertia_kgm2);

// Relative motion acceleration of eq. 1 without thrust.
Vec3 relative_gravity_accel(const RvdConstants& c, const Vec3& r_hill_m, const Vec3& v_hill_mps);

// Body rate relative to the Hill frame (the Euler-angle rates for small angles).
Vec3 relative_rate_body(const RvdConstants& c, const RvdState& s);

// Advances s by dt [s] under body force [N] and torque [N m] held constant (one RK4 step).
void propagate_piece(const RvdConstants& c, const Vec3& force_body_N, const Vec3& torque_body_Nm,
                     double dt_s, RvdState& s);

}  // namespace chaser::invsim
