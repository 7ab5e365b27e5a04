#include "plant/rigid_body.hpp"

namespace chaser::plant {

Vec3 angular_momentum_inertial(const Mat3& inertia, const Quat& q, const Vec3& omega) {
  return q * (inertia * omega);
}

double rotational_energy(const Mat3& inertia, const Vec3& omega) { return 0.5 * omega.dot(inertia * omega); }

}  // namespace chaser::plant
