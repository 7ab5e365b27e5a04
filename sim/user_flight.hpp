#pragma once
// A flight side other than Chaser's for one period (the Python module's flight callback): what it
// returns made into the flight output that Simulation::end_period flies. It saw the period's
// measurements only; these functions add what the plant and the monitor need from the flight side.
#include "core/types.hpp"
#include "flight/flight_software.hpp"
#include "model/messages.hpp"

namespace chaser::sim {

// A wrench demand [F; C] in body axes [N; N m] through Chaser's TMU (flight/modulation.hpp) and
// thruster allocation (flight/thruster_management.hpp) on the flight state's active set and latches.
flight::FlightOutput wrench_flight_output(const flight::FlightParams& params, flight::FlightState& state,
                                          const model::SensorMeasurements& meas, const Vec6& demand_wrench_body);

// On-times [-] (fractions of the period, by thruster index) straight to the thruster hardware,
// with the flight state's latch valves.
flight::FlightOutput on_times_flight_output(const flight::FlightParams& params, flight::FlightState& state,
                                            const model::SensorMeasurements& meas, const model::ThrusterOnTimes& ton);

}  // namespace chaser::sim
