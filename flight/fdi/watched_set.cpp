#include "flight/fdi/watched_set.hpp"

#include <cassert>

namespace chaser::flight::fdi {

WatchedSet watched_set(model::ThrusterMask mask) {
  const model::ThrusterList list = model::thruster_list(mask);
  assert(list.count >= 1 && list.count <= kMaxWatchedThrusters);
  WatchedSet w;
  w.mask = mask;
  w.count = list.count;
  for (int k = 0; k < list.count; ++k) w.index[static_cast<std::size_t>(k)] = list.index[static_cast<std::size_t>(k)];
  return w;
}

}  // namespace chaser::flight::fdi
