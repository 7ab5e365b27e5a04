// The plain chaser's side of campaign/mpi_runner.hpp: no MPI linked (its libraries cost every
// command 2.5 ms of start-up); `--mpi` makes main replace the process with chaser-mpi, and these
// answer only where that binary was not built (no MPI found): --mpi then says so.
#include "campaign/mpi_runner.hpp"

namespace chaser::campaign {

bool mpi_built() { return false; }

MpiSession::MpiSession(int&, char**&) : error_(kNoMpiMessage) {}

MpiSession::~MpiSession() = default;

int mpi_rank() { return 0; }

bool mpi_all_agree(const std::string& campaign, int) { return !campaign.empty(); }

CampaignOutcome run_campaign_mpi(const CampaignPlan&, const CampaignOptions&, int) {
  CampaignOutcome outcome;
  outcome.status = CampaignStatus::kBadInput;
  outcome.message = std::string(kNoMpiMessage);
  return outcome;
}

}  // namespace chaser::campaign
