#include "flight/fdi/watched_set.hpp"

#include <cassert>

namespace chaser::flight::fdi {

WatchedSet watched_set(model::ThrusterMask mask) {
  assert(model::thruster_count(mask) == kWatchedThrusters);
  const model::ThrusterList list = model::thruster_list(mask);
  WatchedSet w;
  w.mask = mask;
  for (int k = 0; k < kWatchedThrusters; ++k) w.index[static_cast<std::size_t>(k)] = list.index[static_cast<std::size_t>(k)];
  return w;
}

}  // namespace chaser::flight::fdi
