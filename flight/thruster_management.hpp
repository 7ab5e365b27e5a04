#pragma once
// Thruster management function (TMF, Fonod 2015 sec. II.C): turns the wrench released by the TMU
// into on-times of the active branch's eight thrusters with the least propellant, then respects
// the valves' minimum on-time, which the allocation itself does not know about.
#include <array>

#include "core/types.hpp"
#include "flight/thruster_allocation.hpp"
#include "model/messages.hpp"
#include "model/scenario.hpp"

namespace chaser::flight {

struct ThrusterManagementParams {
  std::array<AllocationParams, 2> allocation;  // per branch (A, B), nominal geometry and CoM
  double min_on_fraction = 0;                  // [-] min_on_time / T: shorter on-times are dropped
};

ThrusterManagementParams make_thruster_management(const model::Scenario& scenario);

struct ThrusterManagementOutput {
  model::ThrusterCommand command;  // all 16 thrusters; the inactive branch is zero
  model::Ton8 ton_active;          // on-times of the active branch
  Vec6 commanded_wrench;           // [N; N m] M ton: what the command realises if the thrusters are healthy
  bool feasible = true;            // the allocator reached the demand exactly
};

// `warm`: the active branch's warm start (flight state; one per branch, see AllocationWarmStart).
ThrusterManagementOutput manage_thrusters(const ThrusterManagementParams& params, int active_branch,
                                          const Vec6& demand_wrench, AllocationWarmStart& warm);

}  // namespace chaser::flight
