#pragma once
// A plant's bodies handed from one motion model to another (a phase that changes the plant: the
// capture hands the rigid chaser and the target to a multibody plant when the arm wakes). The
// hand-over is relative to LVLH at its time, so neither side's inertial frame leaks into the
// other (the circle's is LVLH at t = 0, the Earth orbit's is the target's LVLH at t = 0 too but
// turns with the real orbit); the thrusters, their faults, the sensors, the noise streams and the
// propellant used are the plant's own and carry on unchanged.
#include <optional>
#include <string>

#include "core/types.hpp"
#include "model/scenario.hpp"
#include "model/target_orbit.hpp"
#include "plant/plant.hpp"

namespace chaser::plant {

struct HandoverState {
  double t_s = 0;                               // [s] run time
  Vec3 r_lvlh_m = Vec3::Zero();                 // [m] chaser relative to the target, LVLH
  Vec3 v_lvlh_mps = Vec3::Zero();               // [m/s] its rate in the rotating frame
  Quat q_lvlh_from_body = Quat::Identity();     // chaser attitude
  Vec3 omega_body_radps = Vec3::Zero();         // [rad/s] chaser inertial rate, body axes
  double mass_kg = 0;                           // [kg] chaser
  Quat q_lvlh_from_target = Quat::Identity();   // target attitude
  Vec3 omega_target_body_radps = Vec3::Zero();  // [rad/s] target inertial rate, target axes
};

// The bodies of `plant` at run time t_s (the time it is at), read through the seam.
HandoverState handover_state(const Plant& plant, const model::TargetOrbit& circle, double t_s);

// Replaces the plant's motion model by the one `scenario` describes, its bodies placed as `h`
// says. The circular orbit's target keeps the hand-over's inertial rate from then on (its model is
// a constant-rate spin). The perturbed Earth orbit starts its target from the scenario's orbital
// elements at t = 0, so it takes over at t = 0 only. Returns the reason it cannot, or nothing.
std::optional<std::string> hand_over(Plant& plant, const model::Scenario& scenario, const HandoverState& h,
                                     const model::TargetOrbit& circle);

// The perturbed Earth orbit hands its bodies to the multibody plant (plant/multibody_motion.hpp) at
// any time, in ECI as they are (no LVLH round trip: the reference point is the target's CoM, the hub
// is placed where the rigid chaser is), the arm stowed at chaser.arm.stowed_rad, at rest relative to
// the hub and locked there; its environment's samples carry on. scene_timestep_s: MuJoCo's step.
// Returns the reason it cannot (not on the Earth orbit now, multibody_problem), or nothing.
std::optional<std::string> hand_over_to_multibody(Plant& plant, const model::Scenario& scenario,
                                                  double scene_timestep_s = 1e-3);

// And back: the rigid chaser is the hub's chaser point (chaser.com_body_m), its attitude and rate
// the hub's; the target's orbit and attitude the target body's. The rigid chaser is the chaser with
// its arm stowed, so the arm must be there, at rest: within kStowedToleranceRad of
// chaser.arm.stowed_rad and kStowedToleranceRadps of rest at every joint (1e-4 rad moves the 80 kg
// arm's CoM by ~1.5e-4 m, the chaser's by ~7e-6 m).
inline constexpr double kStowedToleranceRad = 1e-4;    // [rad]
inline constexpr double kStowedToleranceRadps = 1e-4;  // [rad/s]
std::optional<std::string> hand_over_to_earth_orbit(Plant& plant, const model::Scenario& scenario);

}  // namespace chaser::plant
