#pragma once
// Phase-plane attitude control of one axis (Zhou 2018, App. A and its Table 1).
//
// The switching lines are parabolas of full-torque braking (a0 = the axis' control acceleration):
//   negative opening line DE:  theta'^2 = -2 a0 (theta - d)        (theta' >= 0 branch)
//   negative closing line BC:  theta'^2 =  2 a0 (theta - d + delta) (theta' <= 0 branch)
//   and their mirror images D'E', B'C' for the positive side.
// Both lines are level sets of the stopping angle sigma = theta + theta'|theta'| / (2 a0) (the
// angle where full opposing torque would stop the motion): DE is sigma = d (theta' >= 0), BC is
// sigma = d - delta (theta' <= 0); on theta' > 0 the level set sigma = d - delta is DE shifted by
// delta, and bounds the step-decelerate area R13.
// The areas (our reading of App. A, which gives the lines and the opening times but not the area
// boundaries; the negative side is listed, the positive side is its mirror theta -> -theta):
//   R11 full opening, T = btc3 dT:  theta' > theta'_s, or sigma > d with theta' > theta'_t
//                                   (moving outward fast: brake with full opening);
//   R12 step control, T = btc2 dT:  sigma > d with |theta'| <= theta'_t
//                                   (beyond the opening line, nearly still: nudge back);
//   R13 step decelerate, T = btc2 dT: d - delta < sigma <= d with theta' > theta'_t
//                                   (between the closing and the opening line, moving outward);
//   R0 closing area:                everything else; no firing (the paper's T = btc1 dT with
//                                   btc1 = 0, the only value the loader accepts).
// Being stateless, the controller needs no memory of the last firing, so a run is reproducible
// from any step.
#include "model/invsim.hpp"

namespace chaser::invsim {

enum class PhasePlaneArea { kR0, kR11, kR12, kR13, kR21, kR22, kR23 };  // R1x negative, R2x positive

struct PhasePlaneCommand {
  PhasePlaneArea area;
  int direction;      // -1 (negative torque), +1, or 0
  double on_time_s;   // [s] opening time T within the sampling period
};

// theta [rad] and rate [rad/s] of one axis relative to the desired attitude; a0 [rad/s^2] > 0.
PhasePlaneArea phase_plane_area(const model::InvSimPhasePlaneParams& p, double a0_radps2,
                                double theta_rad, double rate_radps);

PhasePlaneCommand step_phase_plane(const model::InvSimPhasePlaneParams& p, double a0_radps2,
                                   double theta_rad, double rate_radps);

}  // namespace chaser::invsim
