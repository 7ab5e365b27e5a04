#pragma once
// The on-board software of one control period, in order (docs/architecture.md, "One control period"):
// navigation -> guidance -> position and attitude control -> TMU -> TMF. It sees only sensor
// measurements and its own commands, never the truth.
#include <array>
#include <optional>

#include "core/time.hpp"
#include "flight/active_check.hpp"
#include "flight/arm_reaction.hpp"
#include "flight/attitude_control.hpp"
#include "flight/fdir.hpp"
#include "flight/guidance.hpp"
#include "flight/hinf_control.hpp"
#include "flight/supervision.hpp"
#include "flight/sync_approach.hpp"
#include "flight/sync_guidance.hpp"
#include "flight/target_estimator.hpp"
#include "flight/modulation.hpp"
#include "flight/navigation.hpp"
#include "flight/position_control.hpp"
#include "flight/reach.hpp"
#include "flight/thruster_management.hpp"
#include "model/messages.hpp"
#include "model/recovery.hpp"
#include "model/scenario.hpp"
#include "model/target_orbit.hpp"

namespace chaser::flight {

struct FlightParams {
  model::TargetOrbit orbit;      // the target orbit the flight software believes (LVLH at t)
  TimeNs period_ns = 0;          // [ns] control period T
  model::GuidanceParams guidance;
  NavParams navigation;
  PositionControlParams position;
  AttitudeControlParams attitude;
  HinfControlParams hinf;  // enabled: flies instead of the LQR pair (control.law: hinf)
  // The target's attitude estimator: with a target pose sensor and a rigid-body target.
  std::optional<TargetEstimatorParams> target_estimator;
  // The synchronised approach (guidance.synchronised): its reference replaces the straight line.
  std::optional<SyncTransferParams> sync;
  // With guidance.synchronised.approach: the steps before the transfer (flight/sync_approach.hpp);
  // the reference is then this plan's from the line's start.
  std::optional<SyncApproachPlan> approach;
  // With capture: the arm's reach under the combined controller (flight/reach.hpp), from its start.
  std::optional<ReachParams> reach;
  TmuParams tmu;
  ThrusterManagementParams management;
  FdirParams fdir;
  ActiveCheckParams active_check;
  model::RecoveryPolicy recovery = model::RecoveryPolicy::kNone;
  // fdi.supervisor: the multi-estimator supervisor; with supervisor_accommodates its mode sets the
  // allocation (flight/supervision.hpp).
  std::optional<fdi::SupervisorParams> supervisor;
  bool supervisor_accommodates = false;
  bool mass_from_gauge = false;  // control.mass_from_gauge: the loop's mass is position.mass_kg less the gauge's
};

FlightParams make_flight_params(const model::Scenario& scenario);
// guidance.synchronised with the target's capture point (absent without it or target.body).
std::optional<SyncTransferParams> make_sync_transfer(const model::Scenario& scenario);
// guidance.synchronised.approach with the line before it (absent without it).
std::optional<SyncApproachPlan> make_sync_approach(const model::Scenario& scenario);


struct FlightState {
  NavState navigation;
  TmuState tmu;
  HinfControlState hinf;
  std::optional<TargetEstimator> target;      // with FlightParams::target_estimator
  SyncApproachLatch sync_latch;               // the axis and start point the approach fixed in flight
  Vec3 force_cmd_lvlh_N_prev = Vec3::Zero();  // [N] what was commanded last period, for navigation
  model::ThrusterConfiguration thrusters;     // active set and latch valves: the scenario's starting
                                             // set, every latch open, until a recovery changes them
  ThrusterManagementState management;        // the active set's allocation problem
  ActiveCheckState active_check;              // when each active thruster last proved itself
  ReachState reach;                           // the reach's joint loop (with FlightParams::reach)
  ArmReactionState arm_reaction;              // the awake arm's share of the diagnosis's torque rows
  fdi::SupervisorState supervisor;            // with FlightParams::supervisor (sized in the first period)
  bool initialised = false;
  bool escape_loops_engaged = false;          // the escape's arm braked: the platform's loops reset once
  // Last: its sample and block rings (kMaxWatchedThrusters lanes, ~0.3 MB) would otherwise sit
  // between the small states every period reads, and spread them over more cache sets and pages.
  FdirState fdir;
};

// Everything one period computed, for telemetry and for the plant (command).
struct FlightOutput {
  model::ThrusterCommand command;
  NavEstimate estimate;
  GuidanceRef reference;
  Vec3 force_demand_lvlh_N = Vec3::Zero();   // [N] position controller output
  Vec3 torque_demand_body_Nm = Vec3::Zero(); // [N m] attitude controller output
  Vec6 released_wrench = Vec6::Zero();       // [N; N m] TMU output, body axes
  Vec6 commanded_wrench = Vec6::Zero();      // [N; N m] M ton, body axes
  bool allocation_feasible = true;
  FdirOutput fdir;                           // both FDI schemes, event resolution
  bool recovered_now = false;                // a recovery changed the active set this period
  int checked_thruster = model::kNoThruster; // index of the thruster whose test pulse the command carries
  int supervisor_mode = 0;                   // the supervisor's sigma after this period (0: nominal, or none)
  std::optional<TargetEstimate> target;      // the target's estimated attitude and rate at this period
                                             // (once the first pose has arrived)
};

FlightOutput step_flight(const FlightParams& params, FlightState& state, const model::SensorMeasurements& meas);

}  // namespace chaser::flight
