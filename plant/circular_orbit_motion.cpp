#include "plant/circular_orbit_motion.hpp"

#include <algorithm>

namespace chaser::plant {

CircularOrbitParams make_circular_orbit_params(const model::Scenario& scenario) {
  return {.dynamics = make_dynamics_params(scenario), .target = scenario.target};
}

void advance(const CircularOrbitParams& params, CircularOrbitState&, RigidState& chaser, const ThrustProfile& profile,
             const PeriodDisturbance& disturbance, TimeNs from_ns, TimeNs to_ns) {
  for (int i = 0; i < profile.count; ++i) {
    const ThrustPiece& piece = profile.pieces[i];
    const TimeNs begin_ns = std::max(piece.t_begin_ns, from_ns), end_ns = std::min(piece.t_end_ns, to_ns);
    if (end_ns <= begin_ns) continue;
    propagate_piece(params.dynamics, chaser, to_seconds(begin_ns), to_seconds(end_ns - begin_ns),
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

std::span<const model::SloshState> slosh_states(const CircularOrbitParams&, const CircularOrbitState&) { return {}; }

}  // namespace chaser::plant
