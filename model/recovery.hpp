#pragma once
// What a recovery does to the thrusters that fly (the active set) and to the latch valves, as a
// function of the policy and the confirmed faulty thruster. The flight software's supervisor
// applies it (flight/fdir.cpp); scenario validation uses it to check in advance that every set a
// recovery can lead to can still push and turn in every direction.
#include <cstdint>
#include <optional>

#include "model/fdi.hpp"
#include "model/thrusters.hpp"

namespace chaser::model {

struct ThrusterConfiguration {
  ThrusterMask active = 0;              // thrusters the allocator may command
  std::uint32_t closed_groups = 0;      // bit g: group g's latch valve closed
};

// The configuration when a run starts: every non-standby thruster active, every latch open.
ThrusterConfiguration initial_configuration(const ThrusterSetParams& set);

// The configuration after the policy acts on a confirmed fault of `faulty` (an index), or nothing
// when it cannot act: kNone; kSwitchGroup when the thruster is in no group, its group is already
// closed, or no unused standby group is left. kSwitchGroup closes the faulty thruster's group latch
// (which also stops a stuck-open valve) and makes the first standby group not yet used active.
std::optional<ThrusterConfiguration> recover(const ThrusterSetParams& set, RecoveryPolicy policy,
                                             const ThrusterConfiguration& now, int faulty);

}  // namespace chaser::model
