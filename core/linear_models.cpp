#include "core/linear_models.hpp"

#include "core/discretize.hpp"

namespace chaser {

Mat6 hcw_state_matrix(double n) {
  Mat6 a = Mat6::Zero();
  a.topRightCorner<3, 3>().setIdentity();
  a(3, 0) = 3.0 * n * n;  // gravity gradient minus centrifugal, radial
  a(3, 4) = 2.0 * n;      // Coriolis
  a(4, 3) = -2.0 * n;     // Coriolis
  a(5, 2) = -n * n;       // out-of-plane oscillation at the orbit rate
  return a;
}

Mat63 hcw_input_matrix() {
  Mat63 b = Mat63::Zero();
  b.bottomRows<3>().setIdentity();
  return b;
}

Vec3 hcw_acceleration(double n, const Vec3& r, const Vec3& v) {
  return Vec3(3.0 * n * n * r.x() + 2.0 * n * v.y(), -2.0 * n * v.x(), -n * n * r.z());
}

DiscreteLinear6 discrete_hcw(double mean_motion_radps, double period_s) {
  const DiscreteModel d = discretize_zoh(hcw_state_matrix(mean_motion_radps), hcw_input_matrix(), period_s);
  return DiscreteLinear6{d.Ad, d.Bd};
}

DiscreteLinear6 discrete_attitude(const Mat3& inertia_kgm2, double period_s) {
  Mat6 a = Mat6::Zero();
  a.topRightCorner<3, 3>().setIdentity();
  Mat63 b = Mat63::Zero();
  b.bottomRows<3>() = inertia_kgm2.inverse();
  const DiscreteModel d = discretize_zoh(a, b, period_s);
  return DiscreteLinear6{d.Ad, d.Bd};
}

}  // namespace chaser
