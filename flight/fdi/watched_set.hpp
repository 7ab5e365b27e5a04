#pragma once
// The thrusters the on-board FDI watches: the active set, in compact order (the k-th active
// thruster by index is lane k). Lane k's thruster index is WatchedSet::index[k].
//
// Two lane widths. Chaser's deficit bank and detector watch any active set of 1..kMaxThrusters
// (MSR's branch of eight, COMRADE's 24): their per-thruster sums and fits are stored at the
// capacity, kMaxWatchedThrusters lanes, and loop over the set's `count` (WatchedTon and the
// Deficit* types). The Fonod 2015 schemes' isolation (eqs. 42-45, the signature variant) keeps
// fixed lanes of exactly kSchemeThrusters (SchemeTon, Mat3W, VecW); validate_scenario refuses
// fdi.position or fdi.attitude on an active set of another size (model/fdi.hpp).
#include <Eigen/Core>
#include <array>
#include <type_traits>

#include "model/fdi.hpp"
#include "model/thrusters.hpp"

namespace chaser::flight::fdi {

inline constexpr int kSchemeThrusters = model::kFdiSchemeThrusters;
inline constexpr int kMaxWatchedThrusters = model::kMaxThrusters;

// The Fonod 2015 schemes' lanes (the first kSchemeThrusters of a watched set of that size).
using SchemeTon = Eigen::Matrix<double, kSchemeThrusters, 1>;     // [-] on-times, one per lane
using SchemeConfig = Eigen::Matrix<double, 6, kSchemeThrusters>;  // M of the watched set [N; N m]
using Mat3W = Eigen::Matrix<double, 3, kSchemeThrusters>;
using VecW = Eigen::Matrix<double, kSchemeThrusters, 1>;

// [-] commanded on-times of the watched lanes, at the capacity: lanes [count, kMaxWatchedThrusters)
// are zero.
using WatchedTon = Eigen::Matrix<double, kMaxWatchedThrusters, 1>;

// Which thrusters the lanes are.
struct WatchedSet {
  model::ThrusterMask mask = 0;
  int count = 0;                                  // lanes in use
  std::array<int, kMaxWatchedThrusters> index{};  // lane -> thruster index
  // thruster index -> lane, -1 for a thruster outside the set
  std::array<int, model::kMaxThrusters> lane = [] {
    std::array<int, model::kMaxThrusters> none{};
    none.fill(-1);
    return none;
  }();
};

// The lanes of `mask` (1..kMaxThrusters thrusters).
WatchedSet watched_set(model::ThrusterMask mask);

// Calls f(n) with the lane count n as a compile-time constant for a set of kSchemeThrusters (MSR's
// branch: the per-period loops unrolled and the block sums vectorised as in the eight-lane
// kernels, so MSR's FDIR costs what it did) and as an int for any other count.
template <class F>
inline void with_lanes(int lanes, F&& f) {
  if (lanes == kSchemeThrusters)
    f(std::integral_constant<int, kSchemeThrusters>{});
  else
    f(lanes);
}

}  // namespace chaser::flight::fdi
