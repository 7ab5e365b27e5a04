#pragma once
// A fault mode flown over several noise sequences of the measurement link (the paper reading's
// pulses.paper.measurement_noise.draws; docs/invsim.md, "Readings of App. B").
//
// With noise, one run's counts are one draw: the y counts of the shipped calibration move by up to
// 30 % from one seed to the next. A study row over N draws (seeds seed ... seed + N - 1, the same
// for every mode, so a fault row differs from the nominal by the fault) reports the mean workload
// and the worst deviation:
//  - pulse counts, P, opening and attitude-couple times, propellant: the mean (counts rounded to
//    the nearest pulse; k_p = mean P / P_thrust, unrounded);
//  - peak azimuth, elevation and attitude: the largest over the draws;
//  - target always in view, attitude within limits, docked: only if so in every draw; diverged if
//    any draw diverged;
//  - final position and velocity: the first draw's (a mean of end states is no state).
// So the risk class of a row is that of its worst draw.
#include <cstdint>
#include <vector>

#include "invsim/inverse_simulation.hpp"
#include "model/invsim.hpp"

namespace chaser::invsim {

// Noise sequences a study flies per mode: the scenario's draws under the paper reading with noise
// on, else 1.
std::uint64_t noise_draws_per_mode(const model::InvSimParams& params);

// The measurement-noise seed of draw `i` (0 .. draws - 1): the scenario's seed + i.
std::uint64_t noise_draw_seed(const model::InvSimParams& params, std::uint64_t i);

// The parameters of draw `i`: the scenario's with noise_draw_seed(params, i).
model::InvSimParams noise_draw(const model::InvSimParams& params, std::uint64_t i);

// Each draw's own result, in draw order (one plain run when there is one draw).
std::vector<InvSimResult> fly_noise_draws(const model::InvSimParams& params, const model::InvSimFaultSet& faults);

// The row's result over the scenario's draws: combine_draws(fly_noise_draws(...)), and one plain run
// (bit for bit) when the reading is not paper, the noise is off or draws is 1.
InvSimResult run_over_noise_draws(const model::InvSimParams& params, const model::InvSimFaultSet& faults);

// The combination above, of one or more results (the first gives the final state).
InvSimResult combine_draws(const std::vector<InvSimResult>& draws, double basic_pulse_amount);

}  // namespace chaser::invsim
