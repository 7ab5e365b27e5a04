#pragma once
// ASSIST's berthing judged (model/capture.hpp's BerthingParams; the paper states no figures for it):
// the soft dock (the latches closed on the probe's tip: where the tip was against the socket, and
// the tool's attitude against the fixture's), the hard dock (the pins engaged at the retraction's
// end), and the loads, true values from the plant: the tip's contact force on the drogue against
// Chaser's bound (capture.berthing.contact_force_limit_N), the latches' and pins' hold force.
// Met: hard docked, the contact force within the bound.
#include <limits>

#include "core/types.hpp"
#include "model/capture.hpp"
#include "plant/multibody_motion.hpp"

namespace chaser::sim {

struct BerthResult {
  bool flown = false;                                            // the scenario berths and the arm woke
  double soft_dock_s = std::numeric_limits<double>::quiet_NaN(); // [s] the latches closed
  Vec3 latch_offset_m = Vec3::Zero();                            // [m] the tip from the socket then, the fixture's axes (x the approach)
  double latch_attitude_deg = std::numeric_limits<double>::quiet_NaN();  // [deg] the tool's axes from the fixture's then
  bool pins_jammed = false;                                      // the latch outside the pins' envelope
  double hard_dock_s = std::numeric_limits<double>::quiet_NaN(); // [s] the pins engaged
  double mate_offset_m = std::numeric_limits<double>::quiet_NaN();       // [m] then, the interfaces from their mated pose
  double mate_attitude_deg = std::numeric_limits<double>::quiet_NaN();   // [deg]
  double peak_contact_N = 0.0;                                   // [N] the tip on the drogue, largest
  double peak_hold_N = 0.0;                                      // [N] the latches' and the pins' force, largest
  double contact_force_limit_N = 0.0;                            // [N] the bound (the scenario's)
};

// The plant's berthing truth at a control period (its peaks are kept by the plant).
void add_berth_period(BerthResult& r, const plant::BerthState& truth, const model::BerthingParams& params);

// Hard docked with the tip's contact force within its bound.
bool berth_meets_requirements(const BerthResult& r);

}  // namespace chaser::sim
