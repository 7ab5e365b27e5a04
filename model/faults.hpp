#pragma once
// Thruster faults (Fonod 2015, section II.D, eqs. 3-5). Faults are truth: only the plant reads them.
#include <string_view>

namespace chaser::model {

enum class FaultKind { kStuckOpen, kStuckClosed, kLeak, kLoss };

// Case 1 stuck open (realised on-time 1), case 2 blocked closed (0), case 3 leakage ramp
// m_leak(t) = min(slope (t - t_f), size) as a lower saturation of the on-time, case 4 thrust loss
// (1 - size) of the commanded impulse.
struct FaultParams {
  FaultKind kind = FaultKind::kStuckOpen;
  int thruster = 0;            // index 0..N-1 into the scenario's thrusters (T1 is 0)
  double onset_s = 1000.0;     // [s] t_f
  double leak_size = 0.2;      // [-] \hat m_leak, case 3
  double leak_slope_per_s = 0.1;  // [1/s] m_s, case 3
  double loss_size = 0.5;      // [-] \hat m_loss, case 4
};

std::string_view to_string(FaultKind kind);

}  // namespace chaser::model
