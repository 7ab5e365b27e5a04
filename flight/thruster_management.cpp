#include "flight/thruster_management.hpp"

#include <algorithm>

#include "model/thruster_geometry.hpp"

namespace chaser::flight {

ThrusterManagementParams make_thruster_management(const model::Scenario& scenario) {
  return ThrusterManagementParams{
      .thrusters = scenario.thrusters,
      .com_body_m = scenario.chaser.com_body_m,
      .min_on_fraction = scenario.thrusters.min_on_time_s / scenario.control_period_s,
  };
}

void set_active_thrusters(const ThrusterManagementParams& params, ThrusterManagementState& state,
                          model::ThrusterMask active) {
  state.active = active;
  state.active_list = model::thruster_list(active);
  state.allocation.config = model::configuration_matrix(params.thrusters, active, params.com_body_m);
  state.allocation.thrusters = state.active_list.count;
  state.warm = AllocationWarmStart{};
}

ThrusterManagementOutput manage_thrusters(const ThrusterManagementParams& params, ThrusterManagementState& state,
                                          const Vec6& demand_wrench, model::ThrusterOnTimes& ton_by_thruster) {
  ThrusterManagementOutput out;
  AllocationResult result = allocate_thrusters(state.allocation, demand_wrench, state.warm);
  const int n = state.active_list.count;
  AllocationTon& ton = result.ton;  // compact order: the k-th active thruster
  // An on-time the valve cannot realise is dropped; the TMU keeps the missing impulse for later.
  for (int k = 0; k < n; ++k)
    if (ton[k] < params.min_on_fraction) ton[k] = 0.0;
  out.feasible = result.feasible;
  if (n == 8) {  // fixed-size product for eight (MSR's branch): same sums, no dynamic loop
    out.commanded_wrench = state.allocation.config.leftCols<8>() * ton.head<8>();
  } else {  // any other set: the columns of the thrusters that fire (a few of 24), lowest first
    out.commanded_wrench.setZero();
    for (int k = 0; k < n; ++k)
      if (ton[k] != 0.0) out.commanded_wrench += ton[k] * state.allocation.config.col(k);
  }
  std::fill_n(ton_by_thruster.begin(), params.thrusters.count, 0.0);
  for (int k = 0; k < n; ++k)
    ton_by_thruster[static_cast<std::size_t>(state.active_list.index[static_cast<std::size_t>(k)])] = ton[k];
  return out;
}

}  // namespace chaser::flight
