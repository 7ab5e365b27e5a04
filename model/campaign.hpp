#pragma once
// Parameters of a Monte Carlo campaign (Fonod 2015, section V and Table 1): the dispersions of the
// chaser drawn per run, the fault population of each case, when faults start and how long a run
// flies after the onset. Read from the scenario's campaign section; used only by campaign/.
#include <cstdint>
#include <optional>

#include "model/thrusters.hpp"

namespace chaser::model {

struct CampaignParams {
  std::uint64_t seed = 1;               // campaign seed: run seed = run_seed(seed, run index)
  double onset_s = 1000.0;              // [s] fault onset t_f of every faulty run
  double horizon_after_onset_s = 200.0; // [s] a run ends at onset_s + horizon_after_onset_s
  // Optional: each faulty run's onset uniform in [onset_s, onset_max_s] instead (drawn after the
  // thruster and the size, so a campaign without it keeps its draws); runs still end at
  // onset_s + horizon_after_onset_s.
  std::optional<double> onset_max_s;    // [s]
  // Optional: the thrusters a fault is drawn among (0: the starting active set, as by default).
  ThrusterMask fault_thrusters = 0;
  // Dispersions, 3-sigma, normal truncated at 3 sigma (Fonod 2015, Table 1). Thruster forces are
  // dispersed by the plant itself (thrusters.thrust_sigma), not here.
  double mass_3sigma_rel = 0.10;        // [-] relative to the nominal mass
  double inertia_3sigma_rel = 0.20;     // [-] relative, each principal moment independently
  double com_3sigma_m = 0.03;           // [m] per body axis
  // Optional (0: none). The tumbling target's initial rate (relative) and the tilt of its spin axis
  // (about a random perpendicular), with target.body; the start's position and velocity per LVLH axis.
  double target_spin_rate_3sigma_rel = 0.0;   // [-]
  double target_spin_axis_3sigma_rad = 0.0;   // [rad]
  double initial_position_3sigma_m = 0.0;     // [m]
  double initial_velocity_3sigma_mps = 0.0;   // [m/s]
  // Fault population (Fonod 2015, section V): sizes uniform in [min, max].
  double leak_size_min = 0.1;           // [-]
  double leak_size_max = 0.3;           // [-]
  double leak_slope_per_s = 0.1;        // [1/s]
  double loss_size_min = 0.4;           // [-]
  double loss_size_max = 0.9;           // [-]
  // Threshold selection (Fonod 2015, Fig. 8): J_th = margin x the fault-free GLR envelope maximum.
  double threshold_margin = 1.5;        // [-]
  std::uint64_t runs_per_case = 100;    // runs of each case when --runs is not given
};

}  // namespace chaser::model
