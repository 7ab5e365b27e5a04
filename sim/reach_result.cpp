#include "sim/reach_result.hpp"

#include <array>
#include <cmath>
#include <numbers>

namespace chaser::sim {

void add_reach_period(ReachResult& r, const plant::GripperTruth& gripper, double t_s, double clearance_m) {
  constexpr double kTimeTolS = 1e-9;  // the hold's start is a sum of seconds, the period's start a count of ns
  r.flown = true;
  if (t_s + kTimeTolS >= r.hold_from_s) {
    r.max_gripper_error_m = r.max_gripper_error_m.cwiseMax(gripper.r_m.cwiseAbs());
    r.max_gripper_velocity_mps = r.max_gripper_velocity_mps.cwiseMax(gripper.v_mps.cwiseAbs());
    r.max_gripper_attitude_rad = r.max_gripper_attitude_rad.cwiseMax(gripper.attitude_rad.cwiseAbs());
    r.max_gripper_rate_radps = r.max_gripper_rate_radps.cwiseMax(gripper.omega_radps.cwiseAbs());
    ++r.hold_periods;
  }
  r.final_gripper = gripper;
  if (!(clearance_m >= r.min_tool_clearance_m)) {  // the first, NaN before it, or a smaller one
    if (std::isnan(clearance_m)) return;
    r.min_tool_clearance_m = clearance_m;
    r.min_tool_clearance_at_s = t_s;
  }
}

bool gripper_meets_table2(const ReachResult& r) {
  constexpr double kDeg = std::numbers::pi / 180.0;
  if (!r.flown || r.hold_periods == 0) return false;
  const std::array<Vec3, 4> figures = {r.max_gripper_error_m, r.max_gripper_velocity_mps,
                                       r.max_gripper_attitude_rad / kDeg, r.max_gripper_rate_radps / kDeg};
  for (int f = 0; f < 4; ++f)
    for (int k = 0; k < 3; ++k)
      if (figures[static_cast<std::size_t>(f)](k) > table2_gripper_limit(f, k)) return false;
  return true;
}

}  // namespace chaser::sim
