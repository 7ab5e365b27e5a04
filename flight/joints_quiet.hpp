#pragma once
// Whether the arm is quiet enough for its brakes: every joint slower than a threshold (the
// rigidisation's and the escape's engagement test; the brakes' catch of the joints' last motion
// loads them in proportion to it).
#include <cmath>
#include <cstddef>
#include <numbers>

#include "model/messages.hpp"

namespace chaser::flight {

inline bool joints_slower_than(const model::ArmMeasurements& joints, double rate_degps) {
  const double threshold_radps = rate_degps * std::numbers::pi / 180.0;
  for (int j = 0; j < joints.joints; ++j)
    if (!(std::abs(joints.q_dot_radps[static_cast<std::size_t>(j)]) < threshold_radps)) return false;
  return true;
}

}  // namespace chaser::flight
