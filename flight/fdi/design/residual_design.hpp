#pragma once
// Offline design of the delay-robust residual generator (Fonod 2015, IV.A, eqs. 18-39, App. A-B):
//   1. discretise with the delay (eqs. 19-22): A_bar, B_bar, E_f_bar;
//   2. Cayley-Hamilton and Taylor polytopes of Gamma_1(delta) (Props. 1-2, App. A-B);
//   3. unknown-input matrix E_d = [E_d^a, E_d^b] (eqs. 26-28);
//   4. low-rank E_d* (eq. 39) and weighting Q with Q C E_d* = 0 (eq. 33), choosing Q on purpose
//      where eq. 39 leaves it free; full-column-rank factor of E_d* (Remark 1);
//   5. left eigenstructure assignment: L with the rows of H = Q C as (projected) left eigenvectors
//      (eqs. 35-38);
//   6. design figures (eqs. 31-32).
// The runtime observer is x_hat(k+1) = (A_bar - L C) x_hat(k) + B_bar u_c(k) + L y(k),
// r(k) = Q (y(k) - C x_hat(k)) (eq. 30).
#include <Eigen/Core>

#include "flight/fdi/design/cayley_hamilton_polytope.hpp"
#include "flight/fdi/design/design_figures.hpp"
#include "flight/fdi/design/design_inputs.hpp"
#include "flight/fdi/design/eigenstructure.hpp"
#include "flight/fdi/design/taylor_polytope.hpp"
#include "flight/fdi/design/unknown_input.hpp"

namespace chaser::flight::fdi {

struct ResidualDesign {
  DesignInputs inputs;                      // as given
  Eigen::MatrixXd A_bar;                    // [n_x x n_x] e^{AT}
  Eigen::MatrixXd B_bar;                    // [n_x x n_u] eq. 22
  Eigen::MatrixXd E_f_bar;                  // [n_x x n_f] int_0^T e^{At} dt E_f
  CayleyHamiltonPolytope cayley_hamilton;   // App. A (empty vertices if not used)
  TaylorPolytope taylor;                    // App. B (empty vertices if not used)
  Eigen::MatrixXd E_d;                      // [n_x x N] eq. 28
  LowRankChoice low_rank;                   // the freedom eq. 39 leaves
  Eigen::MatrixXd discarded;                // [n_y x choose] the directions chosen from low_rank.tied
  Eigen::MatrixXd E_d_star;                 // [n_x x N] eq. 39
  double low_rank_error = 0.0;              // ||E_d - E_d*||_F
  double low_rank_optimum = 0.0;            // analytical optimum of eq. 39
  FullRankFactors E_d_factors;              // Remark 1: E_d* = E1 E2
  Eigen::MatrixXd Q;                        // [n_r x n_y] residual weighting, eq. 33
  Eigen::MatrixXd H;                        // [n_r x n_x] Q C
  Eigen::MatrixXd L;                        // [n_x x n_y] observer gain, eq. 38
  EigenstructureAssignment assignment;      // P, S, relative misses, cond(P)
  DesignFigures figures;                    // eqs. 31-32, a posteriori
};

// Throws std::invalid_argument listing every problem with the inputs.
ResidualDesign design_residual_generator(const DesignInputs& inputs);

// The score used by WeightingChoice::kMaxWeakestDcGain: min_i of the DC gain from fault direction i
// to the residual of the observer designed for this Q (-inf if P is numerically singular).
double weakest_dc_fault_gain(const Eigen::MatrixXd& A_bar, const Eigen::MatrixXd& C,
                             const Eigen::MatrixXd& Q, const std::vector<double>& eigenvalues,
                             const Eigen::MatrixXd& E_f_bar);
// The same with the eigenvalues' assignable subspaces computed beforehand (assignable_subspaces).
double weakest_dc_fault_gain(const Eigen::MatrixXd& A_bar, const Eigen::MatrixXd& C,
                             const Eigen::MatrixXd& Q, const std::vector<AssignableSubspace>& subspaces,
                             const Eigen::MatrixXd& E_f_bar);

}  // namespace chaser::flight::fdi
