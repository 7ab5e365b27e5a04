#pragma once
// geometry.json of a run: what a picture of the run needs from its scenario and the telemetry does
// not carry (`chaser view`, docs/view.md): the chaser's thrusters and bus, the target's shape and
// fixture, the LVLH frame's turn. Written beside telemetry and summary.json by `chaser run` and
// chaser.run(out=...); read by view/. Nothing in it is computed by the run.
#include <nlohmann/json.hpp>

#include "model/scenario.hpp"

namespace chaser::sim {

// The scenario's geometry as geometry.json holds it (keys and units in docs/view.md):
//  - "lvlh": the LVLH frame in the run's inertial frame, which is LVLH at t = 0, turning about z at
//    "mean_motion_radps" (exact for the circular orbit; with orbit.earth, the perturbed orbit's frame
//    turns at a rate that departs from n by the perturbations: "exact" says which);
//  - "chaser": its centre of mass, keep-out radius, the bus as the box the thrusters' nozzles bound,
//    every thruster (name, position, direction, thrust, group, standby), the arm's mount if any;
//  - "target": whether it is a rigid body, its keep-out boxes (the body's shape), grasp and capture
//    points, and its fixture: "ring" (a grasp on a ring's rim), "drogue" (berthing) or none.
nlohmann::json run_geometry(const model::Scenario& scenario);

}  // namespace chaser::sim
