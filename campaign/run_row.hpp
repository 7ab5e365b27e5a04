#pragma once
// One runs.csv row (docs/campaigns.md, "runs.csv"): what a run was (seed, dispersed chaser, fault) and
// what the FDI schemes and the mission made of it. The columns live in ONE table (run_row.cpp,
// run_columns): adding a column is adding one line there. A scenario with a capture section has the
// reach's columns after the others (RunColumnSet::kReach); a file's header says which set it holds.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "campaign/fault_sampling.hpp"
#include "campaign/plan.hpp"
#include "core/types.hpp"
#include "sim/run.hpp"

namespace chaser::campaign {

enum class RunStatus { kOk, kDiverged, kError };
std::string_view to_string(RunStatus s);

// One scheme's verdict on one run, judged against the truth (Fonod 2015, section V).
struct SchemeOutcome {
  double detection_s;          // [s] first alarm minus onset; NaN: none, or a false alarm, or case none
  double isolation_s;          // [s] confirmation minus onset; NaN likewise
  int isolated;                // index of the confirmed thruster, model::kNoThruster: none
  bool false_alarm;            // alarm before the onset (any alarm for case none)
  bool missed;                 // fault case and no alarm at or after the onset
  bool wrong_isolation;        // a thruster confirmed that is not the faulty one (any, for case none)
  double glr_max_before_onset; // [-] largest GLR statistic before the onset (whole run for none)
};

// With a capture (model::CaptureParams): the reach against COMRADE 2018 Table 2 (sim::ReachResult).
// The gripper against the pre-grasp pose in its axes (x the approach): signed at the end of the run,
// and the largest |value| per axis over the hold. NaN where the arm never woke.
struct ReachFigures {
  Vec3 final_error_m, final_velocity_mps, final_attitude_deg, final_rate_deg_s;
  Vec3 max_error_m, max_velocity_mps, max_attitude_deg, max_rate_deg_s;
  double peak_joint_torque_Nm;   // [N m] the largest command over the joints and the reach
  double min_tool_clearance_m;   // [m] the tool point from the keep-out volume, over the reach
  bool table2_met;               // sim::gripper_meets_table2
  // The grasp that follows the reach (sim::GraspResult): when the gripper locked on the fixture (NaN:
  // not captured within the run), and whether Table 2 held at the jaws' closure.
  double grasp_captured_s;       // [s]
  bool grasp_table2_met;         // sim::grasp_meets_table2
  // The stabilisation after the brakes (sim::StabiliseResult; NaN where it was not flown): the time
  // from its start to the rate staying below 0.5 deg/s (NaN: not by the end), the target's rate at
  // the end (its axes), the braked joints' peak load, its propellant, and Table 3's verdict.
  double stabilise_below_goal_s; // [s]
  Vec3 stabilise_final_rate_deg_s;
  double stabilise_peak_load_Nm; // [N m]
  double stabilise_propellant_kg;
  bool stabilise_table3_met;     // sim::stabilise_meets_table3
};

struct RunRecord {
  std::int64_t run = 0;
  std::uint64_t seed = 0;
  FaultCase fault_case = FaultCase::kNone;
  RunStatus status = RunStatus::kOk;
  int fault_thruster = model::kNoThruster;  // index, kNoThruster for case none
  double fault_size = 0;       // [-] leak or loss size, 1 stuck, 0 none
  double onset_s = 0;          // [s] NaN for case none
  model::SpacecraftParams chaser;
  // Each diagnosis scheme's, by slot (flight/diagnosis_schemes.hpp), and the FDIR's as a whole.
  std::array<SchemeOutcome, flight::kMaxDiagnosisSchemes> schemes{};
  SchemeOutcome fdir{};
  double recovery_s = 0;       // [s] run time of the recovery, NaN: none
  bool capture = false, corridor_kept = false, target_in_view = false;
  double propellant_kg = 0;    // [kg]
  double simulated_s = 0;      // [s]
  // At the end, against the capture point (sim::MissionFigures; COMRADE 2018 Table 1), and the least
  // keep-out clearances either side of the rotation's synchronisation (Table 4; NaN without a
  // keep-out volume or where the run has no such time).
  double final_position_error_m = 0, final_speed_mps = 0, final_attitude_error_deg = 0, final_rate_error_deg_s = 0;
  double min_clearance_unsynchronised_m = 0, min_clearance_synchronised_m = 0;
  // fdi.supervisor: its mode switches, the last mode's thruster (index) and fault, the first switch's
  // time (NaN: none, or no supervisor).
  int supervisor_switches = 0;
  int supervisor_thruster = model::kNoThruster;
  flight::fdi::SupervisorFault supervisor_fault = flight::fdi::SupervisorFault::kNone;
  double supervisor_first_switch_s = 0;
  ReachFigures reach{};
  // With a capture, the whole mission judged phase by phase (sim/phase_verdicts.hpp): every phase
  // met, and the phases not met as bits (sim::phases_not_met_bits: bit i sim::kMissionPhases[i]).
  bool mission_met = false;
  std::int64_t phases_not_met = 0;
};

// The record of a flown run; status kDiverged when the monitor stopped it or it left the planned
// duration early. `planned_s` is the run duration it should have flown.
RunRecord make_record(const RunSetup& setup, const sim::RunResult& result, double planned_s);
// The record of a run that threw: no figures, every outcome empty.
RunRecord error_record(const RunSetup& setup);

// How a column's fields read back (the Python module's structured array takes its types from it).
enum class ColumnKind {
  kInteger,   // a signed integer: run index, thruster number n of Tn (0: none)
  kUnsigned,  // an unsigned 64-bit integer: the seed
  kText,      // a word: case, status
  kNumber,    // append_number's {:.17g} or nan
  kFlag,      // 1 or 0
};

struct RunColumn {
  std::string name;
  ColumnKind kind;
  void (*write)(const RunRecord& r, int index, std::string& out);
  int index = 0;  // passed to write: a scheme's slot (-1: the FDIR's) for a scheme's columns
};
// Which columns a campaign's runs.csv has: the reach's too when its scenario has a capture section.
enum class RunColumnSet { kStandard, kReach };
RunColumnSet run_column_set(const model::Scenario& scenario);
const std::vector<RunColumn>& run_columns(RunColumnSet set);

std::string runs_header(RunColumnSet set);  // names joined by commas, no newline
std::string format_row(const RunRecord& r, RunColumnSet set);  // one row, no newline
// The name of a reach column per axis: figure 0-3 the gripper's error [m], velocity [m/s], attitude
// [deg] and rate [deg/s] (ReachFigures' order), at the end of the run or the largest over the hold.
std::string reach_column_name(bool over_hold, int figure, int axis);
// The set whose header a runs.csv's first line is; nullopt for another file (an older Chaser's).
std::optional<RunColumnSet> run_column_set_of(std::string_view header);

// Numbers as the spec writes them: {:.17g}, "nan" for a time that does not exist.
void append_number(std::string& out, double value);

}  // namespace chaser::campaign
