#include "invsim/pulse_conversion.hpp"

#include <algorithm>
#include <cmath>

namespace chaser::invsim {

Pulse convert_to_pulse(const PulseParams& p, double u) {
  const double ratio = std::abs(u) / p.u_max_mps2;  // dtau / tau by eq. 1
  const double k = std::min(p.time_sensitivity, p.accel_sensitivity);
  if (!(std::abs(u) / p.dead_zone_u_max_mps2 > k)) return {0, 0.0};  // eqs. 3-4 (also catches NaN)
  return {u > 0.0 ? 1 : -1, std::min(ratio, 1.0) * p.step_s};
}

}  // namespace chaser::invsim
