#pragma once
// The body-rate model a diagnosis designs from where the tanks' liquid moves the chaser (COMRADE
// 2018, sec. 6.3: thruster commands to the gyro's rates, Euler's second law with the tanks' dominant
// slosh modes, reduced to the modes that matter). Built from a scenario with chaser.slosh:
//
//   x' = A x + B u + E d,   y = C x,   x = [omega (3); q (2 per tank); q' (2 per tank)]
//
// omega the body rate [rad/s], q the slosh masses' lateral displacements [m] along two unit
// directions perpendicular to each tank's axis, u the thrusters' on-time fractions (the scenario's
// starting active set, in its order), d a torque disturbance [N m] on the body, y the gyro's rate.
// It is the linearisation about rest (omega = 0, the liquid at its anchors) of model/slosh.hpp's
// coupled equations with each tank's first mode as the spring-mass at chaser.slosh.g_eff_mps2
// (the pendulum's small-swing limit under that acceleration: k1 = m1 g_eff / L), taken by central
// differences, which are exact here but for round-off: at rest the equations' only non-linear
// terms (gyroscopic, centrifugal, Coriolis) are products of two state components. The thrusters'
// force enters too: it accelerates the tanks and so drives the liquid.
//
// Reduction: a slosh mode (a pair of eigenvalues of A) that the wrench cannot excite or the gyro
// cannot see is dropped (the Popov-Belevitch-Hautus test on its eigenvectors); the rigid rates and
// the kept modes form the reduced model, in modal coordinates. Two tanks side by side at the same
// height, as COMRADE's: their masses swinging in opposite directions along the line joining them
// give no torque and are driven by none, so of the two tanks' four lateral modes three remain.
#include <string>
#include <vector>

#include "core/types.hpp"
#include "model/scenario.hpp"

namespace chaser::flight::fdi {

struct SloshModeFigures {
  double frequency_radps = 0;  // [rad/s] |imag| of the eigenvalue pair
  double damping_ratio = 0;    // [-]
  double controllability = 0;  // [-] |w' B_wrench| / (|w| |B_wrench|), w the left eigenvector
  double observability = 0;    // [-] |C v| / |v|, v the right eigenvector (unit)
  bool kept = false;           // both above the tolerance
};

struct RateModel {
  Eigen::MatrixXd A, B, E, C;  // the full model (3 + 4 tanks states), continuous time
  std::vector<std::string> state_names;
  Eigen::MatrixXd A_reduced, B_reduced, E_reduced, C_reduced;  // rigid rates and kept modes, real modal form
  std::vector<SloshModeFigures> modes;  // every slosh mode of A, by frequency
  int thrusters = 0;                    // columns of B
};

inline constexpr double kRateModeTolerance = 1e-6;  // [-] controllability and observability below: dropped

// Throws std::invalid_argument naming the key when the scenario has no chaser.slosh.
RateModel rate_model(const model::Scenario& scenario);

}  // namespace chaser::flight::fdi
