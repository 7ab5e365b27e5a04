#include "invsim/pulse_conversion.hpp"

#include <algorithm>
#include <cmath>

namespace chaser::invsim {

Pulse convert_to_opening(const PulseParams& p, double u) {
  const double ratio = std::abs(u) / p.u_max_mps2;  // dtau / tau by eq. 1
  const double k = std::min(p.time_sensitivity, p.accel_sensitivity);
  if (!(std::abs(u) / p.dead_zone_u_max_mps2 > k)) return {0, 0.0};  // eqs. 3-4 (also catches NaN)
  return {u > 0.0 ? 1 : -1, ratio * p.step_s};
}

Pulse convert_to_pulse(const PulseParams& p, double u) {
  Pulse pulse = convert_to_opening(p, u);
  pulse.on_time_s = std::min(pulse.on_time_s, p.step_s);  // the group open for the whole step at most
  return pulse;
}

}  // namespace chaser::invsim
