// Recovery as a policy on the active set (model/recovery.hpp), and the thruster-set helpers it
// stands on, checked against configurations written out by hand.
#include "model/recovery.hpp"

#include <gtest/gtest.h>

namespace chaser::model {
namespace {

// `groups` groups of eight, the first active, the others on standby (MSR has two).
ThrusterSetParams grouped_set(int groups) {
  ThrusterSetParams set;
  set.count = 8 * groups;
  for (int g = 0; g < groups; ++g) set.groups.push_back({std::string(1, static_cast<char>('A' + g)), g > 0});
  for (int i = 0; i < set.count; ++i) set.thrusters[static_cast<std::size_t>(i)].group = i / 8;
  return set;
}

TEST(ThrusterSetHelpers, NamesMasksAndLists) {
  EXPECT_EQ(thruster_name(0), "T1");
  EXPECT_EQ(thruster_name(31), "T32");
  EXPECT_EQ(thruster_name(kNoThruster), "none");
  EXPECT_EQ(first_thrusters(8), 0xFFu);
  EXPECT_EQ(first_thrusters(32), 0xFFFFFFFFu);
  const ThrusterList list = thruster_list(0b1010'0001u);
  ASSERT_EQ(list.count, 3);
  EXPECT_EQ(list.index[0], 0);
  EXPECT_EQ(list.index[1], 5);
  EXPECT_EQ(list.index[2], 7);
  const ThrusterSetParams msr = grouped_set(2);
  EXPECT_EQ(group_thrusters(msr, 1), 0xFF00u);
  EXPECT_EQ(initial_active_set(msr), 0x00FFu);  // B on standby
}

// MSR: a fault anywhere in A closes A's latch and flies B; a fault in B then has nowhere to go.
TEST(Recovery, SwitchGroupClosesTheFaultyGroupAndOpensTheStandby) {
  const ThrusterSetParams set = grouped_set(2);
  const ThrusterConfiguration start = initial_configuration(set);
  EXPECT_EQ(start.active, 0x00FFu);
  EXPECT_EQ(start.closed_groups, 0u);
  for (int faulty = 0; faulty < 8; ++faulty) {
    const auto after = recover(set, RecoveryPolicy::kSwitchGroup, start, faulty);
    ASSERT_TRUE(after.has_value()) << faulty;
    EXPECT_EQ(after->active, 0xFF00u);
    EXPECT_EQ(after->closed_groups, 0b01u);
  }
  const ThrusterConfiguration on_b = *recover(set, RecoveryPolicy::kSwitchGroup, start, 3);
  EXPECT_FALSE(recover(set, RecoveryPolicy::kSwitchGroup, on_b, 11).has_value());  // no standby left
  EXPECT_FALSE(recover(set, RecoveryPolicy::kSwitchGroup, on_b, 3).has_value());   // A already closed
  EXPECT_FALSE(recover(set, RecoveryPolicy::kNone, start, 3).has_value());
  EXPECT_FALSE(recover(set, RecoveryPolicy::kSwitchGroup, start, kNoThruster).has_value());
  ThrusterSetParams ungrouped = set;
  ungrouped.thrusters[2].group = kNoGroup;  // no latch: nothing to close
  EXPECT_FALSE(recover(ungrouped, RecoveryPolicy::kSwitchGroup, initial_configuration(ungrouped), 2).has_value());
}

// Three groups: A, then B after a fault in A, then C after a fault in B; each set once.
TEST(Recovery, ReachableConfigurationsFollowFaultAfterFault) {
  const ThrusterSetParams set = grouped_set(3);
  const std::vector<ReachableConfiguration> r = reachable_configurations(set, RecoveryPolicy::kSwitchGroup);
  ASSERT_EQ(r.size(), 3u);
  EXPECT_EQ(r[0].configuration.active, 0x0000FFu);
  EXPECT_EQ(r[0].failed_group, kNoGroup);
  EXPECT_EQ(r[1].configuration.active, 0x00FF00u);
  EXPECT_EQ(r[1].failed_group, 0);
  EXPECT_EQ(r[2].configuration.active, 0xFF0000u);
  EXPECT_EQ(r[2].configuration.closed_groups, 0b011u);
  EXPECT_EQ(r[2].failed_group, 1);
  EXPECT_EQ(when_it_flies(set, r[0]), "the set that flies at the start");
  EXPECT_EQ(when_it_flies(set, r[2]), "the set that flies after a fault in group B (fdi.recovery: switch_group)");
  EXPECT_EQ(reachable_configurations(set, RecoveryPolicy::kNone).size(), 1u);  // only the start flies
}

// Exclude: the faulty thruster leaves the active set, its group's latch stays open (a stuck-open valve
// keeps firing), once per run; a standby group stays on standby; an inactive thruster is not acted on.
TEST(Recovery, ExcludeTakesTheThrusterOutOnce) {
  const ThrusterSetParams set = grouped_set(2);
  const ThrusterConfiguration start = initial_configuration(set);
  const auto without_t3 = recover(set, RecoveryPolicy::kExclude, start, 2);
  ASSERT_TRUE(without_t3.has_value());
  EXPECT_EQ(without_t3->active, 0x00FBu);
  EXPECT_EQ(without_t3->closed_groups, 0u);
  EXPECT_FALSE(recover(set, RecoveryPolicy::kExclude, *without_t3, 5).has_value());  // once per run
  EXPECT_FALSE(recover(set, RecoveryPolicy::kExclude, start, 9).has_value());        // T10: on standby
  EXPECT_FALSE(recover(set, RecoveryPolicy::kExclude, start, kNoThruster).has_value());
}

// Exclude reaches the start and each start set less one of its thrusters, named by that thruster.
TEST(Recovery, ExcludeReachesEverySingleExclusion) {
  const ThrusterSetParams set = grouped_set(1);
  const std::vector<ReachableConfiguration> r = reachable_configurations(set, RecoveryPolicy::kExclude);
  ASSERT_EQ(r.size(), 9u);
  EXPECT_EQ(r[0].configuration.active, 0xFFu);
  for (int k = 1; k <= 8; ++k) {
    EXPECT_EQ(r[static_cast<std::size_t>(k)].configuration.active, 0xFFu & ~thruster_bit(k - 1));
    EXPECT_EQ(r[static_cast<std::size_t>(k)].excluded_thruster, k - 1);
    EXPECT_EQ(r[static_cast<std::size_t>(k)].failed_group, kNoGroup);
  }
  EXPECT_EQ(when_it_flies(set, r[3]), "the set that flies without T3 (fdi.recovery: exclude)");
}

}  // namespace
}  // namespace chaser::model
