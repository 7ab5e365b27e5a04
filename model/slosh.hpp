#pragma once
// Propellant slosh: the first lateral mode of each tank as a spring-mass, coupled to the rigid body.
// Model knowledge, not the truth alone: the plant flies it (plant/orbit_propagator), and a model the
// flight software keeps of its own liquid is built on the same equations and nominal parameters.
//
// COMRADE 2018 models the chaser's two tanks with "3D spring-mass" sloshing. Only the first lateral
// mode matters: its mass m1 is 83 % of the liquid at h = 0.1 R and 43 % at h = R (below), while the
// second mode's, from the same formula with xi2 = 5.331, is 3 % of m1 in a deep tank, at 1.7 times
// the frequency (sqrt(xi2/xi1)), further from the attitude loop's bandwidth. The rest of the liquid
// moves with the tank.
//
// Equivalent mechanical model of an upright flat-bottomed cylinder (radius R, fill height h, axial
// acceleration g_eff pressing the liquid to the bottom), Abramson, NASA SP-106 (1966), ch. 6, and
// Dodge, "The New Dynamic Behavior of Liquids in Moving Containers", SwRI (2000), ch. 3:
//
//   xi1 = 1.8412 (first root of J1'),   omega1^2 = (g_eff xi1 / R) tanh(xi1 h / R)
//   m1 / m_liquid = 2 R tanh(xi1 h / R) / (xi1 (xi1^2 - 1) h)
//   L1 = h/2 - (2R / xi1) tanh(xi1 h / (2R))   (m1 above the liquid's centre of mass; with the
//                                                diameter d = 2R: h/2 - (d/xi1) tanh(xi1 h/d))
//   k1 = m1 omega1^2,   c1 = 2 zeta m1 omega1
//   m0 = m_liquid - m1 at L0 = -m1 L1 / m0   (the liquid's centre of mass stays where it was)
//
// L1 is also what the potential flow gives directly: the first mode's lateral momentum and moment of
// momentum about the bottom are in the ratio h - (2R/xi1) tanh(xi1 h/(2R)) (wall, bottom and free-
// surface terms); and it is Dodge's pendulum bob, hinge minus length (the test holds it to that).
// A form with R/xi1 in place of 2R/xi1 (the d -> R slip of the diameter form) puts m1 too high.
// Abramson's Table 6.1 places m0 with an extra -d^2/(8h) term (from matching a pitching excitation
// too); we keep the centre of mass instead, so a tank at rest weighs where its liquid does. m0's
// moment of inertia is left to the caller, with the rest of the rigid body.
//
// Coupled dynamics. The body (mass M: everything but the slosh masses; inertia I about its own
// centre of mass c) carries N <= kMaxSloshTanks point masses m_i at p_i = a_i + s_i (body axes, from
// the body's reference point; a_i the anchor, s_i the displacement). The spring-damper is lateral:
// f_i = -k_i s_i - c_i s_i', s_i in the plane perpendicular to the tank axis n_i. Along n_i the mass
// moves with the tank, which takes an axial constraint force lambda_i n_i. Both act on the mass and,
// reversed, on the body AT THE SAME POINT p_i, so they form action-reaction pairs on one line and the
// total angular momentum is conserved exactly, whatever direction the damper pulls in.
//
// Why the lateral spring with its constraint, and not an isotropic 3-D spring: the liquid has no
// axial slosh mode (it is incompressible and pressed to the bottom); an isotropic spring invents one
// at omega1, and a stiff axial spring to suppress it makes the equations stiff (a 100x stiffer
// spring needs a 10x smaller step). The constraint n_i . s_i = 0 is linear in body coordinates, so
// every Runge-Kutta step keeps it but for round-off: no drift, no stabilisation. The price is an implicit
// step (lambda_i depends on the body's acceleration), solved exactly: eliminating lambda_i leaves
// one 6x6 symmetric positive definite system for (a_c, omega'):
//
//   lambda_i = m_i [ n_i . a_c + (r_i x n_i) . omega' + n_i . (w x (w x r_i) + 2 w x s_i') ],  r_i = p_i - c
//   M a_c                  = F - sum (f_i + lambda_i n_i)
//   I omega' + w x I w     = T - sum r_i x (f_i + lambda_i n_i)
//   s_i'' = P_i [ f_i / m_i - (a_ref + omega' x p_i + w x (w x p_i) + 2 w x s_i') ],  P_i = 1 - n_i n_i^T
//   a_ref = a_c - omega' x c - w x (w x c)   (the reference point's inertial acceleration)
//
// a_c: inertial acceleration of the body's centre of mass, body axes; omega (w): inertial angular
// velocity, body axes; s_i', s_i'': derivatives in the body frame. F, T: external force and torque
// (about c) on the body alone (thrusters). A uniform gravity field accelerates everything alike and
// is left out. Like its source, the spring-mass is linear: small free-surface slopes.
//
// The pendulum (pendulum_length_m > 0) uses the same equations with n_i replaced by the rod's
// direction u_i (from the mass to its hinge, at rest n_i) and its constraint |p_i - hinge_i| = L_i
// differentiated twice, u_i . s_i'' = |s_i'|^2 / L_i (the centripetal term):
//
//   lambda_i = m_i [ u_i . (a_c + w' x r_i + w x (w x r_i) + 2 w x s_i') + |s_i'|^2 / L_i ] - u_i . f_i
//   s_i'' = P_i [ f_i / m_i - (...) ] + u_i |s_i'|^2 / L_i,   P_i = 1 - u_i u_i^T
//
// f_i is the damper's (and the wall's, when pressed), k_i = 0. Rod, damper and wall act on the mass
// and the body at the same point, so momentum is conserved as above, and with the damper off the
// kinetic energy is too (the rod does no work on the pair).
#include <array>
#include <span>

