#pragma once
// Comparing thruster layouts on the same fault modes (Zhou 2018, section 4.2: Schemes I and II,
// and `chaser fmea --optimize`): one summary per layout, and the order "better layout first".
#include <array>
#include <cstddef>
#include <vector>

#include "invsim/fmea.hpp"
#include "model/invsim_study.hpp"

namespace chaser::invsim {

struct LayoutSummary {
  int fault_modes = 0;                  // rows other than the nominal one
  std::array<int, 3> per_class{0, 0, 0};  // fault modes per class I, II, III
  int controllable = 0;                 // fault modes of Class I or II
  int most_failed_tolerated = 0;        // most failed thrusters in a controllable fault mode
  int fewest_failed_lost = 0;           // fewest failed thrusters in an uncontrollable mode (0: none)
  double propellant_kg = 0.0;           // [kg] summed over every row (nominal included)
  double attitude_propellant_kg = 0.0;  // [kg] of it, by the attitude thrusters
  double yaw_on_time_s = 0.0;           // [s] summed opening time of the yaw couple, every row
  double mean_k_p = 0.0;                // [-] over every row
  double peak_azimuth_rad = 0.0;        // [rad] largest over the controllable rows
  double peak_yaw_rad = 0.0;            // [rad] largest over the controllable rows
  bool nominal_controllable = false;    // the fault-free run docks in view
};

LayoutSummary summarize_layout(const std::vector<FmeaRow>& rows);

// Better layout first: a controllable nominal run, then more controllable fault modes, then fewer
// Class II modes, then less propellant over the modes (the paper prefers Scheme II for its
// propellant once both schemes make every mode controllable), then a lower mean k_p.
bool better_layout(const LayoutSummary& a, const LayoutSummary& b);

// Indices of `summaries`, best first; ties keep the input order (deterministic).
std::vector<std::size_t> layout_order(const std::vector<LayoutSummary>& summaries);

struct LayoutCandidate {
  model::InvSimConfiguration configuration;  // the options taken, named "choice=option, ..."
  LayoutSummary summary;
};

// `chaser fmea --optimize`: every candidate of the free choices (model::candidate) flown through
// `cases` on `threads` workers; all candidates, best first (ties in enumeration order). `flights`,
// when given, receives the number of distinct flights flown (invsim/fmea.hpp).
std::vector<LayoutCandidate> search_layouts(const model::InvSimParams& base,
                                            const std::vector<model::InvSimFreeChoice>& choices,
                                            const std::vector<FmeaCase>& cases, int threads,
                                            std::size_t* flights = nullptr);

}  // namespace chaser::invsim
