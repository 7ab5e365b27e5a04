#pragma once
// Thruster fault effects on the realised on-time (Fonod 2015, section II.D, eqs. 3-5).
//
// phi_i = max(Ton_i, m_leak(t))   case 1 (stuck open, m_leak = 1) and case 3 (leak)      eq. 5
// phi_i = (1 - m_loss) Ton_i      case 2 (blocked closed, m_loss = 1) and case 4 (loss)
// with m_leak(t) = min(m_s (t - t_f), \hat m_leak).
//
// Timing rule: faults are evaluated at the control period start t_k. A fault with onset t_f acts in
// period k iff t_k >= t_f (an onset between two period starts takes effect at the next one), and the
// leak size used for the whole period is m_leak(t_k). Faults are permanent once active.
#include <array>
#include <span>

#include "core/time.hpp"
#include "model/faults.hpp"
#include "model/thrusters.hpp"

namespace chaser::plant {

// What the active fault of one thruster does during one control period. A healthy thruster has the
// default values.
struct ThrusterFaultEffect {
  bool stuck_open = false;    // case 1: valve open the whole time, across periods; phi = 1
  bool blocked = false;       // case 2: valve never opens (and closes at t_k if it was open); phi = 0
  double ton_floor = 0.0;     // [-] case 3: m_leak(t_k), lower saturation of the on-time
  double thrust_scale = 1.0;  // [-] case 4: 1 - m_loss, thrust (and mass flow) level while open
};
using FaultEffects = std::array<ThrusterFaultEffect, model::kMaxThrusters>;

// True when the fault acts in the period starting at t_k (t_k >= t_f).
bool fault_active(const model::FaultParams& fault, TimeNs t_k);

// m_leak(t_k) = min(m_s (t_k - t_f), \hat m_leak) for an active leak, 0 otherwise (case 3).
double leak_size(const model::FaultParams& fault, TimeNs t_k);

// Effects on every thruster during the period starting at t_k. Faults naming a thruster outside
// 0..kMaxThrusters-1 are ignored (the scenario validator rejects them). At most one fault per thruster is
// expected; if several are given they are applied in order and combine.
FaultEffects evaluate_faults(std::span<const model::FaultParams> faults, TimeNs t_k);

// Fonod 2015, eq. 5: realised scaled on-time phi_i of a commanded scaled on-time ton (0..1).
double realised_on_time(const ThrusterFaultEffect& effect, double ton);

}  // namespace chaser::plant
