#pragma once
// The fault of one campaign run (Fonod 2015, section V): a thruster uniform over the eight active
// ones (branch A), the onset of the campaign, and a size uniform in the case's range. A campaign may
// narrow the thrusters (campaign.fault_thrusters) and spread the onsets (campaign.onset_max_s).
#include <cstdint>
#include <optional>

#include "campaign/cases.hpp"
#include "model/campaign.hpp"
#include "model/faults.hpp"
#include "model/thrusters.hpp"

namespace chaser::campaign {

// Draws from the stream "campaign/fault" of the run seed: the thruster, uniformly among
// `candidates` (the starting active set: the thrusters that fly when the fault strikes) or among
// campaign.fault_thrusters where given, then the size (leak and loss only), then the onset where
// campaign.onset_max_s is given. Case none has no fault.
std::optional<model::FaultParams> sample_fault(FaultCase fault_case, const model::CampaignParams& params,
                                               model::ThrusterMask candidates, std::uint64_t run_seed);

// The size the runs.csv row reports: 1 for stuck cases, the leak or loss size, 0 without a fault.
double fault_size(const std::optional<model::FaultParams>& fault);

}  // namespace chaser::campaign
