#include "core/hill_frames.hpp"

#include "core/rotation.hpp"

namespace chaser {

Vec3 lvlh_from_hill(const Vec3& v) { return msr_from_zhou(v); }
Vec3 hill_from_lvlh(const Vec3& v) { return zhou_from_msr(v); }

Vec6 lvlh_state_from_hill(const Vec6& x) {
  Vec6 y;
  y << lvlh_from_hill(x.head<3>()), lvlh_from_hill(x.tail<3>());
  return y;
}

Vec6 hill_state_from_lvlh(const Vec6& x) {
  Vec6 y;
  y << hill_from_lvlh(x.head<3>()), hill_from_lvlh(x.tail<3>());
  return y;
}

Quat q_lvlh_from_hill() { return Quat(0.5, -0.5, -0.5, 0.5); }
Quat q_hill_from_lvlh() { return Quat(0.5, 0.5, 0.5, -0.5); }

Vec3 omega_hill_in_hill(double n) { return Vec3(0.0, -n, 0.0); }

}  // namespace chaser
