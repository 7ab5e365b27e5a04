#include "plant/target.hpp"

#include "core/rotation.hpp"

namespace chaser::plant {

Quat target_attitude(const model::TargetParams& target, double t_s) {
  return (quat_from_rotation_vector(target.omega_inertial_radps * t_s) * target.q_inertial_from_target).normalized();
}

TargetRotation target_rotation(const model::TargetParams& target, double t_s) {
  const Quat q = target_attitude(target, t_s);
  return {q, q.conjugate() * target.omega_inertial_radps};
}

}  // namespace chaser::plant
