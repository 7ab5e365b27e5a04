#include "sim/berth_result.hpp"

#include <cmath>

#include "core/constants.hpp"

namespace chaser::sim {

void add_berth_period(BerthResult& r, const plant::BerthState& truth, const model::BerthingParams& params) {
  r.flown = true;
  r.contact_force_limit_N = params.contact_force_limit_N;
  r.peak_contact_N = truth.peak_contact_N;
  r.peak_hold_N = truth.peak_hold_N;
  if (truth.latched) {
    r.soft_dock_s = truth.latch_s;
    r.latch_offset_m = truth.latch_offset_m;
    r.latch_attitude_deg = truth.latch_attitude_rad / kDegToRad;
    r.pins_jammed = truth.pins_jammed;
  }
  if (truth.hard_docked) {
    r.hard_dock_s = truth.hard_dock_s;
    r.mate_offset_m = truth.mate_offset_m;
    r.mate_attitude_deg = truth.mate_attitude_rad / kDegToRad;
  }
}

bool berth_meets_requirements(const BerthResult& r) {
  return r.flown && std::isfinite(r.hard_dock_s) && r.peak_contact_N <= r.contact_force_limit_N;
}

}  // namespace chaser::sim
