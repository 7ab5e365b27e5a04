// chaser campaign: a Monte Carlo campaign (or one shard of it), and chaser campaign merge
// (docs/campaigns.md).
#include <iostream>
#include <optional>
#include <thread>

#include <fmt/format.h>

#include "campaign/campaign.hpp"
#include "campaign/campaign_json.hpp"
#include "campaign/merge.hpp"
#include "campaign/mpi_runner.hpp"
#include "campaign/progress.hpp"
#include "cli/commands.hpp"
#include "cli/scenario_input.hpp"

namespace chaser::cli {

namespace {

constexpr const char* kPresetTable2 = "fonod2015-table2";
// Fonod 2015, section V: 200 fault-free runs, 1600 runs per fault case, each scheme judged alone.
constexpr const char* kTable2Runs = "none=200,stuck_open=1600,stuck_closed=1600,leak=1600,loss=1600";

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
};

std::optional<Prepared> prepare(const CampaignArgs& args) {
  std::vector<std::string> overrides;
  std::string runs_text = args.runs;
  if (!args.preset.empty()) {
    if (args.preset != kPresetTable2) {
      std::cerr << fmt::format("chaser campaign: --preset: unknown preset '{}' (allowed: {})\n", args.preset,
                               kPresetTable2);
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
  const auto loaded = load_or_report(args.scenario_path, overrides);
  if (!loaded) return std::nullopt;
  const auto layout = campaign::parse_layout(args.cases, runs_text,
                                             static_cast<std::int64_t>(loaded->scenario->campaign.runs_per_case));
  if (!layout.error.empty()) {
    std::cerr << ("chaser campaign: " + layout.error + '\n');
    return std::nullopt;
  }
  // With --mpi every rank is one process per core by default: one worker thread each.
  const int default_threads = args.mpi ? 1 : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return Prepared{campaign::CampaignPlan{*loaded->scenario, loaded->hash, campaign::RunLayout(layout.cases)},
                  campaign::CampaignOptions{.out_dir = args.out_dir,
                                            .shard = *shard.shard,
                                            .threads = args.threads.value_or(default_threads),
                                            .resume = args.resume,
                                            .keep_telemetry = args.keep_telemetry,
                                            .progress = campaign::stderr_is_terminal()}};
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
  return rank == 0 ? report(outcome, args.out_dir) : kExitOk;
}

}  // namespace

int campaign_command(const CampaignArgs& args) {
  if (args.mpi && !campaign::mpi_built()) {
    std::cerr << ("chaser campaign: " + std::string(campaign::kNoMpiMessage) + '\n');
    return kExitBadInput;
  }
  if (args.mpi) return campaign_mpi(args);
  const std::optional<Prepared> prepared = prepare(args);
  if (!prepared) return kExitBadInput;
  return report(campaign::run_campaign(prepared->plan, prepared->options), args.out_dir);
}

int campaign_merge_command(const CampaignMergeArgs& args) {
  return report(campaign::merge_shards(args.out_dir, args.shard_dirs), args.out_dir);
}

}  // namespace chaser::cli
