#pragma once
// What a campaign is: the nominal scenario (overrides applied, validated), the run layout, and how
// the truth of each run is made from them. Pure data and pure functions: any runner (threads,
// shards, an MPI rank) can make run i anywhere and get the same bits.
#include <cstdint>
#include <optional>
#include <string>

#include "campaign/cases.hpp"
#include "model/faults.hpp"
#include "model/scenario.hpp"

namespace chaser::campaign {

struct CampaignPlan {
  model::Scenario nominal;   // the validated scenario; nominal.campaign holds the campaign keys
  std::string scenario_hash; // io::LoadResult::hash of the scenario after every override
  RunLayout layout{{}};
};

// Seconds each run flies: campaign.onset_s + campaign.horizon_after_onset_s.
double run_duration_s(const model::Scenario& nominal);

// The truth of run `run`: seed = run_seed(campaign seed, run), the dispersed chaser, the sampled
// fault replacing the scenario's faults list, and the campaign's run duration.
struct RunSetup {
  std::int64_t run = 0;
  std::uint64_t seed = 0;
  FaultCase fault_case = FaultCase::kNone;
  std::optional<model::FaultParams> fault;
  model::Scenario truth;
};

RunSetup make_run_setup(const CampaignPlan& plan, std::int64_t run);

}  // namespace chaser::campaign
