#pragma once
// The truth a run starts from, and the synchronised reference judged against the truth: the
// chaser's state at t = 0 (on the approach axis at the start distance, at rest and pointing at the
// target; in the synchronised approach at its start point turning with the target; or as the
// scenario gives it, plus a campaign's dispersion), built from the scenario and the guidance's own
// closed forms so that a run starts where its flight software expects.
#include <optional>

#include "flight/guidance.hpp"
#include "model/scenario.hpp"
#include "model/target_orbit.hpp"
#include "plant/propagator.hpp"
#include "plant/target.hpp"

namespace chaser::sim {

// The synchronised reference from the truth (the target's true attitude, rate and Euler's rate
// derivative), for the run's start and its final judgement: the flight software's own follows its
// estimate instead. start_target_m: the transfer's start point in target axes, when the flight
// software fixed it (the approach steps); the scenario's otherwise.
flight::GuidanceRef true_sync_reference(const model::Scenario& s, const model::TargetOrbit& orbit,
                                        const plant::TargetRotation& target, double t_s,
                                        const std::optional<Vec3>& start_target_m = std::nullopt);

// The chaser's truth at t = 0.
plant::RigidState initial_truth(const model::Scenario& s, const model::TargetOrbit& orbit);

}  // namespace chaser::sim
