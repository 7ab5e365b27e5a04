#pragma once
// COMRADE 2018 Tables 5 (its reach columns: the chaser at the capture point) and 6 (the gripper
// against the grasping point) from the comrade-reach preset's campaigns, one per combined controller
// (docs/servicing.md, "The reach over 100 dispersed runs"): means +- 1 sigma at the end of the runs
// as the paper gives them, beside the paper's, and the 95th percentiles against COMRADE Table 2, the
// gripper's taken over the hold (the largest |value| per axis of each run).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "campaign/statistics.hpp"
#include "campaign/table5.hpp"

namespace chaser::campaign {

// The gripper's four figures, each per axis (x the approach), in the order of COMRADE Table 6.
inline constexpr int kGripperFigures = 4;  // position [m], velocity [m/s], attitude [deg], rate [deg/s]

struct ReachColumn {
  std::string law;  // "hinf" or "compliance": the paper's column beside it
  int runs = 0;     // rows in runs.csv
  int flown = 0;    // status ok and the arm woke
  // The chaser at the end against the capture point: position, speed, attitude, rate (Table 5).
  std::array<FigureStats, 4> chaser;
  // The gripper, [figure][axis]: signed at the end of the run (Table 6's means), and the largest
  // |value| over the hold (the 95th percentile against Table 2).
  std::array<std::array<FigureStats, 3>, kGripperFigures> gripper_final, gripper_max;
  Proportion table2_met;             // runs whose gripper met every figure of Table 2 over the hold
  FigureStats peak_joint_torque_Nm;  // per run, the largest over the joints
  FigureStats tool_clearance_m;      // per run, the tool point's least clearance (n 0: no keep-out volume)
};

// One law's column from its runs.csv (a campaign of a scenario with a capture section); nullopt
// with `error` set when the file cannot be read or lacks the reach's columns.
std::optional<ReachColumn> read_reach_column(const std::string& law, const std::string& runs_csv, std::string& error);

// reach.md: Tables 5 (reach) and 6 beside the paper's, with Table 2's limits.
std::string reach_markdown(const std::vector<ReachColumn>& columns);
// reach.csv: one row per law and figure: its statistics over the runs, Table 2's limit (or the
// torque limit; 0 for the clearance, a least value) and the paper's mean and sd where it gives them.
std::string reach_csv(const std::vector<ReachColumn>& columns);

}  // namespace chaser::campaign
