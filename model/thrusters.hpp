#pragma once
// Thruster hardware description (Fonod 2015, section II.C, eq. 2).
#include <array>

#include "core/types.hpp"

namespace chaser::model {

inline constexpr int kThrustersTotal = 16;     // two branches of eight
inline constexpr int kThrustersPerBranch = 8;

using Ton16 = std::array<double, kThrustersTotal>;  // scaled on-times, one per thruster, 0..1
using Ton8 = Eigen::Matrix<double, kThrustersPerBranch, 1>;
using ConfigMatrix = Eigen::Matrix<double, 6, kThrustersPerBranch>;  // M: [F_body; C_body] per unit on-time

struct ThrusterParams {
  Vec3 position_body_m = Vec3::Zero();      // [m] nozzle position from the body reference point
  Vec3 direction_body = Vec3::UnitX();      // unit vector of the force the thruster produces
  double max_thrust_N = 22.0;               // [N] nominal thrust when open
};

// Branch A is thrusters 0..7, branch B thrusters 8..15 (1-based names T1..T16 in files).
struct ThrusterSetParams {
  std::array<ThrusterParams, kThrustersTotal> thrusters{};
  double delay_max_s = 0.02;          // [s] drive-electronics delay tau(k) drawn uniformly in [0, max)
  double rise_time_s = 0.005;         // [s] valve opening ramp (modelled as its equivalent delay)
  double min_on_time_s = 0.005;       // [s] commands shorter than this do not open the valve
  double min_off_time_s = 0.005;      // [s] off-gaps shorter than this keep the valve open
  double thrust_sigma = 0.0;          // [-] 1-sigma relative thrust dispersion, drawn per run
  double misalignment_sigma_rad = 0.0;  // [rad] 1-sigma direction misalignment, drawn per run
};

inline int branch_first(int branch) { return branch * kThrustersPerBranch; }

}  // namespace chaser::model
