#include "model/keep_out.hpp"

#include <algorithm>
#include <limits>

namespace chaser::model {

// Per box, with q = |p - c| - h per axis: outside, |max(q, 0)| (the nearest point clamps each
// axis to the box); inside (every q <= 0), the largest q, minus the depth to the nearest face.
double keep_out_distance_m(const std::vector<KeepOutBox>& boxes, const Vec3& point_target_m) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const KeepOutBox& box : boxes) {
    const Vec3 q = (point_target_m - box.centre_target_m).cwiseAbs() - box.half_extents_m;
    const double outside = q.cwiseMax(0.0).norm();
    const double inside = std::min(q.maxCoeff(), 0.0);
    nearest = std::min(nearest, outside + inside);
  }
  return nearest;
}

}  // namespace chaser::model
