#pragma once
// What a recovery does to the thrusters that fly (the active set) and to the latch valves, as a
// function of the policy and the confirmed faulty thruster. The flight software's supervisor
// applies it (flight/fdir.cpp); scenario validation uses it to check in advance that every set a
// recovery can lead to can still push and turn in every direction.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

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
// closed, or no unused standby group is left; kExclude when the thruster is not active or a thruster
// has already been excluded. kSwitchGroup closes the faulty thruster's group latch (which also stops
// a stuck-open valve) and makes the first standby group not yet used active. kExclude takes the
// thruster out of the active set and closes nothing: a stuck-open valve keeps firing, and the flight
// software cancels its thrust (flight/thruster_management.hpp). It acts once per run, so that every
// set it can lead to is known in advance (validated to push and turn everywhere, watched by the FDI).
std::optional<ThrusterConfiguration> recover(const ThrusterSetParams& set, RecoveryPolicy policy,
                                             const ThrusterConfiguration& now, int faulty);

// A configuration the vehicle may fly, and the fault that led to it.
struct ReachableConfiguration {
  ThrusterConfiguration configuration;
  int failed_group = kNoGroup;           // group of the fault whose recovery led here; kNoGroup: the start
  int excluded_thruster = kNoThruster;   // kExclude: the thruster taken out to get here
};

// The starting configuration, then every configuration the policy can lead to by faults of active
// thrusters, one after another (breadth first), each active set once. What validation checks,
// what the FDI prepares parameters for, what the TMU's clamp and `chaser thrusters` cover.
std::vector<ReachableConfiguration> reachable_configurations(const ThrusterSetParams& set, RecoveryPolicy policy);

// How reports name it: "the set that flies at the start", "the set that flies after a fault in
// group A (fdi.recovery: switch_group)", "the set that flies without T3 (fdi.recovery: exclude)".
std::string when_it_flies(const ThrusterSetParams& set, const ReachableConfiguration& reachable);

}  // namespace chaser::model
