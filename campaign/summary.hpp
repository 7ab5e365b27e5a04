#pragma once
// The campaign's result files, derived only from the files of the run rows (runs.csv, glr_runs.csv)
// read in run-index order: summary.csv, summary.md and glr_envelope.csv (docs/campaigns.md).
// An interrupted-and-resumed, a sharded-and-merged and a one-go campaign therefore write the same
// bytes.
#include <optional>
#include <string>
#include <vector>

#include "campaign/cases.hpp"
#include "campaign/glr_envelope.hpp"
#include "campaign/statistics.hpp"
#include "campaign/target.hpp"

namespace chaser::campaign {

// Streams runs.csv into the statistics; nullopt with a message if the file is not a runs file.
struct StatsRead {
  std::optional<CampaignStats> stats;
  std::string error;
};
StatsRead read_campaign_stats(const std::string& runs_path, const std::vector<FaultCase>& cases);

// What the summary states besides the statistics.
struct SummaryContext {
  std::string scenario;          // scenario name
  double threshold_margin = 1.5; // [-] campaign.threshold_margin
  double glr_threshold = 20.0;   // [-] fdi.glr_threshold the campaign flew
  std::vector<Target> targets;   // --target: judged in summary.md's "Targets" section
};

std::string summary_csv(const CampaignStats& stats);
std::string summary_markdown(const CampaignStats& stats, const SummaryContext& context,
                             const std::optional<GlrEnvelope>& envelope);

// Reads DIR/runs.csv (and DIR/glr_runs.csv when case none ran) and writes summary.csv,
// summary.md and glr_envelope.csv in DIR. Returns an error message, empty on success.
std::string write_summaries(const std::string& dir, const std::vector<FaultCase>& cases,
                            const SummaryContext& context);

}  // namespace chaser::campaign
