#pragma once
// What chaser campaign --target reports, per target and per case (and scheme, for the FDI indices):
// the runs that would demonstrate it with no failure, and whether this campaign's runs do
// (target.hpp). The same verdicts as summary.md's "Targets" section and as terminal lines.
#include <string>
#include <vector>

#include "campaign/statistics.hpp"
#include "campaign/target.hpp"

namespace chaser::campaign {

std::string targets_markdown(const CampaignStats& stats, const std::vector<Target>& targets);
std::string targets_text(const CampaignStats& stats, const std::vector<Target>& targets);

}  // namespace chaser::campaign
