#pragma once
// The truth side of one run: motion, environment, thruster hardware with its faults, sensors.
// make_plant builds it from a scenario and a run seed; each control period the simulator calls
// sense_plant at the period start and step_plant to propagate to the next period start.
#include <optional>
#include <vector>

#include "core/random.hpp"
#include "core/time.hpp"
#include "model/messages.hpp"
#include "model/scenario.hpp"
#include "plant/orbit_plant.hpp"
#include "plant/propagator.hpp"
#include "plant/sensors.hpp"
#include "plant/target.hpp"
#include "plant/thruster_hardware.hpp"

namespace chaser::plant {

struct PlantParams {
  DynamicsParams dynamics;              // the circular orbit's (Fonod 2015, eq. 8)
  std::optional<OrbitPlantParams> earth;  // set: a perturbed Earth orbit instead (issue 17)
  model::TargetParams target;
  ThrusterHardware thrusters;          // dispersed once per run
  std::vector<model::FaultParams> faults;
  model::SensorParams sensors;
  model::EnvironmentParams environment;
  TimeNs period_ns = 0;
  TimeNs delay_max_ns = 0;
};

// Every noise source draws from its own named stream (docs/architecture.md, deterministic randomness).
struct PlantStreams {
  RandomStream delay, force_noise, torque_noise, propellant_gauge, target_pose;
  SensorNoise sensors;
  explicit PlantStreams(std::uint64_t seed);
};

struct PlantState {
  RigidState rigid;  // the chaser; with an Earth orbit its r_lvlh_m, v_lvlh_mps are derived from `orbit`
  OrbitState orbit;  // Earth orbit only: both bodies in ECI, the target's attitude
  EphemerisSamples ephemeris;  // Earth orbit only: the Sun's and the Moon's last samples
  SlowEnvironmentSample slow_environment;  // Earth orbit only: the slow terms of the current window
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

// The target's attitude and the target's LVLH at run time t_s (the period start the state is at):
// integrated or from the circle's constant-rate model, as the plant flies it.
TargetRotation target_rotation(const Plant& plant, double t_s);
Quat q_inertial_from_lvlh(const Plant& plant, const model::TargetOrbit& circle, double t_s);

model::SensorMeasurements sense_plant(const PlantParams& params, PlantState& state, TimeNs t);

// Propagates the truth over [t_k, t_k + T] under the command: thruster pieces, disturbances.
void step_plant(const PlantParams& params, PlantState& state, const model::ThrusterCommand& command, TimeNs t_k);

}  // namespace chaser::plant
