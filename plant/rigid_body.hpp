#pragma once
// Rigid-body attitude of the chaser: Euler's equations and quaternion kinematics.
//
//   omega' = I^-1 (C - omega x I omega)          Fonod 2015, eq. 13, with the full gyroscopic term
//   q'     = 1/2 q (x) (0, omega)                Hamilton product; q = q_inertial_from_body
//
// omega is the inertial angular velocity in body axes; C the total torque about the centre of mass
// (thrusters, disturbances, gravity gradient), body axes. The inertia is taken constant: propellant
// use changes it by a fraction of a percent over a rendezvous, far below its own uncertainty.
#include <Eigen/Core>

#include "core/types.hpp"

namespace chaser::plant {

// Truth state of the chaser: translation relative to the target (MSR LVLH), attitude, mass.
struct RigidState {
  Vec3 r_lvlh_m = Vec3::Zero();                    // [m] chaser CoM from target CoM, LVLH
  Vec3 v_lvlh_mps = Vec3::Zero();                  // [m/s] time derivative of r_lvlh_m in the rotating LVLH frame
  Quat q_inertial_from_body = Quat::Identity();    // unit
  Vec3 omega_body_radps = Vec3::Zero();            // [rad/s] inertial angular velocity, body axes
  double mass_kg = 0.0;                            // [kg] must be set (> 0) before propagating
};

// Both are defined here, inline: every Runge-Kutta stage of both plants calls them, and a call
// into another translation unit cost more than their dozen multiplications.

// Euler's equations (Fonod 2015, eq. 13). Returns omega' [rad/s^2], body axes.
inline Vec3 euler_angular_acceleration_body(const Mat3& inertia_kgm2, const Mat3& inertia_inv,
                                            const Vec3& omega_body_radps, const Vec3& torque_body_Nm) {
  return inertia_inv * (torque_body_Nm - omega_body_radps.cross(inertia_kgm2 * omega_body_radps));
}

// Quaternion kinematics q' = 1/2 q (x) (0, omega), returned in Quat::coeffs() order (x, y, z, w).
// Valid for a non-unit q as well (it is then the same linear map), which keeps a Runge-Kutta stage
// that leaves the unit sphere smooth; the norm of the exact solution is preserved.
inline Eigen::Vector4d quat_derivative(const Quat& q_inertial_from_body, const Vec3& omega_body_radps) {
  // q (x) (0, w) = (-q.vec . w, q.w w + q.vec x w)
  const Quat& q = q_inertial_from_body;
  const Vec3& w = omega_body_radps;
  const Vec3 dvec = 0.5 * (q.w() * w + q.vec().cross(w));
  return Eigen::Vector4d(dvec.x(), dvec.y(), dvec.z(), -0.5 * q.vec().dot(w));
}

// Invariants of torque-free motion, for tests and telemetry.
Vec3 angular_momentum_inertial(const Mat3& inertia_kgm2, const Quat& q_inertial_from_body,
                               const Vec3& omega_body_radps);                           // [N m s]
double rotational_energy(const Mat3& inertia_kgm2, const Vec3& omega_body_radps);      // [J]

}  // namespace chaser::plant
