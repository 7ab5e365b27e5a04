#pragma once
// The target's keep-out volume (COMRADE 2018, Table 4: at least 3 m from the target's
// surface while the rotations are not synchronised, 0.5 m during synchronisation and capture): a
// union of boxes fixed in the target's axes, and the chaser as a sphere about its centre of mass.
#include <vector>

#include "core/types.hpp"

namespace chaser::model {

struct KeepOutBox {
  Vec3 centre_target_m = Vec3::Zero();     // [m] from the target's centre of mass, target axes
  Vec3 half_extents_m = Vec3::Constant(1.0);  // [m] each > 0
};

inline constexpr int kMaxKeepOutBoxes = 4;

// Signed distance from a point (target axes, from the target's CoM) to the union of the boxes:
// > 0 outside, the Euclidean distance to the nearest box; <= 0 inside one, minus the depth to its
// nearest face (for overlapping boxes, the least deep). +infinity for no boxes.
double keep_out_distance_m(const std::vector<KeepOutBox>& boxes, const Vec3& point_target_m);

}  // namespace chaser::model
