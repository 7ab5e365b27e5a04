#include "flight/thruster_management.hpp"

#include <algorithm>
#include <optional>

#include "flight/norm_allocation.hpp"
#include "model/thruster_geometry.hpp"

namespace chaser::flight {

ThrusterManagementParams make_thruster_management(const model::Scenario& scenario) {
  return ThrusterManagementParams{
      .thrusters = scenario.thrusters,
      .com_body_m = scenario.chaser.com_body_m,
      .min_on_fraction = scenario.thrusters.min_on_time_s / scenario.control_period_s,
      .norm = scenario.control.allocation_norm,
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

void set_uncommanded_thrust(const ThrusterManagementParams& params, ThrusterManagementState& state, int thruster,
                            double on_fraction) {
  if (thruster == model::kNoThruster || !(on_fraction > 0.0)) {
    state.uncommanded_thruster = model::kNoThruster;
    state.uncommanded_on_fraction = 0.0;
    state.uncommanded_wrench.setZero();
    return;
  }
  state.uncommanded_thruster = thruster;
  state.uncommanded_on_fraction = on_fraction;
  state.uncommanded_wrench =
      on_fraction * model::configuration_matrix(params.thrusters, model::thruster_bit(thruster), params.com_body_m).col(0);
}

namespace {

// The compact index of a thruster in the active list, -1 if it is not active.
int compact_index(const ThrusterManagementState& state, int thruster) {
  for (int k = 0; k < state.active_list.count; ++k)
    if (state.active_list.index[static_cast<std::size_t>(k)] == thruster) return k;
  return -1;
}

// The test pulse's allocation (cold: the floor changes the problem), if the demand stays attainable.
std::optional<AllocationResult> allocate_with_pulse(const ThrusterManagementState& state, const Vec6& demand_wrench,
                                                    const TestPulse& pulse) {
  if (pulse.thruster == model::kNoThruster) return std::nullopt;
  const int k = compact_index(state, pulse.thruster);
  if (k < 0) return std::nullopt;
  AllocationTon floor = AllocationTon::Zero();
  floor[k] = pulse.on_fraction;
  AllocationResult result = allocate_thrusters_floored(state.allocation, demand_wrench, floor);
  if (!result.feasible || !result.converged) return std::nullopt;
  return result;
}

}  // namespace

ThrusterManagementOutput manage_thrusters(const ThrusterManagementParams& params, ThrusterManagementState& state,
                                          const Vec6& demand_wrench, model::ThrusterOnTimes& ton_by_thruster,
                                          const TestPulse& pulse) {
  ThrusterManagementOutput out;
  // What the active set must give: the demand, less an excluded thruster's thrust where one fires.
  const bool uncommanded = state.uncommanded_thruster != model::kNoThruster;
  const Vec6 wanted = uncommanded ? Vec6(demand_wrench - state.uncommanded_wrench) : demand_wrench;
  std::optional<AllocationResult> pulsed = allocate_with_pulse(state, wanted, pulse);
  if (pulsed) out.pulsed = pulse.thruster;
  // While an excluded thruster fires, the least-propellant allocation would cancel it with whole-
  // period firings of a few thrusters (its LP's optimal vertex), leaving them no margin for the
  // loops; the least-peak one spreads the cancellation at about the same propellant (docs/fdi.md).
  const model::AllocationNorm norm =
      uncommanded && params.norm == model::AllocationNorm::kOne ? model::AllocationNorm::kInfinity : params.norm;
  AllocationResult result = pulsed ? *pulsed : allocate_thrusters(state.allocation, wanted, norm, state.warm);
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
  if (uncommanded) out.commanded_wrench += state.uncommanded_wrench;
  std::fill_n(ton_by_thruster.begin(), params.thrusters.count, 0.0);
  for (int k = 0; k < n; ++k)
    ton_by_thruster[static_cast<std::size_t>(state.active_list.index[static_cast<std::size_t>(k)])] = ton[k];
  return out;
}

}  // namespace chaser::flight
