#pragma once
// The thrusters the on-board FDI watches: the active set, in compact order (the k-th active
// thruster by index is lane k). The Fonod 2015 schemes' isolation and Chaser's deficit bank and
// detector keep per-thruster sums and fits in fixed-size lanes, vectorised over exactly
// kWatchedThrusters of them (MSR's branch of eight); validate_scenario refuses an FDI on an active
// set of another size (model/fdi.hpp). Lane k's thruster index is WatchedSet::index[k].
#include <Eigen/Core>
#include <array>

#include "model/fdi.hpp"
#include "model/thrusters.hpp"

namespace chaser::flight::fdi {

inline constexpr int kWatchedThrusters = model::kFdiWatchedThrusters;

using WatchedTon = Eigen::Matrix<double, kWatchedThrusters, 1>;     // [-] on-times, one per lane
using WatchedConfig = Eigen::Matrix<double, 6, kWatchedThrusters>;  // M of the watched set [N; N m]
using Mat3W = Eigen::Matrix<double, 3, kWatchedThrusters>;
using VecW = Eigen::Matrix<double, kWatchedThrusters, 1>;

// Which thrusters the lanes are.
struct WatchedSet {
  model::ThrusterMask mask = 0;
  std::array<int, kWatchedThrusters> index{};  // lane -> thruster index
};

// The lanes of `mask`, which must hold exactly kWatchedThrusters thrusters.
WatchedSet watched_set(model::ThrusterMask mask);

}  // namespace chaser::flight::fdi
