#pragma once
// The truth side of one run: motion, environment, thruster hardware with its faults, sensors.
// make_plant builds it from a scenario and a run seed; each control period the simulator calls
// sense_plant at the period start and step_plant to propagate to the next period start.
//
// The seam: what carries the bodies between thrust edges is a motion model, one alternative of
// MotionParams / MotionState (today the circular orbit's relative motion and the perturbed Earth
// orbit, and for the capture the multibody hub, arm and target on MuJoCo). Everything else (thrusters and their
// faults, sensors, disturbances, propellant) is the plant's own and does not change with it. A
// motion model is one file that defines XParams (with `using State = XState`) and XState, and
// overloads begin_period, advance, target_rotation, q_inertial_from_lvlh and slosh_states; adding one
// is one alternative in each variant below and one branch in make_plant (docs/architecture.md,
// "How to add a plant"). Outside plant/ the chaser's state is read with chaser_state().
#include <span>
#include <variant>
#include <vector>

#include "core/random.hpp"
#include "core/time.hpp"
#include "model/messages.hpp"
#include "model/scenario.hpp"
#include "model/target_orbit.hpp"
#include "plant/circular_orbit_motion.hpp"
#include "plant/earth_orbit_motion.hpp"
#include "plant/multibody_motion.hpp"
#include "plant/propagator.hpp"
#include "plant/sensors.hpp"
#include "plant/target.hpp"
#include "plant/thruster_hardware.hpp"

namespace chaser::plant {

// Index i of MotionState is the state of index i of MotionParams.
// The multibody plant is entered by hand-over only (plant/handover.hpp), never by make_plant.
using MotionParams = std::variant<CircularOrbitParams, EarthOrbitParams, MultibodyMotionParams>;
using MotionState = std::variant<CircularOrbitState, EarthOrbitState, MultibodyMotionState>;

struct PlantParams {
  MotionParams motion;
  ThrusterHardware thrusters;  // dispersed once per run
  model::SensorParams sensors;
  model::EnvironmentParams environment;
  TimeNs period_ns = 0;
  TimeNs delay_max_ns = 0;
  // The grasp fixture's frame on the target (target axes, from its CoM): what the arm camera sees
  // (model::ArmCameraParams).
  Vec3 fixture_target_m = Vec3::Zero();
  Quat q_target_from_fixture = Quat::Identity();
};

// Every noise source draws from its own named stream (docs/architecture.md, deterministic randomness).
struct PlantStreams {
  RandomStream delay, force_noise, torque_noise, propellant_gauge, target_pose, arm_camera;
  SensorNoise sensors;
  explicit PlantStreams(std::uint64_t seed);
};

struct PlantState {
  MotionState motion;
  RigidState chaser;  // read outside plant/ through chaser_state()
  ThrusterState thrusters;
  // The faults the hardware has, each from its onset: the scenario's, and any injected during the
  // run (inject_fault). State, not parameters: a fault happens to the plant.
  std::vector<model::FaultParams> faults;
  SensorState sensors;
  PlantStreams streams;
  ThrustProfile last_profile;     // the thrust profile of the period begun (telemetry: the last one)
  PeriodDisturbance disturbance;  // the period's disturbances, drawn when it begins
  TimeNs last_delay_ns = 0;       // [ns] tau(k) of the last period
  double propellant_used_kg = 0;  // [kg]
};

struct Plant {
  PlantParams params;
  PlantState state;
};

Plant make_plant(const model::Scenario& scenario, const RigidState& initial, std::uint64_t seed);

// Calls f(params, state) with the motion model's own types.
template <class F>
decltype(auto) visit_motion(const PlantParams& params, const PlantState& state, F&& f) {
  return std::visit(
      [&](const auto& p) -> decltype(auto) {
        return f(p, std::get<typename std::decay_t<decltype(p)>::State>(state.motion));
      },
      params.motion);
}

// The chaser at the time the plant is at (the period start between steps).
inline const RigidState& chaser_state(const Plant& plant) { return plant.state.chaser; }

// The target's attitude and the target's LVLH at run time t_s (the period start the state is at):
// integrated or from the circle's constant-rate model, as the plant flies it.
TargetRotation target_rotation(const Plant& plant, double t_s);
Quat q_inertial_from_lvlh(const Plant& plant, const model::TargetOrbit& circle, double t_s);

// The chaser's slosh masses now (none without chaser.slosh).
std::span<const model::SloshState> slosh_states(const Plant& plant);

// A fault from its onset on (not before the plant's time: the caller checks).
void inject_fault(Plant& plant, const model::FaultParams& fault);

// The sensors' samples at t (the LIDAR and the pose sensor see the target only inside their view:
// q_inertial_from_lvlh turns the LIDAR's LVLH line of sight into the body's axes).
model::SensorMeasurements sense_plant(const PlantParams& params, PlantState& state, TimeNs t,
                                      const Quat& q_inertial_from_lvlh);

// The period at t_k begins under the command: the latches act, tau(k) is drawn, the thrust profile
// of [t_k, t_k + T] is scheduled and the disturbances drawn. advance_plant then carries the truth
// through the period, in one go or stopping where a faster block needs the truth (sim/).
void begin_plant_period(const PlantParams& params, PlantState& state, const model::ThrusterCommand& command,
                        TimeNs t_k);
// From from_ns to to_ns within the period begun (t_k <= from_ns < to_ns <= t_k + T): the profile's
// pieces clipped to the interval. Stopping inside a piece splits its RK4 steps, nothing else.
void advance_plant(const PlantParams& params, PlantState& state, TimeNs from_ns, TimeNs to_ns);

// Propagates the truth over [t_k, t_k + T] under the command: both of the above.
void step_plant(const PlantParams& params, PlantState& state, const model::ThrusterCommand& command, TimeNs t_k);

}  // namespace chaser::plant
