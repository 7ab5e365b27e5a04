#pragma once
// The channels of telemetry.csv as one table: each channel's name, unit and how its value is read
// from a period's record, so the header and every row come from the same list and cannot drift
// apart. The table is built once per run for the scenario's thruster count.
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/types.hpp"
#include "flight/flight_software.hpp"
#include "model/scenario.hpp"
#include "plant/arm_joints.hpp"
#include "plant/plant.hpp"
#include "sim/telemetry.hpp"

namespace chaser::sim {

// What one row is made from: the truth at the period start, the flight output computed from the
// measurements at its start, what the plant realised over it (profile, delay, propellant at the
// period end), and the FDI's watched set of this period (before a recovery in it changes it).
struct PeriodRecord {
  double t_s = 0;                                 // [s] period start
  const plant::RigidState* truth = nullptr;       // at the period start
  const plant::PlantState* plant = nullptr;       // after the period
  const flight::FlightOutput* flight = nullptr;
  const flight::FlightState* flight_state = nullptr;
  const flight::fdi::WatchedSet* watched = nullptr;
  Vec3 attitude_error_body_rad = Vec3::Zero();    // [rad] truth against the reference
  Quat q_inertial_from_target = Quat::Identity();   // at the period start
  Vec3 omega_target_body_radps = Vec3::Zero();      // [rad/s] the target's inertial rate, its body axes
  std::span<const model::SloshState> slosh;         // each tank's slosh state at the period start
  int phase = 0;                                    // the phase flown in this period (its index)
  // With a capture: the joints at the period start and the gripper against the reach's goal (the
  // pre-grasp pose), true values; null before the arm wakes (the gripper's channels are then NaN).
  const model::ArmMeasurements* arm = nullptr;
  const plant::GripperTruth* gripper = nullptr;
  const plant::ArmFigure* figure = nullptr;  // the arm's figure in target axes; null before the arm wakes
};

// What the table has channels for, from the scenario: its thrusters and its slosh tanks.
struct TelemetryShape {
  int thrusters = 0;    // ton_cmd_1..N, ton_real_1..N
  int slosh_tanks = 0;  // slosh1_s_body_x_m .. per tank of chaser.slosh (none without it)
  bool target_estimator = false;  // target_est_att_err_rad, target_est_rate_err_radps, target_est_att_sigma_rad
  int phases = 1;       // the run's phases (sim/run_phases.hpp); with more than one, the phase channel
  bool arm = false;     // a capture: the joints (q_arm_1..7_rad, tau_arm_1..7_Nm) and the gripper's errors
  bool supervisor = false;  // fdi.supervisor: its mode (supervisor_mode: 0 nominal, 2i+1 / 2i+2 the i-th thruster stuck open / closed)
};
TelemetryShape telemetry_shape(const model::Scenario& scenario);

struct TelemetryChannel {
  std::string name;  // the CSV column: quantity, then axis or thruster number, then unit ("r_lvlh_x_m")
  std::string unit;  // SI unit as the name's suffix spells it ("m", "mps", "radps"); "" if dimensionless
  double (*value)(const PeriodRecord&, int index) = nullptr;
  int index = 0;     // vector component, or thruster index 0..N-1, passed to value
};

// Every channel for a scenario of that shape, in column order. Thruster channels are numbered
// T1..TN (ton_cmd_1 .. ton_cmd_N); the FDI's candidate and confirmed thrusters are numbers 1..N,
// 0 for none; active_thrusters is the active set's mask (bit i: T(i+1)). Slosh channels follow the
// tanks' order in chaser.slosh.tanks: slosh1_s_body_x_m (the mass's displacement from its rest
// point, chaser body axes) and slosh1_s_dot_body_x_mps (its rate in the body frame). A run of
// several phases ends with `phase`, the index of the phase flown (summary.json's phases name them).
// A capture adds the joints' angles at the period start and the torques the joint loop commanded
// last (q_arm_1_rad .., tau_arm_1_Nm ..; the stowed angles and 0 before the arm wakes) and the
// gripper against the reach's goal, true values in the goal's axes (gripper_err_x_m ..,
// gripper_v_x_mps .., gripper_att_err_x_rad .., gripper_rate_x_radps ..; NaN before the arm wakes),
// then the arm's figure, true, in the target's axes from its CoM (hub_target_x_m .., the hub's
// attitude q_target_from_hub_w .., joint1_target_x_m .. joint7_target_z_m, tool_target_x_m ..;
// NaN before the arm wakes).
std::vector<TelemetryChannel> telemetry_channels(const TelemetryShape& shape);

std::vector<std::string> channel_names(const std::vector<TelemetryChannel>& channels);

// Channel selection (`chaser run --channels`): the channels whose name matches one of the patterns
// ('*' any run of characters, '?' one), in table order, and t_s always; every channel if there are
// no patterns. unmatched_patterns lists the patterns that match no channel (a typo: the command
// line refuses them).
bool name_matches(std::string_view pattern, std::string_view name);
std::vector<TelemetryChannel> select_channels(std::vector<TelemetryChannel> channels,
                                              const std::vector<std::string>& patterns);
std::vector<std::string> unmatched_patterns(const std::vector<TelemetryChannel>& channels,
                                            const std::vector<std::string>& patterns);

// One row: every channel's value, in table order. `row` holds channels.size() values.
void record_period(const std::vector<TelemetryChannel>& channels, const PeriodRecord& record, double* row);

// The same row for the whole table of telemetry_channels(shape), the usual case, written in
// straight-line code: the table's call per channel cost 2,500 instructions a period, a sixth of
// the loop. `row` holds the table's size. Its reference and test is the table, channel by channel.
void record_every_channel(const PeriodRecord& record, const TelemetryShape& shape, double* row);

}  // namespace chaser::sim
