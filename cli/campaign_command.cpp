// chaser campaign: a Monte Carlo campaign (or one shard of it), and chaser campaign merge
// (docs/campaigns.md).
#include <iostream>
#include <thread>

#include <fmt/format.h>

#include "campaign/campaign.hpp"
#include "campaign/merge.hpp"
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
    std::cerr << "chaser campaign: " << o.message << '\n';
    return kExitBadInput;
  }
  if (o.status == campaign::CampaignStatus::kFailure) {
    std::cerr << "chaser campaign: " << o.message << '\n';
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

}  // namespace

int campaign_command(const CampaignArgs& args) {
  std::vector<std::string> overrides;
  std::string runs_text = args.runs;
  if (!args.preset.empty()) {
    if (args.preset != kPresetTable2) {
      std::cerr << fmt::format("chaser campaign: --preset: unknown preset '{}' (allowed: {})\n", args.preset,
                               kPresetTable2);
      return kExitBadInput;
    }
    overrides.push_back("fdi.recovery=false");  // the paper evaluates each scheme alone
    if (runs_text.empty() && args.cases.empty()) runs_text = kTable2Runs;
  }
  if (args.seed) overrides.push_back(fmt::format("campaign.seed={}", *args.seed));
  overrides.insert(overrides.end(), args.overrides.begin(), args.overrides.end());  // the user's --set win

  const campaign::ShardParse shard = campaign::parse_shard(args.shard.empty() ? "0/1" : args.shard);
  if (!shard.shard) {
    std::cerr << "chaser campaign: " << shard.error << '\n';
    return kExitBadInput;
  }
  if (args.threads && *args.threads < 1) {
    std::cerr << fmt::format("chaser campaign: --threads: must be >= 1 (got {})\n", *args.threads);
    return kExitBadInput;
  }
  if (args.keep_telemetry < 0) {
    std::cerr << fmt::format("chaser campaign: --keep-telemetry: must be >= 0 (got {})\n", args.keep_telemetry);
    return kExitBadInput;
  }
  const auto loaded = load_or_report(args.scenario_path, overrides);
  if (!loaded) return kExitBadInput;
  const auto layout = campaign::parse_layout(args.cases, runs_text,
                                             static_cast<std::int64_t>(loaded->scenario->campaign.runs_per_case));
  if (!layout.error.empty()) {
    std::cerr << "chaser campaign: " << layout.error << '\n';
    return kExitBadInput;
  }
  const campaign::CampaignPlan plan{*loaded->scenario, loaded->hash, campaign::RunLayout(layout.cases)};
  const int threads = args.threads ? *args.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const campaign::CampaignOptions options{.out_dir = args.out_dir,
                                          .shard = *shard.shard,
                                          .threads = threads,
                                          .resume = args.resume,
                                          .keep_telemetry = args.keep_telemetry,
                                          .progress = campaign::stderr_is_terminal()};
  return report(campaign::run_campaign(plan, options), args.out_dir);
}

int campaign_merge_command(const CampaignMergeArgs& args) {
  return report(campaign::merge_shards(args.out_dir, args.shard_dirs), args.out_dir);
}

}  // namespace chaser::cli
