#pragma once
// Thruster management function (TMF, Fonod 2015 sec. II.C): turns the wrench released by the TMU
// into on-times of the active thrusters with the least propellant (or, by the scenario's choice, the
// least energy or peak: flight/norm_allocation.hpp), then respects the valves'
// minimum on-time, which the allocation itself does not know about. The active set is a mask that
// recovery may change (model/recovery.hpp); the allocation problem is rebuilt when it does.
#include "core/types.hpp"
#include "flight/thruster_allocation.hpp"
#include "model/messages.hpp"
#include "model/scenario.hpp"

namespace chaser::flight {

struct ThrusterManagementParams {
  model::ThrusterSetParams thrusters;  // nominal geometry
  Vec3 com_body_m = Vec3::Zero();      // [m] nominal centre of mass
  double min_on_fraction = 0;          // [-] min_on_time / T: shorter on-times are dropped
  model::AllocationNorm norm = model::AllocationNorm::kOne;  // what the on-times minimise
};

ThrusterManagementParams make_thruster_management(const model::Scenario& scenario);

// The allocation problem of the current active set (derived when the set changes) and its warm start.
struct ThrusterManagementState {
  model::ThrusterMask active = 0;
  model::ThrusterList active_list;  // compact index k -> thruster index
  AllocationParams allocation;      // M of the active set, compact columns
  AllocationWarmStart warm;         // optimal bases of this set's earlier demands
  // A thruster out of the active set that still fires on its own (excluded stuck open or leaking:
  // fdi.recovery: exclude), and the wrench it gives: the allocation cancels it.
  int uncommanded_thruster = model::kNoThruster;
  double uncommanded_on_fraction = 0;      // [-] its on-time every period
  Vec6 uncommanded_wrench = Vec6::Zero();  // [N; N m] body axes, about the nominal centre of mass
};

// Points the TMF at a new active set (outside the per-period path: at start and on recovery).
void set_active_thrusters(const ThrusterManagementParams& params, ThrusterManagementState& state,
                          model::ThrusterMask active);

// Records that `thruster` (out of the active set) keeps firing with on-time `on_fraction` every period
// whatever it is commanded: from then on each allocation asks the active set for the demand less
// that thruster's wrench, so that the two together give the demand (on_fraction 0: nothing to cancel).
void set_uncommanded_thrust(const ThrusterManagementParams& params, ThrusterManagementState& state, int thruster,
                            double on_fraction);

// An active check's test pulse (flight/active_check.hpp): a floor on one thruster's on-time.
struct TestPulse {
  int thruster = model::kNoThruster;  // index; kNoThruster or an inactive thruster: no pulse
  double on_fraction = 0;             // [-] the floor, at least min_on_fraction (validated)
};

struct ThrusterManagementOutput {
  // [N; N m] M ton, plus an excluded thruster's uncommanded wrench: what the vehicle's thrusters
  // give with this command if the active ones are healthy
  Vec6 commanded_wrench = Vec6::Zero();
  bool feasible = true;                  // the allocator reached the demand exactly
  int pulsed = model::kNoThruster;       // the thruster whose test pulse the command carries
};

// Writes the on-times of thrusters [0, N) into `ton` by thruster index, inactive ones zero (entries
// from N on are left as they are). In place, because the command is the flight software's output and
// a copy of the whole capacity-wide array every period is measurable (docs/performance.md).
// With a test pulse on an active thruster, the allocation floors its on-time and the others cancel
// its wrench; where the demand would then be unattainable, the period allocates without the pulse.
// The pulse's allocation is the least-propellant one whatever the norm: a check costs least that way.
ThrusterManagementOutput manage_thrusters(const ThrusterManagementParams& params, ThrusterManagementState& state,
                                          const Vec6& demand_wrench, model::ThrusterOnTimes& ton,
                                          const TestPulse& pulse = {});

}  // namespace chaser::flight
