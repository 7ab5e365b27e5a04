#include "plant/thruster_faults.hpp"

#include <algorithm>

namespace chaser::plant {

bool fault_active(const model::FaultParams& fault, TimeNs t_k) { return t_k >= from_seconds(fault.onset_s); }

double leak_size(const model::FaultParams& fault, TimeNs t_k) {
  if (fault.kind != model::FaultKind::kLeak || !fault_active(fault, t_k)) return 0.0;
  const double elapsed_s = to_seconds(t_k - from_seconds(fault.onset_s));
  return std::min(fault.leak_slope_per_s * elapsed_s, fault.leak_size);
}

FaultEffects evaluate_faults(std::span<const model::FaultParams> faults, TimeNs t_k) {
  FaultEffects effects{};
  for (const model::FaultParams& fault : faults) {
    if (fault.thruster < 0 || fault.thruster >= model::kMaxThrusters || !fault_active(fault, t_k)) continue;
    ThrusterFaultEffect& e = effects[static_cast<std::size_t>(fault.thruster)];
    switch (fault.kind) {
      case model::FaultKind::kStuckOpen: e.stuck_open = true; break;
      case model::FaultKind::kStuckClosed: e.blocked = true; break;
      case model::FaultKind::kLeak: e.ton_floor = std::max(e.ton_floor, leak_size(fault, t_k)); break;
      case model::FaultKind::kLoss: e.thrust_scale *= 1.0 - fault.loss_size; break;
    }
  }
  return effects;
}

double realised_on_time(const ThrusterFaultEffect& effect, double ton) {
  if (effect.blocked) return 0.0;
  if (effect.stuck_open) return 1.0;
  return effect.thrust_scale * std::max(ton, effect.ton_floor);
}

}  // namespace chaser::plant
