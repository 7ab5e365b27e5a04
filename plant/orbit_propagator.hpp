#pragma once
// Piecewise-exact propagation of a chaser and its target in a perturbed Earth orbit (the
// COMRADE platform), the counterpart of propagator.hpp's circular-orbit model. Same contract: the
// thruster model cuts a control period into pieces of constant input, and propagate_orbit_piece
// integrates one piece from edge to edge with classical RK4 in equal substeps.
//
// State equations, integrated together:
//   target:   r_t' = v_t,   v_t' = a_t(r_t, v_t)                           ECI (orbit_perturbations.hpp)
//   chaser:   dr' = dv,     dv' = a_rel(r_t, v_t, dr, dv) + F_eci / m      ECI, relative to the target
//             q' = 1/2 q (x) (0, omega),  omega' = I^-1 (C - omega x I omega),  m' = -mass_flow
//             C = thrusters + disturbances + gravity gradient + magnetic
//             with slosh (model::ChaserSloshParams): omega' and each tank's s'' from the coupled equations
//             of model/slosh.hpp instead, s' = s_dot; dv' unchanged (the whole chaser's CoM); a pendulum
//             is read on its sphere in each derivative and put back on it after each piece
//   target attitude: the same rigid-body equations with the target's inertia, gravity gradient and
//             magnetic torque (torque-free when both are off): it tumbles, it does not turn at a
//             constant rate.
//
// Attitudes are kept in the run's inertial frame, the target's LVLH at t = 0 (the frame every other
// part of Chaser calls "inertial"; run_from_eci below), so the flight software, sensors and telemetry
// are those of the circular-orbit runs. Translation is in ECI, where the Earth's field is static.
#include "core/types.hpp"
#include "model/chaser_slosh.hpp"
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

// [s] RK3 for pieces up to 25 ms: for the slosh's 0.12 rad/s (the fastest mode COMRADE flies),
// (w 0.025)^4 / 24 = 3.4e-12 against RK4's (w 0.1)^5 / 120 = 2.1e-12 over the period.
inline constexpr double kThirdOrderMaxPieceS = 0.025;

// [s] The slowly varying environment (drag, solar pressure, the third bodies, the Earth's field and
// its turn) is sampled once per this much run time, a whole number of control periods, at the
// window's midpoint (slow_environment below): each turns with the orbit, (3 n dt)^2 / 8 ~ 1e-6 of
// itself over 1 s in LEO, and the shadow's edge is then resolved to 1 s where the cylindrical
// shadow itself is ~4 s early or late (docs/dynamics.md, "Held environment").
inline constexpr double kEnvironmentStepS = 1.0;

struct OrbitDynamicsParams {
  OrbitPerturbationParams perturbations;
  double epoch_jd_tt = 2451545.0;         // [d] Julian date (TT) of t = 0
  Mat3 run_from_eci = Mat3::Identity();   // the run's inertial axes (target LVLH at t = 0) from ECI
  BodyTorqueParams chaser, target;
  model::ChaserSloshParams slosh;
  double max_substep_s = kDefaultMaxSubstepS;  // [s] RK4 substep bound (> 0)
  // Pieces up to this long take one step of Kutta's third-order method (3 stages) instead of RK4:
  // the short pieces of a thrusting period (valve delay and the pulses themselves, 2.5-25 ms),
  // where its local error, (w dt)^4 / 24 for the fastest mode w, is no larger than RK4's over a
  // whole 0.1 s period, (w T)^5 / 120 (docs/dynamics.md). 0: RK4 for every piece.
  double third_order_max_piece_s = kThirdOrderMaxPieceS;
  // Hold drag, solar pressure, the third bodies, the magnetic field and the environment's torques
  // (slow_environment and period_environment below); false evaluates them at every RK4 stage, the
  // reference the test orbit_propagator_test.cpp compares against.
  bool hold_slow_environment = true;
  // [s] the slow terms' window (kEnvironmentStepS), rounded to whole control periods (at least one):
  // environment_periods.
  double environment_step_s = kEnvironmentStepS;
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
  std::array<model::SloshState, model::kMaxSloshTanks> slosh{};  // the chaser's slosh masses, [0, slosh.count) used
};

