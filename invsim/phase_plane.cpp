#include "invsim/phase_plane.hpp"

#include <algorithm>
#include <cmath>

namespace chaser::invsim {
namespace {

// 0 if not on the negative side, else 1, 2, 3 for R11, R12, R13.
int negative_area(const model::InvSimPhasePlaneParams& p, double a0, double theta, double rate) {
  const double sigma = theta + rate * std::abs(rate) / (2.0 * a0);
  if (rate > p.rate_border_s_radps) return 1;
  if (sigma > p.d_rad && rate > p.rate_border_t_radps) return 1;
  if (sigma > p.d_rad && std::abs(rate) <= p.rate_border_t_radps) return 2;
  if (sigma > p.d_rad - p.delta_rad && sigma <= p.d_rad && rate > p.rate_border_t_radps) return 3;
  return 0;
}

}  // namespace

PhasePlaneArea phase_plane_area(const model::InvSimPhasePlaneParams& p, double a0, double theta,
                                double rate) {
  switch (negative_area(p, a0, theta, rate)) {
    case 1: return PhasePlaneArea::kR11;
    case 2: return PhasePlaneArea::kR12;
    case 3: return PhasePlaneArea::kR13;
    default: break;
  }
  switch (negative_area(p, a0, -theta, -rate)) {
    case 1: return PhasePlaneArea::kR21;
    case 2: return PhasePlaneArea::kR22;
    case 3: return PhasePlaneArea::kR23;
    default: return PhasePlaneArea::kR0;
  }
}

PhasePlaneCommand step_phase_plane(const model::InvSimPhasePlaneParams& p, double a0, double theta,
                                   double rate) {
  const PhasePlaneArea area = phase_plane_area(p, a0, theta, rate);
  double btc = p.btc1;
  int direction = 0;
  switch (area) {
    case PhasePlaneArea::kR11: btc = p.btc3; direction = -1; break;
    case PhasePlaneArea::kR12:
    case PhasePlaneArea::kR13: btc = p.btc2; direction = -1; break;
    case PhasePlaneArea::kR21: btc = p.btc3; direction = 1; break;
    case PhasePlaneArea::kR22:
    case PhasePlaneArea::kR23: btc = p.btc2; direction = 1; break;
    case PhasePlaneArea::kR0: break;
  }
  const double on_time = std::clamp(btc, 0.0, 1.0) * p.period_s;
  if (direction == 0 || on_time <= 0.0) return {area, 0, 0.0};
  return {area, direction, on_time};
}

}  // namespace chaser::invsim
