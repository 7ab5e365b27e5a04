#pragma once
// One campaign run from its index alone: the seam every runner uses (thread pool, shard, and an
// MPI rank later). Pure: the same (plan, flight params, index) gives the same bytes anywhere.
#include <cstdint>
#include <string>

#include "campaign/plan.hpp"
#include "flight/flight_software.hpp"

namespace chaser::campaign {

struct RunOutput {
  std::int64_t run = 0;
  std::string row;       // the runs.csv row, no newline
  std::string glr_line;  // fault-free runs: the glr_runs.csv line (glr_envelope.hpp), no newline; else empty
  bool diverged = false; // status diverged or error (for the progress line)
};

// Flies run `run` of the plan with the flight software designed once from the nominal scenario.
// Never throws: a run that throws is recorded with status error. With `telemetry_dir` non-empty the
// run also writes telemetry.csv and summary.json there (the directory is created).
RunOutput run_one(const CampaignPlan& plan, const flight::FlightParams& flight, std::int64_t run,
                  const std::string& telemetry_dir = "");

}  // namespace chaser::campaign
