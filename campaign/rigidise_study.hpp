#pragma once
// COMRADE 2018 Table 7, the rigidisation from the paper's artificial starts (`chaser campaign
// --preset comrade-rigidise`, docs/servicing.md): one column per rigidisation law, each the same
// capture flown once to its confirmation (the scenario's synchronisation, reach and grasp), then
// many runs from a fork of that state (sim::Simulation's fork), each with the joints' rates set to a
// drawn start, the hub and the target moving with them as the closed chain and the momentum demand
// (plant/arm_joints.hpp), flown for 120 s with the brakes held off (the paper's runs end with rates
// left, unbraked). The paper's starts: H-infinity from joint rates of 0.14 +- 0.20 deg/s (1 sigma,
// largest 3.02), compliance from 1 deg/s on every joint.
//
// Our reading of the starts: each joint's rate drawn from N(0.14, 0.20^2) deg/s; and 1 deg/s on
// every joint with each sign drawn (the paper's all-positive start is one of the 128). Each run's
// draw is its own named random stream from the scenario's seed, so a column is the same bits at any
// thread count.
#include <array>
#include <string>
#include <vector>

#include "model/capture.hpp"
#include "model/scenario.hpp"

namespace chaser::campaign {

struct RigidiseStart {
  bool every_joint = false;  // |rate| = mean_degps on every joint, the signs drawn; else N(mean, sd^2) per joint
  double mean_degps = 0.0;   // [deg/s]
  double sd_degps = 0.0;     // [deg/s]
};

struct RigidiseColumnSpec {
  std::string name;  // the folder and the column: "hinf", "compliance"
  model::RigidiseLaw law = model::RigidiseLaw::kCompliance;
  RigidiseStart start;
  int runs = 100;
  double duration_s = 120.0;  // [s] each run from the start
};

struct RigidiseRun {
  std::array<double, model::kArmJoints> start_rate_degps{};  // [deg/s] the draw
  std::array<double, model::kArmJoints> angle_error_deg{};   // [deg] q - q_d at the end
  std::array<double, model::kArmJoints> rate_degps{};        // [deg/s] at the end
  std::array<double, model::kArmJoints> peak_torque_Nm{};    // [N m] each joint's largest command
  std::string error;  // empty: flown
};

struct RigidiseColumn {
  RigidiseColumnSpec spec;
  double start_s = 0.0;  // [s] the capture confirmed: every run starts here
  std::vector<RigidiseRun> runs;
};

// The column's runs on `threads` workers. Throws std::invalid_argument for a scenario without
// capture.rigidise, std::runtime_error when the capture is not made.
RigidiseColumn run_rigidise_column(const model::Scenario& scenario, const RigidiseColumnSpec& spec, int threads);

// The paper's two columns: hinf from N(0.14, 0.20^2) deg/s, compliance from 1 deg/s on every joint.
std::vector<RigidiseColumnSpec> comrade_table7_columns(int runs);

// Table 7 beside the paper's (markdown), its figures one per line (csv: column,figure,value), and a
// column's runs (csv, one row per run: the start, the end, the peaks, per joint).
std::string rigidise_markdown(const std::vector<RigidiseColumn>& columns);
std::string rigidise_csv(const std::vector<RigidiseColumn>& columns);
std::string rigidise_runs_csv(const RigidiseColumn& column);

}  // namespace chaser::campaign
