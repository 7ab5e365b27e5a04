#include "model/recovery.hpp"

#include <algorithm>

namespace chaser::model {

ThrusterConfiguration initial_configuration(const ThrusterSetParams& set) {
  return ThrusterConfiguration{.active = initial_active_set(set), .closed_groups = 0};
}

namespace {

std::optional<ThrusterConfiguration> exclude(const ThrusterSetParams& set, const ThrusterConfiguration& now,
                                             int faulty) {
  const ThrusterMask start = initial_active_set(set);
  if (now.active != start || (start & thruster_bit(faulty)) == 0) return std::nullopt;
  return ThrusterConfiguration{.active = start & ~thruster_bit(faulty), .closed_groups = now.closed_groups};
}

}  // namespace

std::optional<ThrusterConfiguration> recover(const ThrusterSetParams& set, RecoveryPolicy policy,
                                             const ThrusterConfiguration& now, int faulty) {
  if (faulty < 0 || faulty >= set.count) return std::nullopt;
  if (policy == RecoveryPolicy::kExclude) return exclude(set, now, faulty);
  if (policy != RecoveryPolicy::kSwitchGroup) return std::nullopt;
  const int group = set.thrusters[static_cast<std::size_t>(faulty)].group;
  if (group == kNoGroup || ((now.closed_groups >> group) & 1U) != 0) return std::nullopt;
  for (int g = 0; g < static_cast<int>(set.groups.size()); ++g) {
    const ThrusterMask members = group_thrusters(set, g);
    const bool unused = set.groups[static_cast<std::size_t>(g)].standby && (now.active & members) == 0 &&
                        ((now.closed_groups >> g) & 1U) == 0;
    if (!unused) continue;
    return ThrusterConfiguration{.active = (now.active & ~group_thrusters(set, group)) | members,
                                 .closed_groups = now.closed_groups | (std::uint32_t{1} << group)};
  }
  return std::nullopt;
}

std::vector<ReachableConfiguration> reachable_configurations(const ThrusterSetParams& set, RecoveryPolicy policy) {
  std::vector<ReachableConfiguration> found{{initial_configuration(set), kNoGroup}};
  for (std::size_t q = 0; q < found.size(); ++q) {
    const ThrusterConfiguration now = found[q].configuration;  // a copy: `found` grows below
    const ThrusterList list = thruster_list(now.active);
    for (int k = 0; k < list.count; ++k) {
      const auto next = recover(set, policy, now, list.index[k]);
      if (!next) continue;
      const bool seen = std::any_of(found.begin(), found.end(),
                                    [&](const ReachableConfiguration& r) { return r.configuration.active == next->active; });
      if (seen) continue;
      const int faulty = list.index[k];
      if (policy == RecoveryPolicy::kExclude)
        found.push_back({*next, kNoGroup, faulty});
      else
        found.push_back({*next, set.thrusters[static_cast<std::size_t>(faulty)].group, kNoThruster});
    }
  }
  return found;
}

std::string when_it_flies(const ThrusterSetParams& set, const ReachableConfiguration& reachable) {
  if (reachable.excluded_thruster != kNoThruster)
    return "the set that flies without " + thruster_name(reachable.excluded_thruster) + " (fdi.recovery: exclude)";
  if (reachable.failed_group == kNoGroup) return "the set that flies at the start";
  return "the set that flies after a fault in group " + set.groups[static_cast<std::size_t>(reachable.failed_group)].name +
         " (fdi.recovery: switch_group)";
}

}  // namespace chaser::model
