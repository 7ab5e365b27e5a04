#pragma once
// chaser campaign merge --out DIR SHARD_DIR...: the complete shards of one campaign into one
// campaign directory, byte-identical to the same campaign run in one go (docs/campaigns.md).
#include <string>
#include <vector>

#include "campaign/campaign.hpp"

namespace chaser::campaign {

// Checks that the shards are the m shards of one campaign (same campaign.json but for the shard),
// each exactly once and complete, then concatenates their rows in shard order and writes the
// summaries (with `targets` judged in summary.md). kBadInput with a message naming the offending
// directory otherwise.
CampaignOutcome merge_shards(const std::string& out_dir, const std::vector<std::string>& shard_dirs,
                             const std::vector<Target>& targets = {});

}  // namespace chaser::campaign
