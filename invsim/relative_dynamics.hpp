#pragma once
// Truth model of the forward simulation (Zhou 2018, eqs. 1, 10-11): nonlinear relative motion
// about a circular target orbit and the chaser's rigid-body attitude, driven by a body-fixed force
// and torque held constant over a piece of time.
//
// The interface is in the paper's manual-RVD Hill frame (x along-track, y opposite the orbit
// normal, z towards the planet); the equations are the plant's (plant/propagator.hpp), integrated
// in the MSR LVLH frame and mapped at this boundary by the constant rotation of core/hill_frames.hpp:
//   translation: eq. 1 with omega_tar' = 0 is Fonod 2015, eq. 8 seen in the other frame; the plant
//     evaluates it in Battin's cancellation-free form (plant/relative_orbit.hpp). Eq. 1's literal
//     z line, -mu / R^2 + mu (R - z) / r^3, subtracts two ~8.7 m/s^2 terms to get ~1e-5 m/s^2 and
//     so carries an error of about one ulp of mu / R^2 (~2e-15 m/s^2): the form this file used to
//     integrate;
//   attitude: I omega' + omega x (I omega) = M (eq. 10; omega inertial, body axes) and
//     q_inertial_from_body' = 1/2 q (x) (0, omega) (plant/rigid_body.hpp). The Hill attitude is
//     q_hill_from_body = q_hill_from_lvlh q_lvlh_from_inertial(t) q_inertial_from_body, which is
//     eq. 11's kinematics (body rate relative to Hill: omega - C_bh omega_hill, omega_hill =
//     (0, -n, 0)) without integrating the frame's turn.
// Thrust acceleration C_hb(q) F / m with the attitude at each Runge-Kutta stage (eq. 8, exact
// rotation); mass constant (the paper's truth has no mass flow); no gravity-gradient torque (the
// paper has none). The run keeps pieces at most one attitude period long and splits them at every
// valve edge, so the held force is exact on each piece; the plant's RK4 integrates each piece in
// ceil(dt / max_substep) substeps (one per piece in the run, below).
#include "core/types.hpp"
#include "plant/propagator.hpp"

namespace chaser::invsim {

struct RvdConstants {
  plant::DynamicsParams dynamics;  // mu, orbit radius R, mean motion n, inertia; no gravity gradient
  double mass_kg;                  // [kg]
};

struct RvdState {
  Vec3 r_hill_m = Vec3::Zero();        // [m] chaser from target
  Vec3 v_hill_mps = Vec3::Zero();      // [m/s] in the rotating Hill frame
  Quat q_hill_from_body = Quat::Identity();
  Vec3 omega_body_radps = Vec3::Zero();  // [rad/s] inertial rate, body axes
};

// max_substep_s [s]: the plant's RK4 substep bound. The run passes its attitude period dT, its
// longest piece, so that every piece is one RK4 step as in the plant's quiet control periods: the
// step's local error ~(|omega| dT)^5 / 120 is ~4e-18 rad at the phase-plane's rate border
// (0.2 deg/s, dT = 0.25 s).
RvdConstants make_rvd_constants(double mu_m3ps2, double radius_m, double mass_kg,
                                const Mat3& inertia_kgm2,
                                double max_substep_s = plant::kDefaultMaxSubstepS);

// Relative motion acceleration of eq. 1 without thrust, Hill axes [m/s^2]: the plant's
// cancellation-free form (plant/relative_orbit.hpp) mapped from LVLH.
Vec3 relative_gravity_accel(const RvdConstants& c, const Vec3& r_hill_m, const Vec3& v_hill_mps);

// Body rate relative to the Hill frame (the Euler-angle rates for small angles), eq. 11.
Vec3 relative_rate_body(const RvdConstants& c, const RvdState& s);

// Advances s by dt [s] under body force [N] and torque [N m] held constant: the plant's
// The state as the plant's, in LVLH, with the inertial frame at LVLH of this instant.
plant::RigidState plant_state(const RvdConstants& c, const RvdState& s);

// propagate_piece on the state mapped to LVLH. dt <= 0 is a no-op.
void propagate_piece(const RvdConstants& c, const Vec3& force_body_N, const Vec3& torque_body_Nm,
                     double dt_s, RvdState& s);

}  // namespace chaser::invsim
