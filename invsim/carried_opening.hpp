#pragma once
// An opening longer than the IS step (the paper reading's pulses.paper.opening: carried).
//
// Eq. 1 of App. B, u_max dtau = u* tau, gives dtau > tau when the inverse model asks for more than
// the group can give in one step; the paper does not cap dtau. Capped (`smooth`, and the paper
// reading's default), the group is open the whole step and the rest of the impulse is lost, to be
// asked for again by the next step's inverse model from the deficit it sees. Carried, the group
// stays open into the next steps until the commanded impulse is given, as a pilot holding a
// thruster open would; the inverse model then asks each step only for what the opening under way
// will not give (command_beyond_carried), so nothing is asked for twice. It matters when a group
// has lost one of its two thrusters: a command above half the healthy group's thrust saturates the
// halved group, and capped, the fault changes the flight as well as the opening times
// (docs/invsim.md, "Predictions").
#include <array>

#include "invsim/pulse_conversion.hpp"

namespace chaser::invsim {

// The opening under way on one body axis: its direction (+1, -1, 0 for none) and the time left.
struct CarriedOpening {
  int direction = 0;
  double remaining_s = 0.0;  // [s]
};

// The acceleration the inverse model still asks for [m/s^2]: u_ls less what the opening under way
// will give, its remaining time at its group's acceleration (accel_mps2[0] for +1, [1] for -1)
// spread over one step (the step's command is u tau of impulse, eq. 1).
double command_beyond_carried(const CarriedOpening& carried, const std::array<double, 2>& accel_mps2, double step_s,
                              double u_ls_mps2);

// Adds this step's new opening to the one under way and returns the opening flown in this step (at
// most step_s); the rest stays in `carried`. `commanded` is the new opening, direction and its whole
// dtau (not capped), of the group whose acceleration is accel_mps2[0] for +1, [1] for -1. In the
// direction under way it lengthens the opening; in the other it first shortens it, impulse for
// impulse, and only what is left opens the other group.
Pulse open_for_step(CarriedOpening& carried, const Pulse& commanded, const std::array<double, 2>& accel_mps2,
                    double step_s);

}  // namespace chaser::invsim
