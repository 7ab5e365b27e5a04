#pragma once
// The two readings of Zhou 2018's App. B pulses (model::InvSimReading; docs/invsim.md, "Readings
// of App. B"). Both convert the inverse model's acceleration with eqs. 1-4 (pulse_conversion.hpp)
// and fly the same opening; they differ in what P of eq. 22 counts and in Q of eq. 20:
//  - smooth: one pulse per step in which a group fired; Q = inverse.state_weights;
//  - paper: one pulse per valve opening of at most w = pulse_width_s, a step's opening dtau
//    counting ceil(dtau / w): P is the commanded opening time in units of w, which is what makes
//    the paper's counts double when a group loses one of its two thrusters (Table 4: e1~ y+
//    230 -> 464, f2~ z- 567 -> 1131, d1 x+ 114 -> 230); Q = pulses.paper.state_weights.
//    The train of openings is flown as one opening of dtau at the step's start (same impulse in
//    the same step; the shift of its centre within the step changes the state by O(n tau) of it).
#include <array>
#include <string_view>

#include "invsim/pulse_conversion.hpp"
#include "model/invsim.hpp"

namespace chaser::invsim {

// Pulses counted for one step's pulse of one group under the reading (0 for no pulse).
int counted_pulses(const model::InvSimPulseParams& p, const Pulse& pulse);

// The diagonal of Q (eq. 20) under the scenario's reading.
const std::array<double, 6>& reading_state_weights(const model::InvSimParams& p);

// The choices that change the flight (inverse_model, opening, lateral_time_constant_s, lateral_brake_mps2,
// measurement_noise) as they apply to a run: the scenario's pulses.paper block under the paper
// reading; under smooth the block's defaults, which are smooth's own flight (the nominal inverse
// model, capped openings, y and z held at 0, a perfect measurement). The one place a run asks which
// reading it is under for these; the block's pulse_width_s and state_weights are read through
// counted_pulses and reading_state_weights.
const model::InvSimPaperReadingParams& flight_choices(const model::InvSimParams& p);

std::string_view reading_name(model::InvSimReading r);  // "smooth", "paper"

}  // namespace chaser::invsim
