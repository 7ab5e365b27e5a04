#pragma once
// Tustin's (bilinear) discretisation of a continuous controller, s = (2 / T) (z - 1) / (z + 1):
//
//   M = (I - A T/2)^-1,  Ad = M (I + A T/2),  Bd = M B T,  Cd = C M,  Dd = D + C M B T/2.
//
// Its frequency response is the continuous one at a warped frequency, exactly:
// H_d(e^{j w T}) = H_c(j (2/T) tan(w T / 2)), so a controller designed with the sampling's delay in
// its plant (the hold's T/2, control/six_axis_design.hpp) keeps its margins where w T << 1, and
// a stable H_c (poles in the left half-plane) maps to a stable H_d (poles inside the unit circle).
// The state's meaning changes; the discrete system is x+ = Ad x + Bd e, u = Cd x + Dd e.
// Design-time code: allocates. Throws std::invalid_argument for T <= 0, an inconsistent system, or
// a pole at s = 2/T (I - A T/2 singular).
#include "control/state_space.hpp"

namespace chaser::control {

StateSpace discretise_tustin(const StateSpace& continuous, double period_s);

}  // namespace chaser::control