#include "core/types.hpp"

namespace chaser::model {

// Fixed capacity, so that the hot loop allocates nothing (SloshAccelerations spells out 4 zeros).
inline constexpr int kMaxSloshTanks = 4;
inline constexpr double kSloshXi1 = 1.8411837813406593;  // first root of J1'(x) = 0
// [rad/s] The pendulum wall's spring frequency at most: 0.5 rad per RK4 substep of the longest
// substep that integrates it, 0.1 s (the plant's kDefaultMaxSubstepS, which asserts the pair).
inline constexpr double kMaxWallOmegaRadps = 5.0;

// An upright flat-bottomed cylinder fixed in the body.
struct CylindricalTank {
  Vec3 bottom_centre_body_m = Vec3::Zero();  // [m] centre of the bottom, from the body reference point
  Vec3 axis_body = Vec3::UnitZ();            // unit, bottom to top (along the thrust's acceleration)
  double radius_m = 0.0;                     // [m] R
};

// One slosh mass: rest position, lateral plane, spring and damper; or, with a pendulum length, the
// pendulum analogue (below), whose restoring force is the actual specific force in the tank.
struct SloshTankParams {
  Vec3 anchor_body_m = Vec3::Zero();  // [m] the mass's rest position, from the body reference point
  Vec3 axis_body = Vec3::UnitZ();     // unit tank axis n; the mass moves in the plane perpendicular to it
  double mass_kg = 0.0;               // [kg] m1 > 0
  double stiffness_Npm = 0.0;         // [N/m] k1 = m1 omega1^2 (spring-mass; 0 for the pendulum)
  double damping_Nspm = 0.0;          // [N s/m] c1 = 2 zeta m1 omega1, on the mass's velocity in the body
  // Pendulum analogue: > 0, the rod's length L [m], hinged at anchor + L n; 0: the spring-mass.
  double pendulum_length_m = 0.0;
  double wall_angle_rad = 0.0;        // [rad] the swing's bound from n (the tank wall), pendulum only
  double wall_stiffness_Npm = 0.0;    // [N/m] the wall's penalty spring on the arc beyond the bound
  double wall_damping_Nspm = 0.0;     // [N s/m] and its damper (the wall only pushes, never pulls)
  double capillary_accel_mps2 = 0.0;  // [m/s^2] g_c: surface tension's hold on the liquid, pendulum only
};

// The equivalent model of one tank at one fill: the slosh mass and the fixed mass (Dodge 2000, ch. 3).
struct SloshTankFill {
  SloshTankParams slosh;
  double omega_radps = 0.0;          // [rad/s] omega1
  double slosh_height_m = 0.0;       // [m] h1 = h/2 + L1, m1 above the tank bottom
  double fixed_mass_kg = 0.0;        // [kg] m0 = m_liquid - m1, rigid with the tank
  double fixed_height_m = 0.0;       // [m] h0, m0 above the tank bottom: m0 h0 + m1 h1 = m_liquid h/2
  Vec3 fixed_mass_body_m = Vec3::Zero();  // [m] m0's position, from the body reference point
};

// The first lateral mode of liquid_mass_kg filling the tank to fill_height_m under the axial
// acceleration g_eff_mps2 (>= 0; at 0 the spring vanishes and the model, a gravity-wave one, no longer
// describes the capillary-dominated liquid), damping ratio damping_ratio (a bare tank: 0.001-0.01).
SloshTankFill slosh_tank_from_fill(const CylindricalTank& tank, double liquid_mass_kg, double fill_height_m,
                                   double g_eff_mps2, double damping_ratio);

// Pendulum analogue of the same mode, valid in turning flight (Dodge 2000, ch. 3; Abramson 1966,
// sec. 6.3): the mass m1 on a massless rod of length L = g_eff / omega1^2 = (R / xi1) coth(xi1 h / R),
// hinged on the tank axis L above m1's rest point (the spring-mass anchor), with the same damper.
// No spring: the rod's tension carries the specific force that the tank actually feels (thrust,
// turning, Coriolis), so the mode's frequency follows it, sqrt(a / L) under a steady axial
// acceleration a, and at zero specific force the mass coasts until the damper or the wall stops it.
// Small swings under the design acceleration g_eff are the spring-mass's (k1 = m1 g_eff / L).
// Restoring at zero thrust: below a Bond number of about 1 surface tension, not the acceleration,
// holds the liquid in place (Dodge 2000, ch. 11), so the tank pulls the mass towards its bottom with
// a constant capillary_accel_mps2 = sigma / (rho R^2) (the acceleration at Bond number rho a R^2 /
// sigma = 1: 3.2e-4 m/s^2 for hydrazine in a 0.45 m tank), a force pair between mass and tank at the
// mass, like the rod's. Without it the mass of a coasting chaser drifts to the wall and stays there.
// The wall: the liquid's centre cannot pass the tank's side nor climb above the hinge, so the swing
// is bounded at asin(R / L) from the axis (90 deg when L <= R), by a stiff, critically damped penalty
// spring at 10 omega1, at most 5 rad/s (0.5 rad per 0.1 s RK4 substep of the plant). A steady
// specific force a presses the mass in by a / (10 omega1)^2 along its arc: 9 mm, 3 % of L, under the
// 0.0125 m/s^2 that holds COMRADE's chaser beside its turning target (omega1 0.12 rad/s).
SloshTankParams pendulum_analogue(const SloshTankFill& fill, const CylindricalTank& tank, double g_eff_mps2,
                                  double capillary_accel_mps2);

// The body without the slosh masses.
struct RigidBodyMassProps {
  double mass_kg = 0.0;                         // [kg] M > 0
  Mat3 inertia_com_body_kgm2 = Mat3::Identity();  // [kg m^2] about the body's own centre of mass, body axes
  Vec3 com_body_m = Vec3::Zero();               // [m] c, from the body reference point
};

struct SloshState {
  Vec3 s_body_m = Vec3::Zero();        // [m] displacement from the anchor, perpendicular to the axis
  Vec3 s_dot_body_mps = Vec3::Zero();  // [m/s] its rate in the body frame
};

// The pendulum's state moved onto its constraint (|p - hinge| = L, the rate perpendicular to the rod);
// the spring-mass's returned unchanged. The plant applies it after each integrated piece, since RK4
// keeps the sphere only to its truncation error.
SloshState on_constraint(const SloshTankParams& tank, const SloshState& state);

struct SloshAccelerations {
  Vec3 a_com_body_mps2 = Vec3::Zero();        // [m/s^2] the body's CoM, inertial, body axes
  Vec3 omega_dot_body_radps2 = Vec3::Zero();  // [rad/s^2] inertial, body axes
  // [m/s] s_i' read on the constraint (lateral; the pendulum's along its sphere): the state's s'.
  std::array<Vec3, kMaxSloshTanks> s_dot_body_mps = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  std::array<Vec3, kMaxSloshTanks> s_ddot_body_mps2 = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero(),
                                                       Vec3::Zero()};  // [m/s^2] body frame, lateral
  std::array<double, kMaxSloshTanks> axial_force_N{};  // [N] lambda_i, the tank on the mass along n_i
};
static_assert(kMaxSloshTanks == 4, "SloshAccelerations::s_dot_body_mps and s_ddot_body_mps2 zero 4 entries");

