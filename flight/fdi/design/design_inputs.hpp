#pragma once
// Everything the offline design of the delay-robust residual generator needs (Fonod 2015, IV.A),
// and the two MSR instances: the position model (eq. 12) and the attitude model (eq. 15).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "flight/fdi/design/design_figures.hpp"
#include "flight/fdi/design/unknown_input.hpp"
#include "flight/fdi/design/weighting.hpp"
#include "model/scenario.hpp"
#include "flight/fdi/watched_set.hpp"

namespace chaser::flight::fdi {

// How Q is fixed where eqs. 33 and 39 leave a choice (see weighting.hpp).
enum class WeightingChoice {
  kMaxWeakestDcGain,  // maximise min_i of the DC fault-to-residual gain of fault direction i
  kSvdOrder,          // whatever the SVD's rounding gives (the paper's implicit choice)
};

struct DesignInputs {
  std::string name = "custom";       // "position", "attitude", ...
  std::string residual_unit = "-";   // unit of y and r ("m", "rad")
  Eigen::MatrixXd A;                 // [n_x x n_x] continuous model, eq. 18
  Eigen::MatrixXd B;                 // [n_x x n_u]
  Eigen::MatrixXd C;                 // [n_y x n_x], full row rank
  Eigen::MatrixXd E_f;               // [n_x x n_f] continuous fault directions, one per thruster
  Eigen::MatrixXd fault_inputs;      // [n_u x n_f] the same in input space (E_f = B F), may be empty
  double period_s = 0.1;             // [s] T
  double delta_min_s = 0.0;          // [s] smallest delay (l = 0)
  double delta_max_s = 0.1;          // [s] largest delay; the paper uses [0, T) (m = 1)
  int taylor_order = 2;              // h, Prop. 2
  int residual_dim = 1;              // n_r, eq. 34
  std::vector<double> eigenvalues = {0.85, 0.87, 0.89, 0.91, 0.93, 0.95};  // of A_bar - L C
  bool use_cayley_hamilton = true;   // include E_d^a (eq. 26)
  bool use_taylor = true;            // include E_d^b (eq. 27)
  LowRankMethod low_rank = LowRankMethod::kTruncateSeenPart;
  WeightingChoice weighting = WeightingChoice::kMaxWeakestDcGain;
  double tie_rel_tol = 1e-6;         // singular values this close (relative) are tied
  int ch_grid_points = 256;          // delay grid for s_i^min, s_i^max (App. A)
  SubspaceSearchOptions search;      // Q direction search
  FigureOptions figures;             // frequency and delay grids of the figures
  // The figures (eqs. 31-32) judge a design for a report (`chaser fdi design`); nothing in the
  // observer depends on them. A run's in-memory design skips them: they were most of its set-up time.
  bool compute_figures = true;
};

// Position model (eq. 12) from the scenario: n from the orbit, mass, T; fault directions
// E_f = B M_F with the chaser-to-LVLH rotation R taken as the identity for design.
// delta_max defaults to T (the paper's [0, T)).
DesignInputs position_design_inputs(const model::Scenario& scenario, const SchemeConfig& M);

// Attitude model (eq. 15) from the scenario's inertia, linearised about omega_ref (the paper: 0);
// fault directions E_f = B M_C.
DesignInputs attitude_design_inputs(const model::Scenario& scenario, const SchemeConfig& M,
                                    const Vec3& omega_ref_body_radps = Vec3::Zero());

}  // namespace chaser::flight::fdi
