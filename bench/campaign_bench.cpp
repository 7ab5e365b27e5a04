// Campaign throughput: a small campaign (4 runs of each fault case and 4 fault-free, 1200 s each,
// both FDI schemes on) through run_campaign, on 1 and 2 threads: runs per wall second and simulated
// seconds per wall second. The FDI design (once per campaign) is included, as a user meets it.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "campaign/campaign.hpp"
#include "io/scenario_loader.hpp"

namespace {

using namespace chaser;

void BM_Campaign(benchmark::State& state) {
  const io::LoadResult loaded = io::load_scenario_file(CHASER_SOURCE_DIR "/scenarios/msr_terminal.yaml");
  if (!loaded.scenario) {
    std::cerr << io::format_errors(loaded.errors);
    std::abort();
  }
  using campaign::FaultCase;
  const campaign::CampaignPlan plan{*loaded.scenario, loaded.hash,
                                    campaign::RunLayout({{FaultCase::kNone, 4}, {FaultCase::kStuckOpen, 4},
                                                         {FaultCase::kStuckClosed, 4}, {FaultCase::kLeak, 4},
                                                         {FaultCase::kLoss, 4}})};
  const auto dir = std::filesystem::temp_directory_path() / "chaser_campaign_bench";
  double runs = 0, simulated_s = 0;
  for (auto _ : state) {
    std::filesystem::remove_all(dir);
    campaign::CampaignOptions options;
    options.out_dir = dir.string();
    options.threads = static_cast<int>(state.range(0));
    const campaign::CampaignOutcome outcome = campaign::run_campaign(plan, options);
    if (outcome.status != campaign::CampaignStatus::kOk) state.SkipWithError(outcome.message.c_str());
    runs += static_cast<double>(outcome.executed.runs);
    simulated_s += outcome.simulated_s;
  }
  std::filesystem::remove_all(dir);
  state.counters["runs_per_s"] = benchmark::Counter(runs, benchmark::Counter::kIsRate);
  state.counters["sim_s_per_wall_s"] = benchmark::Counter(simulated_s, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Campaign)->Arg(1)->Arg(2)->ArgName("threads")->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace
