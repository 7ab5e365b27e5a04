#pragma once
// The channels of telemetry.csv and how one row is filled from a period's truth and flight output.
#include <string>
#include <vector>

#include "flight/flight_software.hpp"
#include "plant/plant.hpp"
#include "sim/telemetry.hpp"

namespace chaser::sim {

// The channels for a set of `thrusters` thrusters (ton_cmd_i, ton_real_i for T1..TN).
std::vector<std::string> telemetry_channels(int thrusters);

// One row for period k: the truth at its start (truth_at_start), the flight output computed from
// the measurements at its start, and what the plant realised over it (plant_after: profile, delay,
// propellant at the period end). Thruster columns by thruster number; FDI thrusters as numbers
// 1..N (0: none) through the watched set the FDI had this period; active_thrusters is the active
// set's mask (bit i: T(i+1)).
void record_period(TelemetryWriter& writer, double t_s, const plant::RigidState& truth_at_start,
                   const plant::PlantState& plant_after, const flight::FlightOutput& flight,
                   const flight::FlightState& flight_state, int thrusters, const flight::fdi::WatchedSet& watched,
                   const Vec3& attitude_error_body_rad, const Quat& q_inertial_from_target);

}  // namespace chaser::sim
