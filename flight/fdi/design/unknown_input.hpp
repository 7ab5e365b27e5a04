#pragma once
// The delay as an unknown input, and its reduction to something decouplable (Fonod 2015,
// eqs. 26-28, 34, 39 and Remark 1).
//
// E_d = [U^a_1 .. U^a_{2n_x}, U^b_1 .. U^b_{h+1}] (eq. 28). C E_d has full rank n_y for the MSR
// models, so no Q with Q C E_d = 0 exists (eq. 34) and eq. 39 replaces E_d by the nearest E_d* with
// rank(C E_d*) = n_y - n_r. Its exact minimiser: write E_d = P_C E_d + (I - P_C) E_d with P_C = C^+ C.
// The constraint touches only the part C sees, P_C E_d = V_C M (M = V_C^T E_d, C = U_C S_C V_C^T),
// and the two parts are Frobenius-orthogonal, so the unseen part is kept and M is truncated to rank
// n_y - n_r by SVD (Eckart-Young): ||E_d - E_d*||_F^2 = sum of the discarded sigma_j(M)^2.
// The naive variant truncates E_d itself to rank n_y - n_r (feasible, not optimal).
//
// When singular values of M tie across the truncation boundary (the position model: all three are
// equal), the discarded directions are not unique: any choice inside the tied subspace is optimal.
// LowRankChoice exposes that freedom so the caller can choose on purpose (see weighting.hpp).
#include <Eigen/Core>
#include <vector>

namespace chaser::flight::fdi {

// [E_d^a, E_d^b] of eq. 28: the vertices side by side. Either list may be empty.
Eigen::MatrixXd unknown_input_matrix(const std::vector<Eigen::MatrixXd>& vertices_a,
                                     const std::vector<Eigen::MatrixXd>& vertices_b);

enum class LowRankMethod {
  kTruncateSeenPart,  // exact minimiser of eq. 39 (default)
  kTruncateWhole,     // rank-(n_y - n_r) SVD truncation of E_d itself, for comparison
};

// What eq. 39 leaves open. Columns are unit vectors in "discard coordinates": for
// kTruncateSeenPart the coordinates of M = V_C^T E_d (left singular vectors of M); for
// kTruncateWhole the output space R^{n_y} (the left null space of C E_d*).
struct LowRankChoice {
  LowRankMethod method = LowRankMethod::kTruncateSeenPart;
  int residual_dim = 1;             // n_r
  Eigen::MatrixXd forced;           // [n_y x p0] directions discarded whatever the choice
  Eigen::MatrixXd tied;             // [n_y x c] orthonormal basis to choose from, SVD order
  int choose = 0;                   // how many directions to take from `tied` (p0 + choose = n_r)
  Eigen::VectorXd singular_values;  // sigma_j of M (kTruncateSeenPart) or of C E_d* (kTruncateWhole)
  Eigen::MatrixXd truncated_whole;  // E_d* of kTruncateWhole (independent of the choice)
  // C = U_C diag(s_C) V_C^T, for kTruncateSeenPart: kept so that no trial choice factors C again.
  Eigen::MatrixXd output_U;  // [n_y x n_y]
  Eigen::VectorXd output_s;  // [n_y]
  Eigen::MatrixXd output_V;  // [n_x x n_y]
};

// tie_rel_tol: singular values within tie_rel_tol * sigma_1 of the first discarded one are tied.
// Throws std::invalid_argument if C lacks full row rank or n_r is outside 1..n_y.
LowRankChoice low_rank_choice(const Eigen::MatrixXd& E_d, const Eigen::MatrixXd& C,
                              int residual_dim, LowRankMethod method, double tie_rel_tol = 1e-6);

// The default choice: the last `choose` columns of `tied` (what the SVD's rounding gives).
Eigen::MatrixXd svd_order_choice(const LowRankChoice& choice);

struct LowRankResult {
  Eigen::MatrixXd E_star;      // [n_x x N] E_d* of eq. 39
  Eigen::MatrixXd Q;           // [n_r x n_y] orthonormal rows, Q C E_d* = 0 (eq. 33)
  double frobenius_error = 0;  // ||E_d - E_d*||_F
};

// E_d* and Q for `chosen` ([n_y x choose], orthonormal, inside span(tied)), `choice` made for this
// E_d. Each row of Q has its largest-magnitude entry positive (a deterministic sign).
LowRankResult low_rank_solution(const Eigen::MatrixXd& E_d, const LowRankChoice& choice,
                                const Eigen::MatrixXd& chosen);

// Q alone, the same as low_rank_solution's: what a search over the choices scores.
Eigen::MatrixXd low_rank_Q(const LowRankChoice& choice, const Eigen::MatrixXd& chosen);

// The analytical optimum of eq. 39: sqrt of the sum of the n_r smallest sigma_j(V_C^T E_d)^2.
double optimal_low_rank_error(const Eigen::MatrixXd& E_d, const Eigen::MatrixXd& C, int residual_dim);

// Remark 1: E = E1 E2 with E1 = U_r S_r of full column rank r (singular values above
// rel_tol * sigma_1) and E2 = V_r^T; E1 E2 differs from E by the dropped singular values only.
struct FullRankFactors {
  Eigen::MatrixXd E1;  // [n_x x r]
  Eigen::MatrixXd E2;  // [r x N]
};
FullRankFactors full_column_rank_factors(const Eigen::MatrixXd& E, double rel_tol = 1e-10);

}  // namespace chaser::flight::fdi
