#pragma once
// Thruster hardware description (Fonod 2015, section II.C, eq. 2), for any set of 1..kMaxThrusters
// thrusters. Thrusters are numbered by their index 0..N-1 inside the code, kNoThruster (-1) for
// none, and named T1..TN at every boundary (thruster_name); tables of numbers (telemetry.csv,
// runs.csv) hold the n of Tn and 0 for none (docs/style.md, "Naming and layout").
//
// Redundancy groups: a thruster may belong to a group that sits behind its own latch valve (MSR's
// branches A and B). A standby group does not fly until a recovery opens it (cold redundancy);
// the thrusters that fly at a time are the active set, a ThrusterMask.
#include <array>
#include <bit>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/types.hpp"

namespace chaser::model {

// Compile-time capacity: every per-thruster array in the hot path has this size and uses the
// first `count` entries (docs/architecture.md, "Thrusters, the active set and recovery").
inline constexpr int kMaxThrusters = 32;
inline constexpr int kNoThruster = -1;
inline constexpr int kNoGroup = -1;

using ThrusterMask = std::uint32_t;  // bit i set: thruster i (T(i+1)) is in the set
static_assert(kMaxThrusters <= 32, "ThrusterMask holds one bit per thruster");

inline constexpr ThrusterMask thruster_bit(int index) { return ThrusterMask{1} << index; }
inline constexpr bool has_thruster(ThrusterMask mask, int index) { return ((mask >> index) & 1U) != 0; }
inline constexpr int thruster_count(ThrusterMask mask) { return std::popcount(mask); }
inline constexpr ThrusterMask first_thrusters(int count) {
  return count >= 32 ? ~ThrusterMask{0} : (ThrusterMask{1} << count) - 1U;
}

using ThrusterOnTimes = std::array<double, kMaxThrusters>;  // scaled on-times by index, 0..1

struct ThrusterParams {
  Vec3 position_body_m = Vec3::Zero();      // [m] nozzle position from the body reference point
  Vec3 direction_body = Vec3::UnitX();      // unit vector of the force the thruster produces
  double max_thrust_N = 22.0;               // [N] nominal thrust when open
  int group = kNoGroup;                     // index into ThrusterSetParams::groups, kNoGroup: none
};

struct ThrusterGroup {
  std::string name;      // as in the scenario ("A", "B")
  bool standby = false;  // held out of the active set until a recovery switches to it
};

struct ThrusterSetParams {
  int count = 0;                                      // N, 1..kMaxThrusters
  std::array<ThrusterParams, kMaxThrusters> thrusters{};  // [0, count) used
  std::vector<ThrusterGroup> groups;                  // redundancy groups, in scenario order
  bool tolerates_single_loss = false;  // required: every single-thruster loss leaves a spanning set
  double delay_max_s = 0.02;          // [s] drive-electronics delay tau(k) drawn uniformly in [0, max)
  double rise_time_s = 0.005;         // [s] valve opening ramp (modelled as its equivalent delay)
  double min_on_time_s = 0.005;       // [s] commands shorter than this do not open the valve
  double min_off_time_s = 0.005;      // [s] off-gaps shorter than this keep the valve open
  double thrust_sigma = 0.0;          // [-] 1-sigma relative thrust dispersion, drawn per run
  double misalignment_sigma_rad = 0.0;  // [rad] 1-sigma direction misalignment, drawn per run
};

// The thrusters of the set / of group g.
ThrusterMask all_thrusters(const ThrusterSetParams& set);
ThrusterMask group_thrusters(const ThrusterSetParams& set, int group);

// The active set when a run starts: every thruster outside a standby group.
ThrusterMask initial_active_set(const ThrusterSetParams& set);

// "T1".."TN" for indices 0..N-1, "none" for kNoThruster.
std::string thruster_name(int index);
// And back: the index of "T1".."T32" (kMaxThrusters); none for any other text. Whether the scenario
// has that many thrusters is the caller's to check.
std::optional<int> thruster_index(std::string_view name);
// The same thruster in a table of numbers: n of its name Tn, 0 for kNoThruster; and back (any
// number below 1 reads as none: runs.csv files written before this rule used -1).
inline int thruster_number(int index) { return index == kNoThruster ? 0 : index + 1; }
inline int thruster_index_from_number(long long number) { return number >= 1 ? static_cast<int>(number - 1) : kNoThruster; }

// The indices of a mask's thrusters in increasing order (its compact numbering: the k-th active
// thruster has compact index k).
struct ThrusterList {
  std::array<int, kMaxThrusters> index{};
  int count = 0;
};
ThrusterList thruster_list(ThrusterMask mask);

}  // namespace chaser::model
