#pragma once
// The plant's motion on the scenario's circular orbit: the chaser relative to the target in LVLH
// (Fonod 2015, eq. 8, in plant/relative_orbit.hpp) and its rigid-body rotation, the target's
// attitude a constant-rate spin in closed form (plant/target.hpp). The chaser's rigid state is all
// the state it has; the run's inertial frame is LVLH at t = 0. One of the plant's motion models
// (plant/plant.hpp, "the seam").
#include <span>

#include "core/time.hpp"
#include "model/scenario.hpp"
#include "model/target_orbit.hpp"
#include "plant/period_input.hpp"
#include "plant/propagator.hpp"
#include "model/slosh.hpp"
#include "plant/target.hpp"

namespace chaser::plant {

struct CircularOrbitState {};

struct CircularOrbitParams {
  using State = CircularOrbitState;
  DynamicsParams dynamics;
  model::TargetParams target;
};

CircularOrbitParams make_circular_orbit_params(const model::Scenario& scenario);

// The period at t_k begins: nothing to prepare on the circle.
inline void begin_period(const CircularOrbitParams&, CircularOrbitState&, const RigidState&, TimeNs, TimeNs) {}

// Each constant piece of the period's thrust profile within [from_ns, to_ns], from one edge (or
// stop) to the next.
void advance(const CircularOrbitParams& params, CircularOrbitState& state, RigidState& chaser,
             const ThrustProfile& profile, const PeriodDisturbance& disturbance, TimeNs from_ns, TimeNs to_ns);

TargetRotation target_rotation(const CircularOrbitParams& params, const CircularOrbitState& state, double t_s);

// LVLH in the run's inertial frame: the circle's own turn.
Quat q_inertial_from_lvlh(const CircularOrbitParams& params, const CircularOrbitState& state,
                          const model::TargetOrbit& circle, double t_s);

std::span<const model::SloshState> slosh_states(const CircularOrbitParams& params, const CircularOrbitState& state);

}  // namespace chaser::plant
