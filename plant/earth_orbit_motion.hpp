#pragma once
// The plant's motion on a perturbed Earth orbit (scenario orbit.earth): both bodies in ECI under
// gravity to J2, drag, the Sun and the Moon, solar pressure and the environment's torques
// (plant/orbit_propagator.hpp), the target tumbling under its own torques, the chaser's slosh
// coupled in. The chaser's rigid state keeps its LVLH view (r_lvlh_m, v_lvlh_mps) derived from the
// orbit state at each period's end. One of the plant's motion models (plant/plant.hpp, "the seam").
#include <span>

#include "core/time.hpp"
#include "model/scenario.hpp"
#include "model/target_orbit.hpp"
#include "plant/orbit_plant.hpp"
#include "plant/period_input.hpp"
#include "plant/target.hpp"

namespace chaser::plant {

struct EarthOrbitState {
  OrbitState orbit;                         // both bodies in ECI, the target's attitude, the slosh
  EphemerisSamples ephemeris;               // the Sun's and the Moon's last samples
  SlowEnvironmentSample slow_environment;   // the slow terms of the current window
  PeriodEnvironment env;                    // the current period's (begin_period)
};

struct EarthOrbitParams {
  using State = EarthOrbitState;
  OrbitPlantParams earth;
};

// The motion and its state at t = 0 with the chaser at `chaser` (its LVLH view and attitude);
// refreshes the chaser's LVLH view from the orbit state (the same to rounding).
EarthOrbitParams make_earth_orbit_params(const model::Scenario& scenario);
EarthOrbitState start_earth_orbit(const model::Scenario& scenario, const EarthOrbitParams& params, RigidState& chaser);

// The environment of the period at t_k (its slow terms held per window, plant/orbit_propagator.hpp).
void begin_period(const EarthOrbitParams& params, EarthOrbitState& state, const RigidState& chaser, TimeNs t_k,
                  TimeNs period_ns);

// Each piece of the period's profile within [from_ns, to_ns], then the LVLH view at to_ns.
void advance(const EarthOrbitParams& params, EarthOrbitState& state, RigidState& chaser, const ThrustProfile& profile,
             const PeriodDisturbance& disturbance, TimeNs from_ns, TimeNs to_ns);

// The target's integrated attitude and rate now (t_s is the time the state is at).
TargetRotation target_rotation(const EarthOrbitParams& params, const EarthOrbitState& state, double t_s);

// LVLH in the run's inertial frame, from the orbit state (the circle is not this plant's).
Quat q_inertial_from_lvlh(const EarthOrbitParams& params, const EarthOrbitState& state,
                          const model::TargetOrbit& circle, double t_s);

std::span<const model::SloshState> slosh_states(const EarthOrbitParams& params, const EarthOrbitState& state);

}  // namespace chaser::plant
