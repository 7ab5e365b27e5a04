#pragma once
// The truth side of one run: motion, environment, thruster hardware with its faults, sensors.
// make_plant builds it from a scenario and a run seed; each control period the simulator calls
// sense_plant at the period start and step_plant to propagate to the next period start.
#include <vector>

#include "core/random.hpp"
#include "core/time.hpp"
#include "model/messages.hpp"
#include "model/scenario.hpp"
#include "plant/propagator.hpp"
#include "plant/sensors.hpp"
#include "plant/thruster_hardware.hpp"

namespace chaser::plant {

struct PlantParams {
  DynamicsParams dynamics;
  ThrusterHardware thrusters;          // dispersed once per run
  std::vector<model::FaultParams> faults;
  model::SensorParams sensors;
  model::EnvironmentParams environment;
  TimeNs period_ns = 0;
  TimeNs delay_max_ns = 0;
};

// Every noise source draws from its own named stream (docs/architecture.md, deterministic randomness).
struct PlantStreams {
  RandomStream delay, force_noise, torque_noise, propellant_gauge;
  SensorNoise sensors;
  explicit PlantStreams(std::uint64_t seed);
};

struct PlantState {
  RigidState rigid;
  ThrusterState thrusters;
  SensorState sensors;
  PlantStreams streams;
  ThrustProfile last_profile;     // the thrust profile of the last period, for telemetry
  TimeNs last_delay_ns = 0;       // [ns] tau(k) of the last period
  double propellant_used_kg = 0;  // [kg]
};

struct Plant {
  PlantParams params;
  PlantState state;
};

Plant make_plant(const model::Scenario& scenario, const RigidState& initial, std::uint64_t seed);

model::SensorMeasurements sense_plant(const PlantParams& params, PlantState& state, TimeNs t);

// Propagates the truth over [t_k, t_k + T] under the command: thruster pieces, disturbances.
void step_plant(const PlantParams& params, PlantState& state, const model::ThrusterCommand& command, TimeNs t_k);

}  // namespace chaser::plant
