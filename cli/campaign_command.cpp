// chaser campaign: a Monte Carlo campaign (or one shard of it), and chaser campaign merge
// (docs/campaigns.md).
#include <array>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>

#include <fmt/format.h>

#include "campaign/campaign.hpp"
#include "campaign/campaign_json.hpp"
#include "campaign/merge.hpp"
#include "campaign/mpi_runner.hpp"
#include "campaign/progress.hpp"
#include "campaign/reach_tables.hpp"
#include "campaign/csv.hpp"
#include "campaign/faults_tables.hpp"
#include "campaign/rigidise_study.hpp"
#include "campaign/mission_tables.hpp"
#include "campaign/stabilise_tables.hpp"
#include "campaign/run_one.hpp"
#include "campaign/run_row.hpp"
#include "campaign/summary.hpp"
#include "campaign/table5.hpp"
#include "campaign/target_report.hpp"
#include "cli/commands.hpp"
#include "cli/scenario_input.hpp"
#include "core/worker_threads.hpp"

namespace chaser::cli {

namespace {

constexpr const char* kPresetTable2 = "fonod2015-table2";
constexpr const char* kPresetTable5 = "comrade-table5";
constexpr const char* kPresetReach = "comrade-reach";
constexpr const char* kPresetStabilise = "comrade-stabilise";
constexpr const char* kPresetMission = "comrade-mission";
constexpr const char* kPresetRigidise = "comrade-rigidise";
constexpr const char* kPresetFaults = "comrade-faults";
// comrade-faults: runs per fault kind for each of COMRADE 2018's four thrusters (sec. 6.3: T1, T5,
// T13, T17); every other thruster gets a fifth of that, the fault-free case twice.
constexpr int kFaultsRuns = 100;
constexpr std::array<int, 4> kComradeFourIndices = {0, 4, 12, 16};
// COMRADE Table 7's columns: 100 runs each from one capture (~3 s each: two columns in ~5 minutes
// on 2 cores).
constexpr int kRigidiseRuns = 100;
// COMRADE 2018, sec. 7: the paper's Tables 5 and 6 are means of 100 runs; we fly 100 per spin case
// (synchronisation) and per combined controller (reach).
constexpr const char* kTable5Runs = "none=100";
// The stabilisation's runs fly the whole capture scenario (~18 s each, 15 s of it the arm on
// MuJoCo): 20 per spin case keeps the preset near 10 minutes on 2 cores (--runs gives more).
constexpr const char* kStabiliseRuns = "none=20";
// Fonod 2015, section V: 200 fault-free runs, 1600 runs per fault case, each scheme judged alone.
constexpr const char* kTable2Runs = "none=200,stuck_open=1600,stuck_closed=1600,leak=1600,loss=1600";

// --target, every one checked: nullopt after printing what is wrong with each bad one.
std::optional<std::vector<campaign::Target>> parse_targets(const std::vector<std::string>& texts) {
  std::vector<campaign::Target> targets;
  bool ok = true;
  for (const std::string& text : texts) {
    const campaign::TargetParse parsed = campaign::parse_target(text);
    if (parsed.target) targets.push_back(*parsed.target);
    ok = ok && parsed.target.has_value();
    if (!parsed.target) std::cerr << ("chaser campaign: " + parsed.error + '\n');
  }
  return ok ? std::optional(targets) : std::nullopt;
}

// The targets' verdicts on the terminal, from the runs file just summarised (as in summary.md).
void print_targets(const std::string& out_dir, const std::vector<campaign::FaultCase>& cases,
                   const std::vector<campaign::Target>& targets) {
  if (targets.empty()) return;
  const campaign::StatsRead read = campaign::read_campaign_stats(out_dir + "/runs.csv", cases);
  if (read.stats) std::cout << campaign::targets_text(*read.stats, targets);
}

int report(const campaign::CampaignOutcome& o, const std::string& out_dir) {
  if (o.status == campaign::CampaignStatus::kBadInput) {
    std::cerr << ("chaser campaign: " + o.message + '\n');
    return kExitBadInput;
  }
  if (o.status == campaign::CampaignStatus::kFailure) {
    std::cerr << ("chaser campaign: " + o.message + '\n');
    return kExitFailure;
  }
  const campaign::ExecuteResult& e = o.executed;
  // Wall-clock figures go to the terminal only, never into the result files.
  if (e.runs > 0)
    std::cerr << fmt::format("campaign: {} runs in {:.1f} s ({:.2f} runs/s, {:.0f} simulated s per wall s), {} "
                             "diverged or failed\n",
                             e.runs, e.wall_s, static_cast<double>(e.runs) / e.wall_s, o.simulated_s / e.wall_s,
                             e.diverged);
  std::cout << fmt::format("campaign: {} runs{}; wrote {}/runs.csv, summary.csv, summary.md\n", o.shard_runs,
                           o.resumed > 0 ? fmt::format(" ({} found done, resumed)", o.resumed) : "", out_dir);
  return kExitOk;
}

// Every input checked and loaded into a plan; nullopt after printing what is wrong.
struct Prepared {
  campaign::CampaignPlan plan;
  campaign::CampaignOptions options;
  std::vector<campaign::FaultCase> cases() const {
    std::vector<campaign::FaultCase> out;
    for (const campaign::CaseRuns& c : plan.layout.cases()) out.push_back(c.fault_case);
    return out;
  }
};

std::optional<Prepared> prepare(const CampaignArgs& args) {
  std::vector<std::string> overrides;
  std::string runs_text = args.runs;
  if (!args.preset.empty()) {
    if (args.preset != kPresetTable2) {
      std::cerr << fmt::format("chaser campaign: --preset: unknown preset '{}' (allowed: {}, {}, {}, {}, {}, {}, {})\n",
                               args.preset, kPresetTable2, kPresetTable5, kPresetReach, kPresetStabilise, kPresetMission,
                               kPresetRigidise, kPresetFaults);
      return std::nullopt;
    }
    overrides.push_back("fdi.recovery=none");  // the paper evaluates each scheme alone
    if (runs_text.empty() && args.cases.empty()) runs_text = kTable2Runs;
  }
  if (args.seed) overrides.push_back(fmt::format("campaign.seed={}", *args.seed));
  overrides.insert(overrides.end(), args.overrides.begin(), args.overrides.end());  // the user's --set win

  const campaign::ShardParse shard = campaign::parse_shard(args.shard.empty() ? "0/1" : args.shard);
  std::string error = shard.shard ? "" : shard.error;
  if (error.empty() && args.threads && *args.threads < 1)
    error = fmt::format("--threads: must be >= 1 (got {})", *args.threads);
  if (error.empty() && args.keep_telemetry < 0)
    error = fmt::format("--keep-telemetry: must be >= 0 (got {})", args.keep_telemetry);
  if (!error.empty()) {
    std::cerr << ("chaser campaign: " + error + '\n');
    return std::nullopt;
  }
  const auto targets = parse_targets(args.targets);
  if (!targets) return std::nullopt;
  const auto loaded = load_or_report(args.scenario_path, overrides);
  if (!loaded) return std::nullopt;
  const auto layout = campaign::parse_layout(args.cases, runs_text,
                                             static_cast<std::int64_t>(loaded->scenario->campaign.runs_per_case));
  if (!layout.error.empty()) {
    std::cerr << ("chaser campaign: " + layout.error + '\n');
    return std::nullopt;
  }
  // With --mpi every rank is one process per core by default: one worker thread each.
  const int default_threads = args.mpi ? 1 : default_worker_threads();
  return Prepared{campaign::CampaignPlan{*loaded->scenario, loaded->hash, campaign::RunLayout(layout.cases)},
                  campaign::CampaignOptions{.out_dir = args.out_dir,
                                            .shard = *shard.shard,
                                            .threads = args.threads.value_or(default_threads),
                                            .resume = args.resume,
                                            .keep_telemetry = args.keep_telemetry,
                                            .progress = campaign::stderr_is_terminal(),
                                            .show_progress = {},   // the line on stderr
                                            .stop_requested = {},  // Ctrl-C ends the process instead
                                            .targets = *targets}};
}

// --mpi: every rank prepares; all go on only when all prepared the same campaign (none left waiting).
int campaign_mpi(const CampaignArgs& args) {
  const std::optional<Prepared> prepared = prepare(args);
  const int rank = campaign::mpi_rank();
  const std::string mine =
      prepared ? campaign::campaign_json_text(campaign::campaign_json(prepared->plan, prepared->options.shard)) : "";
  if (!campaign::mpi_all_agree(mine, rank)) {
    if (prepared && rank == 0) std::cerr << "chaser campaign: another MPI rank could not prepare this campaign (see its message)\n";
    return kExitBadInput;
  }
  Prepared p = *prepared;
  p.options.progress = p.options.progress && rank == 0;
  const campaign::CampaignOutcome outcome = campaign::run_campaign_mpi(p.plan, p.options, rank);
  if (rank != 0) return kExitOk;
  const int code = report(outcome, args.out_dir);
  if (code == kExitOk) print_targets(args.out_dir, p.cases(), p.options.targets);
  return code;
}

// One fault-free campaign of `args` into out_dir/name with `first_override` before the user's --set;
// false after printing what went wrong (the exit code in `code`).
// `cases` and `runs` (--cases' and --runs' forms) replace the fault-free case and its runs.
bool run_case_campaign(const CampaignArgs& args, const std::string& scenario_path, const std::string& name,
                       const std::vector<std::string>& first_overrides, int& code, const std::string& cases = "none",
                       const std::string& runs = "") {
  CampaignArgs sub = args;
  sub.preset.clear();
  sub.also.clear();
  sub.scenario_path = scenario_path;
  sub.cases = cases;
  if (!runs.empty()) sub.runs = runs;
  if (sub.runs.empty()) sub.runs = kTable5Runs;
  sub.out_dir = (std::filesystem::path(args.out_dir) / name).string();
  sub.overrides.insert(sub.overrides.begin(), first_overrides.begin(), first_overrides.end());  // the user's --set win
  const std::optional<Prepared> prepared = prepare(sub);
  if (!prepared) {
    code = kExitBadInput;
    return false;
  }
  code = report(campaign::run_campaign(prepared->plan, prepared->options), sub.out_dir);
  return code == kExitOk;
}

// --preset comrade-table5 (docs/campaigns.md, "COMRADE Table 5"): one fault-free campaign per
// spin case S1, S2, S3 of a scenario flying the synchronisation (guidance.synchronised.approach),
// or one of the scenario as it is (the ASSIST approach), for the scenario and each --also, each in
// its folder under --out and resumable as any campaign; then table5.md and table5.csv beside them.
int comrade_table5(const CampaignArgs& args) {
  if (args.mpi || !args.shard.empty() || !args.cases.empty()) {
    std::cerr << "chaser campaign: --preset comrade-table5 runs whole fault-free campaigns in one process: "
                 "leave out --mpi, --shard and --cases\n";
    return kExitBadInput;
  }
  std::vector<std::string> paths = {args.scenario_path};
  paths.insert(paths.end(), args.also.begin(), args.also.end());
  struct Case {
    std::string scenario_path, name, override_text;
  };
  std::vector<Case> cases;
  for (const std::string& path : paths) {  // every scenario checked before anything runs
    const auto loaded = load_or_report(path, args.overrides);
    if (!loaded) return kExitBadInput;
    const model::Scenario& s = *loaded->scenario;
    if (!s.target.body) {
      std::cerr << fmt::format("chaser campaign: --preset comrade-table5: {} has no COMRADE target (target.body): "
                               "use scenarios/comrade_sync.yaml or scenarios/comrade_assist.yaml\n",
                               path);
      return kExitBadInput;
    }
    if (s.guidance.synchronised && s.guidance.synchronised->approach)
      for (const char* spin : {"S1", "S2", "S3"})
        cases.push_back({path, spin, fmt::format("target.body.spin_case={}", spin)});
    else
      cases.push_back({path, s.name, ""});
  }
  std::vector<campaign::Table5Column> columns;
  for (const Case& c : cases) {
    std::cerr << fmt::format("comrade-table5: case {}\n", c.name);
    int code = kExitOk;
    std::vector<std::string> overrides;
    if (!c.override_text.empty()) overrides.push_back(c.override_text);
    if (!run_case_campaign(args, c.scenario_path, c.name, overrides, code)) return code;
    std::string error;
    const auto column = campaign::read_table5_column(
        c.name, (std::filesystem::path(args.out_dir) / c.name / "runs.csv").string(), error);
    if (!column) {
      std::cerr << ("chaser campaign: " + error + '\n');
      return kExitFailure;
    }
    columns.push_back(*column);
  }
  const std::filesystem::path out(args.out_dir);
  std::ofstream(out / "table5.md") << campaign::table5_markdown(columns);
  std::ofstream(out / "table5.csv") << campaign::table5_csv(columns);
  std::cout << fmt::format("comrade-table5: wrote {}/table5.md and table5.csv\n", args.out_dir);
  return kExitOk;
}

// The presets that fly whole fault-free campaigns in one process: true (after saying so) where the
// arguments would split them.
bool refuses_split(const CampaignArgs& args, const char* preset) {
  if (!args.mpi && args.shard.empty() && args.cases.empty() && args.also.empty()) return false;
  std::cerr << fmt::format("chaser campaign: --preset {} runs whole fault-free campaigns in one process: "
                           "leave out --mpi, --shard, --cases and --also\n",
                           preset);
  return true;
}

// One fault-free campaign per case (its name, the folder under --out, and its overrides), each
// resumable as any campaign, read back into the preset's column by read(name, runs.csv path, error).
// The columns in the cases' order, or nothing with `code` set.
template <class Column, class Read>
std::optional<std::vector<Column>> case_columns(const CampaignArgs& args, const char* preset,
                                                const std::vector<std::pair<std::string, std::vector<std::string>>>& cases,
                                                Read read, int& code) {
  std::vector<Column> columns;
  for (const auto& [name, overrides] : cases) {
    std::cerr << fmt::format("{}: {}\n", preset, overrides.front());
    if (!run_case_campaign(args, args.scenario_path, name, overrides, code)) return std::nullopt;
    std::string error;
    const std::optional<Column> column = read(name, (std::filesystem::path(args.out_dir) / name / "runs.csv").string(), error);
    if (!column) {
      std::cerr << ("chaser campaign: " + error + '\n');
      code = kExitFailure;
      return std::nullopt;
    }
    columns.push_back(*column);
  }
  return columns;
}

// --preset comrade-reach (docs/servicing.md, "The reach over 100 dispersed runs"): one fault-free
// campaign per combined controller (capture.law hinf, then compliance, the paper's order) of a
// scenario with a capture section, each in its folder under --out and resumable as any campaign;
// then reach.md and reach.csv beside them: COMRADE Tables 5 (reach) and 6.
int comrade_reach(const CampaignArgs& args) {
  if (refuses_split(args, kPresetReach)) return kExitBadInput;
  const auto loaded = load_or_report(args.scenario_path, args.overrides);
  if (!loaded) return kExitBadInput;
  if (!loaded->scenario->capture) {
    std::cerr << fmt::format("chaser campaign: --preset comrade-reach: {} has no capture section: use "
                             "scenarios/comrade_capture.yaml\n",
                             args.scenario_path);
    return kExitBadInput;
  }
  // Each run ends with the reach, when the tool leaves the pre-grasp pose: Tables 5 and 6 are the
  // reach's (the grasp that follows is judged by each run of the scenario as it is).
  const model::Scenario& s = *loaded->scenario;
  const double reach_end_s = std::min(s.duration_s, s.capture->approach_start_s());
  const std::string horizon = fmt::format("campaign.horizon_after_onset_s={}", reach_end_s - s.campaign.onset_s);
  std::vector<std::pair<std::string, std::vector<std::string>>> cases;
  for (const char* law : {"hinf", "compliance"}) cases.push_back({law, {fmt::format("capture.law={}", law), horizon}});
  int code = kExitOk;
  const auto columns = case_columns<campaign::ReachColumn>(args, kPresetReach, cases, campaign::read_reach_column, code);
  if (!columns) return code;
  const std::filesystem::path out(args.out_dir);
  std::ofstream(out / "reach.md") << campaign::reach_markdown(*columns);
  std::ofstream(out / "reach.csv") << campaign::reach_csv(*columns);
  std::cout << fmt::format("comrade-reach: wrote {}/reach.md and reach.csv\n", args.out_dir);
  return kExitOk;
}

// The whole runs of a capture scenario per spin case S1, S2, S3 (comrade-stabilise, comrade-mission):
// refused split, or where the scenario lacks what `has` asks (the section `lacks` names); else one
// fault-free campaign per case, 20 runs unless --runs, each run flying the scenario's whole
// duration_s (a campaign's run ends at onset_s + the horizon), in its folder under --out and
// resumable as any campaign, read back by read(name, runs.csv path, error).
template <class Column, class Read, class Has>
std::optional<std::vector<Column>> spin_case_columns(const CampaignArgs& args, const char* preset, Has has,
                                                     const char* lacks, Read read, int& code) {
  code = kExitBadInput;
  if (refuses_split(args, preset)) return std::nullopt;
  const auto loaded = load_or_report(args.scenario_path, args.overrides);
  if (!loaded) return std::nullopt;
  const model::Scenario& s = *loaded->scenario;
  if (!has(s)) {
    std::cerr << fmt::format("chaser campaign: --preset {}: {} has no {} section: use scenarios/comrade_capture.yaml\n",
                             preset, args.scenario_path, lacks);
    return std::nullopt;
  }
  CampaignArgs with_runs = args;
  if (with_runs.runs.empty()) with_runs.runs = kStabiliseRuns;
  const std::string horizon = fmt::format("campaign.horizon_after_onset_s={}", s.duration_s - s.campaign.onset_s);
  std::vector<std::pair<std::string, std::vector<std::string>>> cases;
  for (const char* spin_case : {"S1", "S2", "S3"})
    cases.push_back({spin_case, {fmt::format("target.body.spin_case={}", spin_case), horizon}});
  code = kExitOk;
  return case_columns<Column>(with_runs, preset, cases, read, code);
}

// --preset comrade-stabilise (docs/servicing.md, "The stabilisation over dispersed runs"): the
// spin cases' campaigns of a scenario with capture.stabilise, each run the whole mission
// (synchronisation, reach, capture, rigidisation, stabilisation); then stabilise.md and
// stabilise.csv beside them: COMRADE Table 8.
int comrade_stabilise(const CampaignArgs& args) {
  int code = kExitOk;
  const auto columns = spin_case_columns<campaign::StabiliseColumn>(
      args, kPresetStabilise,
      [](const model::Scenario& s) { return s.capture && s.capture->stabilise && s.target.body; }, "capture.stabilise",
      campaign::read_stabilise_column, code);
  if (!columns) return code;
  const std::filesystem::path out(args.out_dir);
  std::ofstream(out / "stabilise.md") << campaign::stabilise_markdown(*columns);
  std::ofstream(out / "stabilise.csv") << campaign::stabilise_csv(*columns);
  std::cout << fmt::format("comrade-stabilise: wrote {}/stabilise.md and stabilise.csv\n", args.out_dir);
  return kExitOk;
}

// --preset comrade-mission (docs/servicing.md, "The whole mission over dispersed runs"): the same
// campaigns as comrade-stabilise's (with --resume into its --out they fly nothing again), then
// mission.md and mission.csv beside them: per case the runs meeting every phase's requirements,
// and where the others fail.
int comrade_mission(const CampaignArgs& args) {
  int code = kExitOk;
  const auto columns = spin_case_columns<campaign::MissionColumn>(
      args, kPresetMission,
      [](const model::Scenario& s) { return s.capture && s.guidance.synchronised && s.target.body; }, "capture",
      campaign::read_mission_column, code);
  if (!columns) return code;
  const std::filesystem::path out(args.out_dir);
  std::ofstream(out / "mission.md") << campaign::mission_markdown(*columns);
  std::ofstream(out / "mission.csv") << campaign::mission_csv(*columns);
  std::cout << fmt::format("comrade-mission: wrote {}/mission.md and mission.csv\n", args.out_dir);
  return kExitOk;
}

// --preset comrade-faults (docs/fdi.md, "Every thruster's faults over the whole synchronisation"):
// faults of every kind on every thruster of a synchronised-flight scenario, onsets uniform over
// [duration/10, duration - 100 s]: N runs per kind (--runs N, default 100) for each of COMRADE's
// four, N/5 (at least 1) for every other starting thruster (or those campaign.fault_thrusters
// names), 2N fault-free; each thruster's campaign flown twice, with the scenario's accommodation and
// with diagnosis only (fdi.recovery=none, the same runs: the same seeds); each a campaign in its
// folder under --out, resumable as any; then faults.md and faults.csv beside them (the groups, and
// the others one by one).
int comrade_faults(const CampaignArgs& args) {
  if (args.mpi || !args.shard.empty() || !args.cases.empty() || !args.also.empty()) {
    std::cerr << "chaser campaign: --preset comrade-faults flies its campaigns in one process: leave out --mpi, "
                 "--shard, --cases and --also\n";
    return kExitBadInput;
  }
  int n = kFaultsRuns;
  if (!args.runs.empty()) {
    const auto [end, ec] = std::from_chars(args.runs.data(), args.runs.data() + args.runs.size(), n);
    if (ec != std::errc{} || end != args.runs.data() + args.runs.size() || n < 1 || n > 100000) {
      std::cerr << fmt::format("chaser campaign: --runs: --preset comrade-faults takes a count of runs per fault kind "
                               "for each of COMRADE's four thrusters, in [1, 100000] (got '{}')\n",
                               args.runs);
      return kExitBadInput;
    }
  }
  const auto loaded = load_or_report(args.scenario_path, args.overrides);
  if (!loaded) return kExitBadInput;
  const model::Scenario& s = *loaded->scenario;
  if (!s.guidance.synchronised || !s.target.body) {
    std::cerr << fmt::format("chaser campaign: --preset comrade-faults: {} flies no synchronisation "
                             "(guidance.synchronised, target.body): use scenarios/comrade_sync.yaml\n",
                             args.scenario_path);
    return kExitBadInput;
  }
  const model::ThrusterMask active = model::initial_active_set(s.thrusters);
  model::ThrusterMask four = 0;
  for (const int t : kComradeFourIndices) four |= model::ThrusterMask{1} << t;
  if ((active & four) != four) {
    std::cerr << fmt::format("chaser campaign: --preset comrade-faults: {} does not start with T1, T5, T13 and T17 "
                             "active (COMRADE's four)\n",
                             args.scenario_path);
    return kExitBadInput;
  }
  if (!(s.duration_s > 200.0)) {
    std::cerr << fmt::format("chaser campaign: --preset comrade-faults: duration_s must be > 200 s for the onsets' "
                             "window [duration/10, duration - 100 s] (got {})\n",
                             s.duration_s);
    return kExitBadInput;
  }
  const model::ThrusterMask others = (s.campaign.fault_thrusters != 0 ? s.campaign.fault_thrusters : active) & ~four;
  const std::uint64_t seed = args.seed.value_or(s.campaign.seed);
  const double onset_s = s.duration_s / 10.0;
  // Before the user's --set (which may move the onsets); the thruster, seed and recovery after them.
  const std::vector<std::string> window = {fmt::format("campaign.onset_s={}", onset_s),
                                           fmt::format("campaign.onset_max_s={}", s.duration_s - 100.0),
                                           fmt::format("campaign.horizon_after_onset_s={}", s.duration_s - onset_s)};
  const std::filesystem::path out(args.out_dir);
  const auto fly = [&](const std::string& folder, const std::string& cases, int runs, std::vector<std::string> last,
                       int& code) {
    CampaignArgs sub = args;
    sub.seed.reset();
    sub.overrides.insert(sub.overrides.end(), last.begin(), last.end());
    std::cerr << fmt::format("comrade-faults: {}\n", folder);
    return run_case_campaign(sub, args.scenario_path, folder, window, code, cases, std::to_string(runs));
  };
  int code = kExitOk;
  if (!fly("none", "none", 2 * n, {fmt::format("campaign.seed={}", seed)}, code)) return code;
  std::string error;
  const std::optional<campaign::FaultFreeFigures> fault_free = campaign::read_fault_free((out / "none" / "runs.csv").string(), error);
  if (!fault_free) {
    std::cerr << ("chaser campaign: " + error + '\n');
    return kExitFailure;
  }
  std::vector<campaign::FaultsColumn> columns, each_other;
  for (int t = 0; t < model::kMaxThrusters; ++t) {
    const model::ThrusterMask bit = model::ThrusterMask{1} << t;
    if (!((four | others) & bit)) continue;
    const std::string name = model::thruster_name(t);
    const int runs = (four & bit) ? n : std::max(1, n / 5);
    // Each thruster's own seed: its runs' dispersions and onsets independent of the other thrusters'.
    const std::vector<std::string> mine = {fmt::format("campaign.fault_thrusters=[{}]", name),
                                           fmt::format("campaign.seed={}", seed + static_cast<std::uint64_t>(t) + 1)};
    std::vector<std::string> diagnose = mine;
    diagnose.push_back("fdi.recovery=none");
    const std::string kinds = "stuck_open,stuck_closed,leak,loss";
    if (!fly(name, kinds, runs, mine, code) || !fly("diagnosis-only/" + name, kinds, runs, diagnose, code)) return code;
    campaign::FaultsColumn own{.name = name, .kinds = {}};
    if (!campaign::add_faults_runs(own, (out / name / "runs.csv").string(), false, error) ||
        !campaign::add_faults_runs(own, (out / "diagnosis-only" / name / "runs.csv").string(), true, error)) {
      std::cerr << ("chaser campaign: " + error + '\n');
      return kExitFailure;
    }
    ((four & bit) ? columns : each_other).push_back(own);
  }
  if (!each_other.empty())
    columns.push_back(campaign::pooled_column(fmt::format("other {}", each_other.size()), each_other));
  std::ofstream(out / "faults.md") << campaign::faults_markdown(*fault_free, columns, each_other);
  std::ofstream(out / "faults.csv") << campaign::faults_csv(*fault_free, columns, each_other);
  std::cout << fmt::format("comrade-faults: wrote {}/faults.md and faults.csv\n", args.out_dir);
  return kExitOk;
}

// --rerun ... --of DIR: the campaign the options describe must be the one DIR holds (its
// campaign.json, shards aside): run I of another campaign is another run, and nothing would say so.
std::string check_rerun_of(const std::string& dir, const campaign::CampaignPlan& plan) {
  std::string error;
  const auto found = campaign::read_campaign_json(dir, error);
  if (!found) return fmt::format("--of: {}", error);
  const std::string differ =
      campaign::differing_keys(*found, campaign::campaign_json(plan, campaign::Shard{}), {"shard", "shard_runs"});
  if (!differ.empty())
    return fmt::format("--of: {} holds a different campaign (differs in: {}); give --rerun the campaign's own "
                       "scenario, --set, --seed, --runs, --cases and --preset",
                       dir, differ);
  return "";
}

// "run 6 of 15: case stuck_open, seed 1 (none 5, stuck_open 5, stuck_closed 5)": which campaign the
// options describe, so that a run of another campaign than the user meant is visible.
std::string describe_rerun(const campaign::CampaignPlan& plan, std::int64_t run) {
  std::string cases;
  std::string_view in_case;
  std::int64_t first = 0;
  for (const campaign::CaseRuns& cr : plan.layout.cases()) {
    cases += fmt::format("{}{} {}", cases.empty() ? "" : ", ", campaign::to_string(cr.fault_case), cr.runs);
    if (run >= first && run < first + cr.runs) in_case = campaign::to_string(cr.fault_case);
    first += cr.runs;
  }
  return fmt::format("run {} of {}: case {}, campaign seed {} ({})", run, plan.layout.total_runs(), in_case,
                     plan.nominal.campaign.seed, cases);
}

// --rerun I: run I of the campaign the other options describe, alone, into --out: its
// telemetry.csv and summary.json, and run.csv (the runs.csv header and the run's row, the same
// bytes as in the campaign's runs.csv). Each run depends only on (scenario, seed, index), so a
// campaign's odd run can be looked into without keeping every run's telemetry.
int rerun_one(const CampaignArgs& args) {
  if (args.mpi || !args.shard.empty() || args.resume || args.keep_telemetry != 0 || !args.targets.empty()) {
    std::cerr << "chaser campaign: --rerun flies one run: leave out --mpi, --shard, --resume, --keep-telemetry "
                 "and --target\n";
    return kExitBadInput;
  }
  const std::optional<Prepared> prepared = prepare(args);
  if (!prepared) return kExitBadInput;
  const std::int64_t total = prepared->plan.layout.total_runs();
  const std::int64_t run = *args.rerun;
  if (run < 0 || run >= total) {
    std::cerr << fmt::format("chaser campaign: --rerun: run index must be in [0, {}] for this campaign (got {})\n",
                             total - 1, run);
    return kExitBadInput;
  }
  if (!args.rerun_of.empty()) {
    if (const std::string error = check_rerun_of(args.rerun_of, prepared->plan); !error.empty()) {
      std::cerr << ("chaser campaign: " + error + '\n');
      return kExitBadInput;
    }
  }
  std::cout << "campaign: " << describe_rerun(prepared->plan, run) << '\n';
  const flight::FlightParams flight = flight::make_flight_params(prepared->plan.nominal);
  const campaign::RunOutput out = campaign::run_one(prepared->plan, flight, run, args.out_dir);
  const std::filesystem::path row_path = std::filesystem::path(args.out_dir) / "run.csv";
  std::ofstream row_file(row_path, std::ios::binary);
  row_file << campaign::runs_header(campaign::run_column_set(prepared->plan.nominal)) << '\n' << out.row << '\n';
  if (!row_file) {
    std::cerr << fmt::format("chaser campaign: cannot write {}\n", row_path.string());
    return kExitFailure;
  }
  std::cout << fmt::format("campaign: run {}{}; wrote {}/telemetry.csv, summary.json, run.csv\n", run,
                           out.diverged ? " (diverged or failed)" : "", args.out_dir);
  return kExitOk;
}

// --preset comrade-rigidise (docs/servicing.md, "The rigidisation from COMRADE Table 7's starts"):
// per rigidisation law, the capture flown once and --runs runs (100) from it, each from a drawn
// start of the joints' rates for 120 s, brakes off (campaign/rigidise_study.hpp); each column's runs
// in <law>/runs.csv, Table 7 in rigidise.md and rigidise.csv. Not resumable: it reruns in minutes.
int comrade_rigidise(const CampaignArgs& args) {
  if (args.mpi || !args.shard.empty() || !args.cases.empty() || !args.also.empty() || args.resume ||
      args.keep_telemetry > 0) {
    std::cerr << "chaser campaign: --preset comrade-rigidise flies its runs from one capture in one process: "
                 "leave out --mpi, --shard, --cases, --also, --resume and --keep-telemetry\n";
    return kExitBadInput;
  }
  int runs = kRigidiseRuns;
  if (!args.runs.empty()) {
    const auto parsed = campaign::parse_integer(args.runs);
    if (!parsed || *parsed < 1 || *parsed > 100000) {
      std::cerr << fmt::format("chaser campaign: --runs: --preset comrade-rigidise takes a count of runs per law in "
                               "[1, 100000] (got '{}')\n",
                               args.runs);
      return kExitBadInput;
    }
    runs = static_cast<int>(*parsed);
  }
  const auto loaded = load_or_report(args.scenario_path, args.overrides);
  if (!loaded) return kExitBadInput;
  const model::Scenario& s = *loaded->scenario;
  if (!s.capture || !s.capture->rigidise || !s.target.body) {
    std::cerr << fmt::format("chaser campaign: --preset comrade-rigidise: {} has no capture.rigidise section: use "
                             "scenarios/comrade_capture.yaml\n",
                             args.scenario_path);
    return kExitBadInput;
  }
  const std::filesystem::path out(args.out_dir);
  std::vector<campaign::RigidiseColumn> columns;
  for (const campaign::RigidiseColumnSpec& spec : campaign::comrade_table7_columns(runs)) {
    std::cerr << fmt::format("comrade-rigidise: capture.rigidise.law {}: the capture, then {} runs of {:g} s\n", spec.name,
                             spec.runs, spec.duration_s);
    try {
      columns.push_back(campaign::run_rigidise_column(s, spec, args.threads.value_or(default_worker_threads())));
    } catch (const std::exception& e) {
      std::cerr << fmt::format("chaser campaign: --preset comrade-rigidise: {}\n", e.what());
      return kExitFailure;
    }
    std::filesystem::create_directories(out / spec.name);
    std::ofstream(out / spec.name / "runs.csv") << campaign::rigidise_runs_csv(columns.back());
  }
  std::ofstream(out / "rigidise.md") << campaign::rigidise_markdown(columns);
  std::ofstream(out / "rigidise.csv") << campaign::rigidise_csv(columns);
  std::cout << fmt::format("comrade-rigidise: wrote {}/rigidise.md and rigidise.csv\n", args.out_dir);
  return kExitOk;
}

}  // namespace

int campaign_command(const CampaignArgs& args) {
  if (!args.rerun_of.empty() && !args.rerun) {
    std::cerr << "chaser campaign: --of: only with --rerun\n";
    return kExitBadInput;
  }
  if (args.rerun) {
    if (args.preset == kPresetTable5 || args.preset == kPresetReach || args.preset == kPresetStabilise ||
        args.preset == kPresetMission || args.preset == kPresetRigidise || args.preset == kPresetFaults ||
        !args.also.empty()) {
      std::cerr << "chaser campaign: --rerun: not with --preset comrade-table5, comrade-reach, comrade-stabilise, comrade-mission, comrade-faults or --also (rerun one "
                   "case's folder: its scenario with --set target.body.spin_case=S1|S2|S3 or capture.law=hinf|"
                   "compliance, and --cases none)\n";
      return kExitBadInput;
    }
    return rerun_one(args);
  }
  if (args.preset == kPresetTable5) return comrade_table5(args);
  if (args.preset == kPresetReach) return comrade_reach(args);
  if (args.preset == kPresetStabilise) return comrade_stabilise(args);
  if (args.preset == kPresetMission) return comrade_mission(args);
  if (args.preset == kPresetRigidise) return comrade_rigidise(args);
  if (args.preset == kPresetFaults) return comrade_faults(args);
  if (!args.also.empty()) {
    std::cerr << "chaser campaign: --also: only with --preset comrade-table5\n";
    return kExitBadInput;
  }
  if (args.mpi && !campaign::mpi_built()) {
    std::cerr << ("chaser campaign: " + std::string(campaign::kNoMpiMessage) + '\n');
    return kExitBadInput;
  }
  if (args.mpi) return campaign_mpi(args);
  const std::optional<Prepared> prepared = prepare(args);
  if (!prepared) return kExitBadInput;
  const int code = report(campaign::run_campaign(prepared->plan, prepared->options), args.out_dir);
  if (code == kExitOk) print_targets(args.out_dir, prepared->cases(), prepared->options.targets);
  return code;
}

int campaign_merge_command(const CampaignMergeArgs& args) {
  const auto targets = parse_targets(args.targets);
  if (!targets) return kExitBadInput;
  const int code = report(campaign::merge_shards(args.out_dir, args.shard_dirs, *targets), args.out_dir);
  if (code == kExitOk && !targets->empty()) {
    std::string error;
    const auto json = campaign::read_campaign_json(args.out_dir, error);
    const auto info = json ? campaign::campaign_info(*json, error) : std::nullopt;
    std::vector<campaign::FaultCase> cases;
    if (info)
      for (const campaign::CaseRuns& c : info->cases) cases.push_back(c.fault_case);
    print_targets(args.out_dir, cases, *targets);
  }
  return code;
}

}  // namespace chaser::cli
