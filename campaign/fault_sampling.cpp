#include "campaign/fault_sampling.hpp"

#include <algorithm>

#include "core/random.hpp"
#include "model/thrusters.hpp"

namespace chaser::campaign {

namespace {

model::FaultKind kind_of(FaultCase c) {
  switch (c) {
    case FaultCase::kStuckClosed: return model::FaultKind::kStuckClosed;
    case FaultCase::kLeak: return model::FaultKind::kLeak;
    case FaultCase::kLoss: return model::FaultKind::kLoss;
    default: return model::FaultKind::kStuckOpen;
  }
}

}  // namespace

std::optional<model::FaultParams> sample_fault(FaultCase fault_case, const model::CampaignParams& params,
                                               model::ThrusterMask candidates, std::uint64_t run_seed) {
  if (fault_case == FaultCase::kNone) return std::nullopt;
  RandomStream rng(run_seed, "campaign/fault");
  model::FaultParams f;
  f.kind = kind_of(fault_case);
  const model::ThrusterMask among = params.fault_thrusters != 0 ? params.fault_thrusters : candidates;
  const model::ThrusterList list = model::thruster_list(among);
  const int drawn = static_cast<int>(rng.uniform() * list.count);
  f.thruster = list.index[static_cast<std::size_t>(std::clamp(drawn, 0, std::max(list.count - 1, 0)))];
  f.onset_s = params.onset_s;
  f.leak_slope_per_s = params.leak_slope_per_s;
  if (fault_case == FaultCase::kLeak) f.leak_size = rng.uniform(params.leak_size_min, params.leak_size_max);
  if (fault_case == FaultCase::kLoss) f.loss_size = rng.uniform(params.loss_size_min, params.loss_size_max);
  if (params.onset_max_s) f.onset_s = rng.uniform(params.onset_s, *params.onset_max_s);
  return f;
}

double fault_size(const std::optional<model::FaultParams>& fault) {
  if (!fault) return 0.0;
  switch (fault->kind) {
    case model::FaultKind::kLeak: return fault->leak_size;
    case model::FaultKind::kLoss: return fault->loss_size;
    default: return 1.0;
  }
}

}  // namespace chaser::campaign
