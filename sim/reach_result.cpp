#include "sim/reach_result.hpp"

#include <numbers>

namespace chaser::sim {

bool gripper_meets_table2(const ReachResult& r) {
  constexpr double kDeg = std::numbers::pi / 180.0;
  if (!r.flown || r.hold_periods == 0) return false;
  for (int k = 0; k < 3; ++k)
    if (r.max_gripper_error_m(k) > kTable2GripperErrorM[k] || r.max_gripper_attitude_rad(k) > kTable2GripperAttitudeDeg * kDeg ||
        r.max_gripper_velocity_mps(k) > kTable2GripperVelocityMps || r.max_gripper_rate_radps(k) > kTable2GripperRateDegps * kDeg)
      return false;
  return true;
}

}  // namespace chaser::sim
