#include "plant/handover.hpp"

#include <cmath>

#include <fmt/format.h>

#include "core/rotation.hpp"

namespace chaser::plant {

HandoverState handover_state(const Plant& plant, const model::TargetOrbit& circle, double t_s) {
  const RigidState& chaser = chaser_state(plant);
  const Quat q_lvlh_from_inertial = q_inertial_from_lvlh(plant, circle, t_s).conjugate();
  const TargetRotation target = target_rotation(plant, t_s);
  return HandoverState{
      .t_s = t_s,
      .r_lvlh_m = chaser.r_lvlh_m,
      .v_lvlh_mps = chaser.v_lvlh_mps,
      .q_lvlh_from_body = (q_lvlh_from_inertial * chaser.q_inertial_from_body).normalized(),
      .omega_body_radps = chaser.omega_body_radps,
      .mass_kg = chaser.mass_kg,
      .q_lvlh_from_target = (q_lvlh_from_inertial * target.q_inertial_from_target).normalized(),
      .omega_target_body_radps = target.omega_body_radps,
  };
}

namespace {

void place_chaser(RigidState& chaser, const HandoverState& h, const Quat& q_inertial_from_lvlh) {
  chaser.r_lvlh_m = h.r_lvlh_m;
  chaser.v_lvlh_mps = h.v_lvlh_mps;
  chaser.q_inertial_from_body = (q_inertial_from_lvlh * h.q_lvlh_from_body).normalized();
  chaser.omega_body_radps = h.omega_body_radps;
  chaser.mass_kg = h.mass_kg;
}

// The circle's target spins at a constant inertial rate w: q(t) = exp(w t) q(0) (plant/target.hpp),
// so the spin that passes through the hand-over's attitude at t_s starts from exp(-w t_s) q(t_s).
CircularOrbitParams circular_take_over(const model::Scenario& scenario, const HandoverState& h,
                                       const model::TargetOrbit& circle) {
  CircularOrbitParams params = make_circular_orbit_params(scenario);
  const Quat q_inertial_from_target = (circle.q_inertial_from_lvlh(h.t_s) * h.q_lvlh_from_target).normalized();
  const Vec3 omega_inertial_radps = q_inertial_from_target * h.omega_target_body_radps;
  params.target.omega_inertial_radps = omega_inertial_radps;
  params.target.q_inertial_from_target =
      (quat_from_rotation_vector(-omega_inertial_radps * h.t_s) * q_inertial_from_target).normalized();
  return params;
}

}  // namespace

std::optional<std::string> hand_over(Plant& plant, const model::Scenario& scenario, const HandoverState& h,
                                     const model::TargetOrbit& circle) {
  if (scenario.orbit.earth) {
    if (h.t_s != 0.0) return "the perturbed Earth-orbit plant takes over at t = 0 only (its target starts from orbit.earth)";
    const EarthOrbitParams params = make_earth_orbit_params(scenario);
    place_chaser(plant.state.chaser, h, Quat::Identity());  // the run's inertial axes are LVLH at t = 0
    EarthOrbitState state = start_earth_orbit(scenario, params, plant.state.chaser);
    state.orbit.q_inertial_from_target = h.q_lvlh_from_target;
    state.orbit.omega_target_body_radps = h.omega_target_body_radps;
    plant.params.motion = params;
    plant.state.motion = state;
    return std::nullopt;
  }
  place_chaser(plant.state.chaser, h, circle.q_inertial_from_lvlh(h.t_s));
  plant.params.motion = circular_take_over(scenario, h, circle);
  plant.state.motion = CircularOrbitState{};
  return std::nullopt;
}

std::optional<std::string> hand_over_to_multibody(Plant& plant, const model::Scenario& scenario,
                                                  double scene_timestep_s) {
  const auto* earth = std::get_if<EarthOrbitState>(&plant.state.motion);
  if (earth == nullptr) return "the multibody plant takes over from the perturbed Earth-orbit plant only";
  if (auto problem = multibody_problem(scenario)) return problem;
  MultibodyStart start = start_multibody(scenario, *earth, plant.state.chaser, scene_timestep_s);
  plant.params.motion = std::move(start.params);
  plant.state.motion = std::move(start.state);
  return std::nullopt;
}

std::optional<std::string> hand_over_to_earth_orbit(Plant& plant, const model::Scenario& scenario) {
  const auto* params = std::get_if<MultibodyMotionParams>(&plant.params.motion);
  if (params == nullptr) return "the perturbed Earth-orbit plant takes over mid-run from the multibody plant only";
  const auto& state = std::get<MultibodyMotionState>(plant.state.motion);
  const auto q = joint_angles_rad(*params, state), w = joint_rates_radps(*params, state);
  for (std::size_t j = 0; j < q.size(); ++j) {
    const double off_rad = q[j] - params->scene.arm.stowed_rad[j];
    if (std::abs(off_rad) > kStowedToleranceRad || std::abs(w[j]) > kStowedToleranceRadps)
      return fmt::format("the rigid chaser has its arm stowed: joint {} is {:.3g} rad from chaser.arm.stowed_rad, "
                         "turning at {:.3g} rad/s (at most {} rad and {} rad/s)",
                         j + 1, off_rad, w[j], kStowedToleranceRad, kStowedToleranceRadps);
  }
  EarthOrbitState earth = earth_orbit_state(state);
  plant.params.motion = make_earth_orbit_params(scenario);
  plant.state.motion = std::move(earth);
  return std::nullopt;
}

}  // namespace chaser::plant