// The equations above. tanks and states have equal sizes <= kMaxSloshTanks (extra entries are
// ignored; the scenario's reader validates masses, axes, springs and dampers, as for every key). s and s' are projected onto the lateral plane before use. No allocation.
SloshAccelerations coupled_accelerations(const RigidBodyMassProps& body, std::span<const SloshTankParams> tanks,
                                         std::span<const SloshState> states, const Vec3& omega_body_radps,
                                         const Vec3& force_body_N, const Vec3& torque_body_Nm);
// The same, with the body's inverse inertia given (the plant forms it once per run, not per call).
SloshAccelerations coupled_accelerations(const RigidBodyMassProps& body, const Mat3& inertia_inv_com_body,
                                         std::span<const SloshTankParams> tanks, std::span<const SloshState> states,
                                         const Vec3& omega_body_radps, const Vec3& force_body_N,
                                         const Vec3& torque_body_Nm);

// Invariants of the free system (tests, telemetry). v_com_inertial_mps: the body's CoM velocity,
// inertial axes. The angular momentum is about the system's centre of mass, inertial axes.
Vec3 total_linear_momentum_inertial(const RigidBodyMassProps& body, std::span<const SloshTankParams> tanks,
                                    std::span<const SloshState> states, const Quat& q_inertial_from_body,
                                    const Vec3& v_com_inertial_mps, const Vec3& omega_body_radps);  // [N s]
Vec3 total_angular_momentum_inertial(const RigidBodyMassProps& body, std::span<const SloshTankParams> tanks,
                                     std::span<const SloshState> states, const Quat& q_inertial_from_body,
                                     const Vec3& v_com_inertial_mps, const Vec3& omega_body_radps);  // [N m s]
double total_kinetic_energy(const RigidBodyMassProps& body, std::span<const SloshTankParams> tanks,
                            std::span<const SloshState> states, const Quat& q_inertial_from_body,
                            const Vec3& v_com_inertial_mps, const Vec3& omega_body_radps);  // [J]
// The springs' energy: the spring-mass's k s^2 / 2; the pendulum's wall penalty when pressed in and its
// capillary hold's m g_c (n . s).
double slosh_spring_energy(std::span<const SloshTankParams> tanks, std::span<const SloshState> states);  // [J]

}  // namespace chaser::model
