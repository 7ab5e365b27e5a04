#include "flight/fdi/watched_set.hpp"

#include <cassert>

namespace chaser::flight::fdi {

WatchedSet watched_set(model::ThrusterMask mask) {
  const model::ThrusterList list = model::thruster_list(mask);
  assert(list.count >= 1 && list.count <= kMaxWatchedThrusters);
  WatchedSet w;
  w.mask = mask;
  w.count = list.count;
  for (int k = 0; k < list.count; ++k) {
    const int thruster = list.index[static_cast<std::size_t>(k)];
    w.index[static_cast<std::size_t>(k)] = thruster;
    w.lane[static_cast<std::size_t>(thruster)] = k;
  }
  return w;
}

}  // namespace chaser::flight::fdi
