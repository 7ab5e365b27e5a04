#pragma once
// chaser campaign --mpi: the runs of one campaign (or shard) spread over MPI ranks (docs/campaigns.md,
// "MPI"). Rank 0's main thread is the coordinator and the writer: it hands out run indices in
// increasing order, to the other ranks on request and to its own worker threads through a shared
// counter, and feeds every finished row to the in-order RowsWriter through a bounded reorder buffer,
// exactly as the thread pool does. The other ranks design the flight software once, then loop:
// ask for a run, fly it with run_one, send its row back. Every rank computes run i the same way, so
// the result files are byte-identical to a campaign without MPI. Only each rank's main thread calls
// MPI (MPI_THREAD_FUNNELED).
//
// This header does not include mpi.h. Two implementations (campaign/mpi/): chaser-mpi links the
// runner over MPI (mpi_runner.cpp); the plain chaser links stubs (no_mpi.cpp: mpi_built() false),
// and its main hands an --mpi command line to chaser-mpi.
#include <string>
#include <string_view>

#include "campaign/campaign.hpp"

namespace chaser::campaign {

inline constexpr std::string_view kNoMpiMessage =
    "--mpi: this chaser was built without MPI (install OpenMPI, e.g. libopenmpi-dev, and rebuild)";

// Whether this chaser was built with MPI.
bool mpi_built();

// MPI_Init_thread (funneled) on construction, MPI_Finalize on destruction. Construct it first in
// main, and only in MPI mode. Without MPI: does nothing, ok() is false.
class MpiSession {
 public:
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  bool ok() const { return error_.empty(); }
  const std::string& error() const { return error_; }
  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  bool initialized_ = false;
  int rank_ = 0;
  int size_ = 1;
  std::string error_;
};

// This process's rank in MPI_COMM_WORLD (after MpiSession); 0 without MPI.
int mpi_rank();

// A collective over all ranks: true when every rank could prepare its campaign (`campaign` is its
// campaign.json text: scenario after overrides, cases, seed, shard; empty when it could not) and
// all prepared rank 0's. Lets all ranks stop together instead of one waiting forever or flying
// another campaign (a scenario file missing or different on one node).
bool mpi_all_agree(const std::string& campaign, int rank);

// Every rank calls it with the same plan and options. Rank 0 runs run_campaign with the runs spread
// over all ranks (options.threads worker threads on rank 0 besides the coordinator, and on every
// other rank) and returns its outcome; another rank serves runs until rank 0 says stop and returns
// kOk with executed.runs = the runs it flew. A rank that fails calls MPI_Abort with a message.
CampaignOutcome run_campaign_mpi(const CampaignPlan& plan, const CampaignOptions& options, int rank);

}  // namespace chaser::campaign
