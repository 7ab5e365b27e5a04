#include "model/thrusters.hpp"

#include <string>

#include <fmt/format.h>

namespace chaser::model {

ThrusterMask all_thrusters(const ThrusterSetParams& set) { return first_thrusters(set.count); }

ThrusterMask group_thrusters(const ThrusterSetParams& set, int group) {
  ThrusterMask mask = 0;
  for (int i = 0; i < set.count; ++i)
    if (set.thrusters[static_cast<std::size_t>(i)].group == group) mask |= thruster_bit(i);
  return mask;
}

ThrusterMask initial_active_set(const ThrusterSetParams& set) {
  ThrusterMask mask = all_thrusters(set);
  for (int g = 0; g < static_cast<int>(set.groups.size()); ++g)
    if (set.groups[static_cast<std::size_t>(g)].standby) mask &= ~group_thrusters(set, g);
  return mask;
}

// fmt, not "T" + std::to_string: GCC 12 -O3 warns falsely (-Wrestrict) on that operator+.
std::string thruster_name(int index) { return index < 0 ? std::string("none") : fmt::format("T{}", index + 1); }

std::optional<int> thruster_index(std::string_view name) {
  for (int i = 0; i < kMaxThrusters; ++i)
    if (name == thruster_name(i)) return i;
  return std::nullopt;
}

ThrusterList thruster_list(ThrusterMask mask) {
  ThrusterList list;
  for (int i = 0; mask != 0; ++i, mask >>= 1)
    if (mask & 1U) list.index[static_cast<std::size_t>(list.count++)] = i;
  return list;
}

}  // namespace chaser::model
