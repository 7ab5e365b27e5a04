#pragma once
// Piecewise-exact propagation of the chaser's coupled 6-DOF truth motion (docs/architecture.md, "One control
// period"): the thruster model cuts each control period into pieces with constant inputs, and
// propagate_piece integrates one piece from edge to edge, so no pulse edge ever falls inside a step.
//
// State equations (all nonlinear, integrated together):
//   r' = v,  v' = eq. 8 gravity/rotation terms (relative_orbit.hpp) + (F_lvlh + F_dist_lvlh) / m,
//            F_lvlh = q_lvlh_from_inertial(t) q_inertial_from_body F_body    (true attitude)
//   q' = 1/2 q (x) (0, omega),  omega' = I^-1 (C - omega x I omega)          (rigid_body.hpp)
//            C = C_body + gravity-gradient torque (gravity_gradient.hpp) when enabled
//   m' = -mass_flow                                                           (inertia constant)
// Integrator: classical fourth-order Runge-Kutta with ceil(dt / max_substep) equal substeps over the
// piece, quaternion re-normalised at the end of the piece. See docs/dynamics.md for the choice and
// the measured accuracy and cost.
#include "core/types.hpp"
#include "model/scenario.hpp"
#include "model/slosh.hpp"
#include "model/target_orbit.hpp"
#include "plant/rigid_body.hpp"

namespace chaser::plant {

// Default RK4 substep bound [s]. Equal to the MSR control period, so a whole quiet period is one
// step; RK4's local error there is ~(|omega| h)^5 / 120, 3e-12 rad at 0.05 rad/s and the
// translation error ~(n h)^5 ~ 1e-20 relative: far below every sensor noise (docs/dynamics.md).
inline constexpr double kDefaultMaxSubstepS = 0.1;  // [s]
// The pendulum slosh's wall spring turns at most 0.5 rad per substep (model/slosh.hpp).
static_assert(model::kMaxWallOmegaRadps * kDefaultMaxSubstepS <= 0.5);

struct DynamicsParams {  // derived once per run from the scenario (make_dynamics_params)
  // The target's orbit: its radius a, mean motion n and mu for eq. 8 and the gravity gradient, and
  // the angle LVLH has turned since t = 0. Eq. 8 is the circular orbit's relative motion; a
  // perturbed orbit brings its own relative dynamics.
  model::TargetOrbit orbit;
  Mat3 inertia_kgm2 = Mat3::Identity();  // [kg m^2] about the CoM, body axes, constant
  Mat3 inertia_inv = Mat3::Identity();   // [1/(kg m^2)]
  bool gravity_gradient = false;         // gravity-gradient torque on
  double max_substep_s = kDefaultMaxSubstepS;  // [s] RK4 substep bound (> 0)
};

DynamicsParams make_dynamics_params(const model::Scenario& s);

// Inputs constant over one piece of a control period.
struct PieceInput {
  Vec3 force_body_N = Vec3::Zero();    // [N] thrusters, body axes
  Vec3 torque_body_Nm = Vec3::Zero();  // [N m] thrusters + disturbance torque about the CoM, body axes
  Vec3 force_lvlh_N = Vec3::Zero();    // [N] disturbance force, LVLH axes
  double mass_flow_kgps = 0.0;         // [kg/s] >= 0, propellant flow while this piece lasts
};

// Advances x from t0_s to t0_s + dt_s under constant u, integrating the coupled nonlinear
// equations above. t0_s [s] is the run time (it fixes the LVLH orientation); dt_s [s] <= 0 is a
// no-op. Allocation-free.
void propagate_piece(const DynamicsParams& p, RigidState& x, double t0_s, double dt_s, const PieceInput& u);

// Number of equal RK4 substeps propagate_piece takes for a piece of dt_s (>= 1). A piece longer
// than max_substep by less than one part in 1e9 (rounding of ns times) is still one substep.
int substep_count(double dt_s, double max_substep_s);

}  // namespace chaser::plant