// The environment of one control period. With hold_slow_environment, the slowly varying
// accelerations, the Earth's field and the ephemeris (the Sun, the Moon, the Earth's turn) are
// held over a window of whole periods (environment_step_s, 1 s), evaluated at the window's
// midpoint (SlowEnvironment; the state there predicted from the window's start), where a held
// value is right to second order: each turns with the orbit (n dt = 1e-3 rad in 1 s in LEO; the
// field at 3 n), so the held value misses the stages' by ~(3 n dt)^2 / 8 ~ 1e-6 of itself on
// average. The gravity-gradient and magnetic torques are held over each period, in body axes, at
// each body's attitude predicted to the period's midpoint: they turn with the body (2.5 deg/s:
// 4.4e-3 rad a period for the tumbling target), so they miss the stages' by ~(w dt)^2 / 8 ~ 2e-6
// of themselves, an impulse error that cancels over each turn. What must follow every stage
// (gravity and J2 at the target and their difference at dr) still does. The gain: 4 stages per
// piece, a few pieces per period with 24 thrusters, each with two drags (an exp), two pressures
// and shadows, four third-body terms, two field evaluations and four torques, against once per
// window for the forces and once per period for the torques.
struct SlowEnvironment {
  Ephemeris eph;                           // at the window's midpoint
  OrbitAccelerations slow;                 // slow_accelerations there
  Vec3 field_target_eci_T = Vec3::Zero();  // [T] the Earth's field at the target
  Vec3 field_chaser_eci_T = Vec3::Zero();  // [T] and at the chaser
};
// The slow terms lead_s [s] after `orbit`'s time (the window's midpoint; eph_mid is for then): the
// bodies' positions predicted by r + v t + a t^2 / 2 (central gravity and J2; the rest is 1e-5 of
// it), their velocities by v + a t.
SlowEnvironment slow_environment(const OrbitDynamicsParams& p, const Ephemeris& eph_mid, const OrbitState& orbit,
                                 double lead_s);
// The control periods in one window of the slow terms: environment_step_s / period_s rounded, >= 1.
std::int64_t environment_periods(const OrbitDynamicsParams& p, double period_s);

struct PeriodEnvironment {
  Ephemeris eph;
  bool held = false;                    // false: the terms below are evaluated at every stage
  OrbitAccelerations slow;              // slow_accelerations at the window's midpoint
  Vec3 torque_target_body_Nm = Vec3::Zero();  // [N m] gravity gradient + magnetic, target axes
  Vec3 torque_chaser_body_Nm = Vec3::Zero();  // [N m] the same on the chaser (about its CoM at rest)
};
// One period's environment from the window's slow terms: the torques at the period's midpoint.
PeriodEnvironment period_environment(const OrbitDynamicsParams& p, const SlowEnvironment& slow,
                                     const OrbitState& orbit, const RigidState& chaser, double period_s);
// The same with a window of one period (eph_mid at its midpoint); without hold_slow_environment
// only the ephemeris, for the stages to evaluate the rest.
PeriodEnvironment period_environment(const OrbitDynamicsParams& p, const Ephemeris& eph_mid, const OrbitState& orbit,
                                     const RigidState& chaser, double period_s);

// Advances (orbit, chaser) by dt_s [s] under constant u (PieceInput's LVLH force is rotated with
// the LVLH frame at the piece start), in the environment env (the time enters only through it: the
// Earth's field is static in ECI). Allocation-free.
void propagate_orbit_piece(const OrbitDynamicsParams& p, const PeriodEnvironment& env, OrbitState& orbit,
                           RigidState& chaser, double dt_s, const PieceInput& u);

// The target's LVLH frame now, and the chaser's relative state in it written into chaser.r_lvlh_m
// and chaser.v_lvlh_mps (what the sensors and the mission monitor read).
void update_lvlh_view(const OrbitDynamicsParams& p, const PeriodEnvironment& env, const OrbitState& orbit,
                      RigidState& chaser);

// The rotation from the target's current LVLH axes to the run's inertial axes.
Quat q_inertial_from_lvlh(const OrbitDynamicsParams& p, const OrbitState& orbit);

}  // namespace chaser::plant
