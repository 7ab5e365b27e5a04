#pragma once
// DIR/campaign.json: what the campaign is. Written first; --resume and merge check it. It holds no
// wall-clock figure, so a merged campaign's file is byte-identical to a one-go campaign's.
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "campaign/cases.hpp"
#include "campaign/plan.hpp"
#include "campaign/summary.hpp"

namespace chaser::campaign {

nlohmann::ordered_json campaign_json(const CampaignPlan& plan, const Shard& shard);
std::string campaign_json_text(const nlohmann::ordered_json& j);  // 2-space indent and a newline

// Reads DIR/campaign.json; nullopt with `error` set if missing or not a campaign file.
std::optional<nlohmann::ordered_json> read_campaign_json(const std::string& dir, std::string& error);

// What a campaign.json says, for merge and the summary.
struct CampaignInfo {
  std::vector<CaseRuns> cases;
  std::uint64_t seed = 0;
  Shard shard;
  RunRange range;
  SummaryContext summary;
};
std::optional<CampaignInfo> campaign_info(const nlohmann::ordered_json& j, std::string& error);

// The keys whose values differ (both ways), comma-separated; empty when the documents agree on
// every key not in `ignored`.
std::string differing_keys(const nlohmann::ordered_json& a, const nlohmann::ordered_json& b,
                           const std::vector<std::string>& ignored = {});

}  // namespace chaser::campaign
