#pragma once
// Subcommands of the `chaser` command. Each returns the process exit code:
// 0 success, 1 a run or I/O failure, 2 a bad scenario or bad command-line input.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace chaser::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitBadInput = 2;

struct RunArgs {
  std::string scenario_path;
  std::string out_dir = "out";
  std::optional<std::uint64_t> seed;
  std::vector<std::string> overrides;
  std::string telemetry_format = "csv";  // "csv", "npy" or "none"
  std::vector<std::string> channels;     // name patterns; empty: every channel
};

struct FdiDesignArgs {
  std::string scenario_path;
  std::string model = "position";  // "position", "attitude" or "rate"
  std::string out_path;            // empty: print only
  std::vector<std::string> overrides;
};

// chaser campaign (docs/campaigns.md); empty strings mean "not given".
struct CampaignArgs {
  std::string scenario_path;
  std::string runs;            // "N" or "case=N,case=N"
  std::string cases;           // "none,stuck_open,..."
  std::string out_dir = "campaign-out";
  std::optional<int> threads;  // default: hardware concurrency
  std::string shard;           // "I/M"
  bool resume = false;
  std::int64_t keep_telemetry = 0;
  std::optional<std::uint64_t> seed;
  std::vector<std::string> overrides;
  std::string preset;
  bool mpi = false;            // spread the runs over MPI ranks (main.cpp started MPI)
  std::vector<std::string> targets;  // --target 'P_nd<=1e-3@0.95' (campaign/target.hpp)
  std::vector<std::string> also;     // --also SCENARIO: more columns of --preset comrade-table5 (ASSIST)
  std::optional<std::int64_t> rerun; // --rerun I: fly run I alone into --out (telemetry, summary, its row)
  std::string rerun_of;              // --of DIR: the campaign folder --rerun's run must belong to (checked)
};

// chaser fmea (docs/invsim.md, "chaser fmea").
struct FmeaArgs {
  std::string scenario_path;
  std::string out_dir = "fmea-out";
  std::vector<std::string> overrides;
  std::optional<int> threads;  // default: hardware concurrency
  bool optimize = false;       // search the scenario's free mounting choices (optimize.choices)
  bool history = false;        // write DIR/history for python/plot_invsim.py
  bool three_axis = false;     // add the 64 three-axis modes (x, y and z double faults)
  bool nominal_only = false;   // only the nominal case of each layout (python/invsim_study/calibrate_invsim.py)
};

// chaser thrusters (docs/scenario.md, "Thruster-set analysis").
struct ThrustersArgs {
  std::string scenario_path;
  std::string json_path;  // empty: print only
  std::vector<std::string> overrides;
};

// chaser control design (docs/control.md, "Six-axis design").
struct ControlDesignArgs {
  std::string scenario_path;
  std::string json_path;  // empty: print only
  std::vector<std::string> overrides;
};

// chaser view (docs/view.md).
struct ViewArgs {
  std::string run_dir;
  std::string out_path;  // empty: RUN_DIR/view.html
};

struct CampaignMergeArgs {
  std::string out_dir;
  std::vector<std::string> shard_dirs;
  std::vector<std::string> targets;  // --target, as for chaser campaign
};

int run_command(const RunArgs& args);
int campaign_command(const CampaignArgs& args);
int campaign_merge_command(const CampaignMergeArgs& args);
int fdi_design_command(const FdiDesignArgs& args);
int fmea_command(const FmeaArgs& args);
int thrusters_command(const ThrustersArgs& args);
int control_design_command(const ControlDesignArgs& args);
int view_command(const ViewArgs& args);
int validate_command(const std::string& scenario_path, const std::vector<std::string>& overrides);

}  // namespace chaser::cli
