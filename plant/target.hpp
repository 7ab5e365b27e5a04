#pragma once
// The passive target's attitude: fixed, or turning at a constant inertial rate (a slow tumble).
// A constant inertial angular velocity w gives q_inertial_from_target(t) = exp(w t) * q(0); the
// target's orbit motion defines the LVLH origin and is not repeated here.
#include "core/types.hpp"
#include "model/spacecraft.hpp"

namespace chaser::plant {

Quat target_attitude(const model::TargetParams& target, double t_s);

// Its attitude and its rate in its own axes at t_s: the constant inertial w seen from the target,
// q(t)^-1 w (what telemetry records as omega_target_body).
struct TargetRotation {
  Quat q_inertial_from_target = Quat::Identity();
  Vec3 omega_body_radps = Vec3::Zero();  // [rad/s] inertial rate, target axes
};
TargetRotation target_rotation(const model::TargetParams& target, double t_s);

}  // namespace chaser::plant
