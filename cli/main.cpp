// chaser: the command-line entry point. Parses arguments and dispatches to a subcommand.
#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <string_view>
#include <system_error>

#include <CLI/CLI.hpp>

#include "campaign/mpi_runner.hpp"
#include "cli/commands.hpp"
#include "sim/summary.hpp"

namespace {

// chaser campaign --mpi: MPI starts before anything else, and only then (MPI_Init may rewrite argv).
bool asks_for_mpi(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::string_view(argv[i]) == "--mpi") return true;
  return false;
}

// The plain chaser does not link MPI (campaign/mpi/CMakeLists.txt: start-up time): it becomes
// chaser-mpi, the same commands with MPI, from its own folder, with the same arguments and
// environment (mpirun's included) and the same process. Returns only if there is none to run: the
// command then says that this chaser has no MPI.
void become_chaser_mpi(char** argv) {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return;
  const std::string sibling = (self.parent_path() / "chaser-mpi").string();
  execv(sibling.c_str(), argv);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace chaser::cli;
  std::unique_ptr<chaser::campaign::MpiSession> mpi;
  if (asks_for_mpi(argc, argv) && !chaser::campaign::mpi_built()) become_chaser_mpi(argv);
  if (asks_for_mpi(argc, argv) && chaser::campaign::mpi_built()) {
    mpi = std::make_unique<chaser::campaign::MpiSession>(argc, argv);
    if (!mpi->ok()) {
      std::cerr << ("chaser campaign: " + mpi->error() + '\n');
      return kExitFailure;
    }
  }
  CLI::App app{"Chaser: thruster FDIR design and verification for rendezvous, docking and capture"};
  app.set_version_flag("--version", std::string("chaser ") + chaser::sim::kChaserVersion);
  app.require_subcommand(1);

  RunArgs run;
  CLI::App* run_cmd =
      app.add_subcommand("run", "Fly one closed-loop run; writes telemetry.csv (or .npy) and summary.json");
  run_cmd->add_option("scenario", run.scenario_path, "Scenario file (YAML)")->required();
  run_cmd->add_option("--out", run.out_dir, "Output directory")->capture_default_str();
  run_cmd->add_option("--seed", run.seed, "Run seed (replaces the scenario's seed)");
  run_cmd->add_option("--set", run.overrides, "Override a scenario key: key.path=value (repeatable)");
  run_cmd->add_option("--telemetry", run.telemetry_format, "Telemetry file: csv, npy (NumPy, np.load) or none")
      ->check(CLI::IsMember({"csv", "npy", "none"}))
      ->capture_default_str();
  run_cmd->add_option("--channels", run.channels,
                      "Telemetry channels to write, by name pattern ('*', '?'), comma-separated; t_s always")
      ->delimiter(',');

  std::string validate_path;
  std::vector<std::string> validate_overrides;
  CLI::App* validate_cmd = app.add_subcommand("validate", "Check a scenario without running it");
  validate_cmd->add_option("scenario", validate_path, "Scenario file (YAML)")->required();
  validate_cmd->add_option("--set", validate_overrides, "Override a scenario key: key.path=value (repeatable)");

  ThrustersArgs thrusters;
  CLI::App* thrusters_cmd = app.add_subcommand(
      "thrusters", "What the thruster set can do: attainable force and torque per axis, and after any one loss");
  thrusters_cmd->add_option("scenario", thrusters.scenario_path, "Scenario file (YAML)")->required();
  thrusters_cmd->add_option("--json", thrusters.json_path, "Also write the analysis as JSON");
  thrusters_cmd->add_option("--set", thrusters.overrides, "Override a scenario key: key.path=value (repeatable)");

  ControlDesignArgs control_design;
  CLI::App* control_cmd = app.add_subcommand("control", "Controller design tools");
  control_cmd->require_subcommand(1);
  CLI::App* control_design_cmd = control_cmd->add_subcommand(
      "design", "H-infinity design of the six loops in control.hinf: gamma, margins, peaks (docs/control.md)");
  control_design_cmd->add_option("scenario", control_design.scenario_path, "Scenario file (YAML)")->required();
  control_design_cmd->add_option("--out", control_design.json_path,
                                 "Write the design, controllers and frequency responses as JSON");
  control_design_cmd->add_option("--set", control_design.overrides, "Override a scenario key: key.path=value (repeatable)");

  FdiDesignArgs fdi_design;
  CLI::App* fdi_cmd = app.add_subcommand("fdi", "Fault detection and isolation tools");
  fdi_cmd->require_subcommand(1);
  CLI::App* design_cmd =
      fdi_cmd->add_subcommand("design", "Design the delay-robust residual generator (Fonod 2015, IV.A)");
  design_cmd->add_option("scenario", fdi_design.scenario_path, "Scenario file (YAML)")->required();
  design_cmd->add_option("--model", fdi_design.model,
                         "Model the residual is built on (position, attitude), or rate: the body-rate model with slosh, or "
                         "uio-bank: the unknown-input observers on it")
      ->check(CLI::IsMember({"position", "attitude", "rate", "uio-bank"}))
      ->capture_default_str();
  design_cmd->add_option("--out", fdi_design.out_path, "Write the design and its figures as JSON");
  design_cmd->add_option("--set", fdi_design.overrides, "Override a scenario key: key.path=value (repeatable)");

  CampaignArgs campaign;
  CLI::App* campaign_cmd = app.add_subcommand("campaign", "Monte Carlo campaign: runs.csv, summary.csv, summary.md (docs/campaigns.md)");
  campaign_cmd->add_option("scenario", campaign.scenario_path, "Scenario file (YAML)");
  campaign_cmd->add_option("--runs", campaign.runs, "Runs per case: N, or case=N,case=N");
  campaign_cmd->add_option("--cases", campaign.cases, "Cases in order: none,stuck_open,stuck_closed,leak,loss");
  campaign_cmd->add_option("--out", campaign.out_dir, "Campaign directory")->capture_default_str();
  campaign_cmd->add_option("--threads", campaign.threads, "Worker threads (default: all cores)");
  campaign_cmd->add_option("--shard", campaign.shard, "Run shard I/M of the campaign (0 <= I < M)");
  campaign_cmd->add_flag("--resume", campaign.resume, "Finish the campaign already in --out");
  campaign_cmd->add_option("--keep-telemetry", campaign.keep_telemetry, "Keep telemetry of runs with index < K");
  campaign_cmd->add_option("--rerun", campaign.rerun,
                           "Fly run I of this campaign alone: telemetry.csv, summary.json and its runs.csv row in --out");
  campaign_cmd->add_option("--of", campaign.rerun_of,
                           "With --rerun: the campaign's folder; refuses options that describe another campaign");
  campaign_cmd->add_option("--seed", campaign.seed, "Campaign seed (replaces campaign.seed)");
  campaign_cmd->add_option("--set", campaign.overrides, "Override a scenario key: key.path=value (repeatable)");
  campaign_cmd->add_option("--preset", campaign.preset, "fonod2015-table2: the paper's campaign; comrade-table5: COMRADE 2018 Table 5 by spin case (docs/campaigns.md); comrade-reach: its Tables 5 (reach) and 6 by combined controller (docs/servicing.md); comrade-stabilise: its Table 8 by spin case; comrade-mission: the whole mission's phase verdicts by spin case; comrade-rigidise: its Table 7 by rigidisation law, from one capture (docs/servicing.md); comrade-faults: every thruster's faults over the synchronisation, with and without accommodation (docs/fdi.md)");
  campaign_cmd->add_option("--also", campaign.also,
                           "With --preset comrade-table5: another scenario's cases in the same table (repeatable)");
  campaign_cmd->add_flag("--mpi", campaign.mpi, "Spread the runs over the ranks of mpirun/srun; rank 0 writes");
  constexpr const char* kTargetHelp =
      "Requirement to judge, e.g. 'P_nd<=1e-3@0.95' (repeatable): INDEX<=P@C for P_nd, P_f; INDEX>=Q@C for P_i, "
      "capture_rate, corridor_rate";
  // One value per --target, so that `--target T SCENARIO` leaves SCENARIO to the positional.
  campaign_cmd->add_option("--target", campaign.targets, kTargetHelp)->allow_extra_args(false);
  CampaignMergeArgs merge;
  CLI::App* merge_cmd = campaign_cmd->add_subcommand("merge", "Merge the complete shards of one campaign");
  merge_cmd->add_option("--out", merge.out_dir, "Merged campaign directory")->required();
  merge_cmd->add_option("shards", merge.shard_dirs, "Shard directories")->required();
  merge_cmd->add_option("--target", merge.targets, kTargetHelp)->allow_extra_args(false);

  FmeaArgs fmea;
  CLI::App* fmea_cmd = app.add_subcommand("fmea", "Thruster failure-mode analysis and reconfiguration by inverse simulation (Zhou 2018): fmea.csv, fmea.md");
  fmea_cmd->add_option("scenario", fmea.scenario_path, "Inverse-simulation scenario file (YAML)")->required();
  fmea_cmd->add_option("--out", fmea.out_dir, "Output directory")->capture_default_str();
  fmea_cmd->add_option("--set", fmea.overrides, "Override a scenario key: key.path=value (repeatable)");
  fmea_cmd->add_option("--threads", fmea.threads, "Worker threads (default: all cores)");
  fmea_cmd->add_flag("--optimize", fmea.optimize, "Also search the scenario's free mounting choices (optimize.choices): optimize.csv");
  fmea_cmd->add_flag("--three-axis", fmea.three_axis, "Add the 64 three-axis modes (x, y and z double faults: six failed thrusters)");
  fmea_cmd->add_flag("--history", fmea.history, "Write per-step histories (DIR/history) for python/plot_invsim.py");
  fmea_cmd->add_flag("--nominal-only", fmea.nominal_only,
                     "Fly only the nominal case of each layout (for calibrations: python/invsim_study/calibrate_invsim.py)");

  ViewArgs view;
  CLI::App* view_cmd = app.add_subcommand(
      "view", "Replay a run in 3D: one self-contained HTML page from its folder (docs/view.md)");
  view_cmd->add_option("run_dir", view.run_dir, "Run folder (telemetry.csv or .npy, summary.json, geometry.json)")->required();
  view_cmd->add_option("--out", view.out_path, "HTML file to write (default: RUN_DIR/view.html)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitBadInput;
  }
  if (*run_cmd) return run_command(run);
  if (*view_cmd) return view_command(view);
  if (*validate_cmd) return validate_command(validate_path, validate_overrides);
  if (*design_cmd) return fdi_design_command(fdi_design);
  if (*control_design_cmd) return control_design_command(control_design);
  if (*thrusters_cmd) return thrusters_command(thrusters);
  if (*fmea_cmd) return fmea_command(fmea);
  if (*merge_cmd) return campaign_merge_command(merge);
  if (*campaign_cmd) {
    if (campaign.scenario_path.empty()) {
      std::cerr << "chaser campaign: give a SCENARIO file (or the merge subcommand)\n";
      return kExitBadInput;
    }
    return campaign_command(campaign);
  }
  return kExitBadInput;
}
