#include "flight/thruster_management.hpp"

#include "model/thruster_geometry.hpp"

namespace chaser::flight {

ThrusterManagementParams make_thruster_management(const model::Scenario& scenario) {
  ThrusterManagementParams params;
  for (int branch = 0; branch < 2; ++branch)
    params.allocation[branch].config =
        model::configuration_matrix(scenario.thrusters, branch, scenario.chaser.com_body_m);
  params.min_on_fraction = scenario.thrusters.min_on_time_s / scenario.control_period_s;
  return params;
}

ThrusterManagementOutput manage_thrusters(const ThrusterManagementParams& params, int active_branch,
                                          const Vec6& demand_wrench, AllocationWarmStart& warm) {
  ThrusterManagementOutput out;
  const AllocationParams& allocation = params.allocation[active_branch];
  const AllocationResult result = allocate_thrusters(allocation, demand_wrench, warm);
  out.ton_active = result.ton;
  // An on-time the valve cannot realise is dropped; the TMU keeps the missing impulse for later.
  for (int i = 0; i < model::kThrustersPerBranch; ++i)
    if (out.ton_active[i] < params.min_on_fraction) out.ton_active[i] = 0.0;
  out.feasible = result.feasible;
  out.commanded_wrench = allocation.config * out.ton_active;
  const int first = model::branch_first(active_branch);
  for (int i = 0; i < model::kThrustersPerBranch; ++i) out.command.ton[first + i] = out.ton_active[i];
  return out;
}

}  // namespace chaser::flight
