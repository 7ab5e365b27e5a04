#include "model/recovery.hpp"

namespace chaser::model {

ThrusterConfiguration initial_configuration(const ThrusterSetParams& set) {
  return ThrusterConfiguration{.active = initial_active_set(set), .closed_groups = 0};
}

std::optional<ThrusterConfiguration> recover(const ThrusterSetParams& set, RecoveryPolicy policy,
                                             const ThrusterConfiguration& now, int faulty) {
  if (policy != RecoveryPolicy::kSwitchGroup || faulty < 0 || faulty >= set.count) return std::nullopt;
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

}  // namespace chaser::model
