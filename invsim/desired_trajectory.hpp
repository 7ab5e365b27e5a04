#pragma once
// Desired trajectory of the approach (the "expected state" x_c of Zhou 2018, section 2.2), Hill
// frame: a constant-velocity approach along x from the initial x0, then, from damping_start_s, the
// exponential "index damping" phase x = x_dock + (x_s - x_dock) exp(-(t - t_s) / T) (section 3.2).
// The approach velocity -(x0 - x_dock) / (t_s + T) makes x and x' continuous at t_s. The paper
// gives neither the profile nor its numbers; y and z are held at 0 (on the docking axis).
#include "core/types.hpp"
#include "model/invsim.hpp"

namespace chaser::invsim {

// [m/s] velocity of the constant-velocity phase.
double approach_velocity_mps(const model::InvSimTrajectoryParams& p, double x0_m);

// [x y z x' y' z'] desired at time t [s] (t may exceed the run; the exponential continues).
Vec6 desired_state(const model::InvSimTrajectoryParams& p, double x0_m, double t_s);

// The paper reading's designed lateral trajectory (pulses.paper.lateral_time_constant_s T > 0):
// y and z return from their initial position and velocity to 0 along the critically damped path
//   q(t) = (q0 + (q0' + q0 / T) t) exp(-t / T),   q'(t) = (q0' - (q0' + q0 / T) t / T) exp(-t / T),
// which starts at (q0, q0') and has no jump for the inverse model to answer at once. Sets
// x_desired's y, z, y', z' (held at 0 by desired_state).
void set_lateral_return(double time_constant_s, const Vec3& r0_m, const Vec3& v0_mps, double t_s,
                        Vec6& x_desired);

// The same with a brake first (pulses.paper.lateral_brake_mps2 a > 0): each lateral axis's initial
// velocity q0' is cancelled at the constant deceleration a,
//   q(t) = q0 + q0' t - sgn(q0') a t^2 / 2,   q'(t) = q0' - sgn(q0') a t,   t <= t_stop = |q0'| / a,
// the way a pilot nulls a drift before steering back, then the critically damped return above
// starts from the stopping point (q0 + q0' t_stop / 2, 0). Position and velocity are continuous.
// With a no larger than what a group that lost one of its two thrusters can give, such a group
// flies the same path as the healthy one (docs/invsim.md, "A designed lateral brake").
void set_lateral_brake_then_return(double brake_mps2, double time_constant_s, const Vec3& r0_m,
                                   const Vec3& v0_mps, double t_s, Vec6& x_desired);

}  // namespace chaser::invsim
