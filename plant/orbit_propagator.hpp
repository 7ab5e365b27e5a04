#pragma once
// Piecewise-exact propagation of a chaser and its target in a perturbed Earth orbit (issue 17, the
// COMRADE platform), the counterpart of propagator.hpp's circular-orbit model. Same contract: the
// thruster model cuts a control period into pieces of constant input, and propagate_orbit_piece
// integrates one piece from edge to edge with classical RK4 in equal substeps.
//
// State equations, integrated together:
//   target:   r_t' = v_t,   v_t' = a_t(r_t, v_t)                           ECI (orbit_perturbations.hpp)
//   chaser:   dr' = dv,     dv' = a_rel(r_t, v_t, dr, dv) + F_eci / m      ECI, relative to the target
//             q' = 1/2 q (x) (0, omega),  omega' = I^-1 (C - omega x I omega),  m' = -mass_flow
//             C = thrusters + disturbances + gravity gradient + magnetic
//   target attitude: the same rigid-body equations with the target's inertia, gravity gradient and
//             magnetic torque (torque-free when both are off): it tumbles, it does not turn at a
//             constant rate.
//
// Attitudes are kept in the run's inertial frame, the target's LVLH at t = 0 (the frame every other
// part of Chaser calls "inertial"; run_from_eci below), so the flight software, sensors and telemetry
// are those of the circular-orbit runs. Translation is in ECI, where the Earth's field is static.
#include "core/types.hpp"
#include "plant/orbit_perturbations.hpp"
#include "plant/propagator.hpp"
#include "plant/rigid_body.hpp"

namespace chaser::plant {

struct BodyTorqueParams {
  Mat3 inertia_kgm2 = Mat3::Identity();  // [kg m^2] about the CoM, body axes
  Mat3 inertia_inv = Mat3::Identity();
  bool gravity_gradient = true;
  bool magnetic = true;                           // magnetic torque m x B of the residual dipole
  Vec3 residual_dipole_body_Am2 = Vec3::Zero();   // [A m^2] body axes
};

struct OrbitDynamicsParams {
  OrbitPerturbationParams perturbations;
  double epoch_jd_tt = 2451545.0;         // [d] Julian date (TT) of t = 0
  Mat3 run_from_eci = Mat3::Identity();   // the run's inertial axes (target LVLH at t = 0) from ECI
  BodyTorqueParams chaser, target;
  double max_substep_s = kDefaultMaxSubstepS;  // [s] RK4 substep bound (> 0)
};

// The translational and target parts of the truth; the chaser's attitude and mass stay in
// RigidState, whose r_lvlh_m / v_lvlh_mps are derived from this (update_lvlh_view).
struct OrbitState {
  Vec3 r_t_eci_m = Vec3::Zero();    // [m] target CoM from the Earth's centre
  Vec3 v_t_eci_mps = Vec3::Zero();  // [m/s]
  Vec3 dr_eci_m = Vec3::Zero();     // [m] chaser CoM minus target CoM
  Vec3 dv_eci_mps = Vec3::Zero();   // [m/s]
  Quat q_inertial_from_target = Quat::Identity();  // run inertial axes
  Vec3 omega_target_body_radps = Vec3::Zero();     // [rad/s] target's inertial rate, target axes
};

// Advances (orbit, chaser) by dt_s [s] under constant u (PieceInput's LVLH force is rotated with
// the LVLH frame at the piece start). eph: the Sun, the Moon and the Earth's turn for this piece
// (the time enters only through them: the Earth's field is static in ECI). Allocation-free.
void propagate_orbit_piece(const OrbitDynamicsParams& p, const Ephemeris& eph, OrbitState& orbit,
                           RigidState& chaser, double dt_s, const PieceInput& u);

// The target's LVLH frame now, and the chaser's relative state in it written into chaser.r_lvlh_m
// and chaser.v_lvlh_mps (what the sensors and the mission monitor read).
void update_lvlh_view(const OrbitDynamicsParams& p, const Ephemeris& eph, const OrbitState& orbit,
                      RigidState& chaser);

// The rotation from the target's current LVLH axes to the run's inertial axes.
Quat q_inertial_from_lvlh(const OrbitDynamicsParams& p, const OrbitState& orbit);

}  // namespace chaser::plant
