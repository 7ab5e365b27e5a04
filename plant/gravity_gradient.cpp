#include "plant/gravity_gradient.hpp"

#include <cmath>

namespace chaser::plant {

double gravity_gradient_gain(double mu, double r2) { return 3.0 * mu / (r2 * r2 * std::sqrt(r2)); }

Vec3 gravity_gradient_torque_body(double gain, const Vec3& r, const Mat3& inertia) {
  return gain * r.cross(inertia * r);
}

}  // namespace chaser::plant
