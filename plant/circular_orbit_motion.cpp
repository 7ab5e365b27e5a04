#include "plant/circular_orbit_motion.hpp"

namespace chaser::plant {

CircularOrbitParams make_circular_orbit_params(const model::Scenario& scenario) {
  return {.dynamics = make_dynamics_params(scenario), .target = scenario.target};
}

void propagate_period(const CircularOrbitParams& params, CircularOrbitState&, RigidState& chaser,
                      const ThrustProfile& profile, const PeriodDisturbance& disturbance, TimeNs, TimeNs) {
  for (int i = 0; i < profile.count; ++i) {
    const ThrustPiece& piece = profile.pieces[i];
    propagate_piece(params.dynamics, chaser, to_seconds(piece.t_begin_ns), to_seconds(piece.t_end_ns - piece.t_begin_ns),
                    piece_input(piece, disturbance));
  }
}

TargetRotation target_rotation(const CircularOrbitParams& params, const CircularOrbitState&, double t_s) {
  return target_rotation(params.target, t_s);
}

Quat q_inertial_from_lvlh(const CircularOrbitParams&, const CircularOrbitState&, const model::TargetOrbit& circle,
                          double t_s) {
  return circle.q_inertial_from_lvlh(t_s);
}

std::span<const SloshState> slosh_states(const CircularOrbitParams&, const CircularOrbitState&) { return {}; }

}  // namespace chaser::plant
