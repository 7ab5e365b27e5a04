#include "sim/user_flight.hpp"

namespace chaser::sim {

namespace {

// As step_flight starts: navigation from the first measurement, the scenario's starting set. A run
// may switch between Chaser's flight software and a user's, so both start the same state.
void initialise(const flight::FlightParams& params, flight::FlightState& state, const model::SensorMeasurements& meas) {
  if (state.initialised) return;
  state.navigation = flight::init_nav(params.navigation, meas);
  state.thrusters = model::initial_configuration(params.management.thrusters);
  flight::set_active_thrusters(params.management, state.management, state.thrusters.active);
  state.initialised = true;
}

// The output of a period whose command comes from elsewhere: the guidance reference, which the
// mission monitor judges the truth against, and the latch valves as the flight state has them.
flight::FlightOutput user_output(const flight::FlightParams& params, const flight::FlightState& state,
                                 const model::SensorMeasurements& meas) {
  flight::FlightOutput out;
  out.reference = flight::guidance_reference(params.guidance, params.orbit, to_seconds(meas.t));
  out.command.latch_closed_groups = state.thrusters.closed_groups;
  return out;
}

}  // namespace

flight::FlightOutput wrench_flight_output(const flight::FlightParams& params, flight::FlightState& state,
                                          const model::SensorMeasurements& meas, const Vec6& demand_wrench_body) {
  initialise(params, state, meas);
  flight::FlightOutput out = user_output(params, state, meas);
  out.released_wrench = flight::tmu_release(params.tmu, state.tmu, demand_wrench_body);
  const flight::ThrusterManagementOutput managed =
      flight::manage_thrusters(params.management, state.management, out.released_wrench, out.command.ton);
  flight::tmu_account(params.tmu, state.tmu, managed.commanded_wrench);
  out.commanded_wrench = managed.commanded_wrench;
  out.allocation_feasible = managed.feasible;
  return out;
}

flight::FlightOutput on_times_flight_output(const flight::FlightParams& params, flight::FlightState& state,
                                            const model::SensorMeasurements& meas, const model::ThrusterOnTimes& ton) {
  initialise(params, state, meas);
  flight::FlightOutput out = user_output(params, state, meas);
  out.command.ton = ton;
  return out;
}

}  // namespace chaser::sim
