#pragma once
// Choosing the residual weighting Q on purpose where eq. 33 does not fix it (Fonod 2015, eqs. 33-34).
//
// When the directions that eq. 39 discards are not unique (tied singular values), or the left null
// space of C E_d* is larger than n_r, Q is free inside a subspace. The paper is silent; rounding
// would decide. Here the caller scores candidates (for the MSR design: the weakest thruster's DC
// fault-to-residual gain) and this search maximises the score, deterministically:
//   - choosing p = 1 direction or p = c - 1 directions (its orthogonal complement) in a
//     c-dimensional subspace is a search over unit vectors w in R^c modulo sign: a deterministic
//     grid (c = 2: half circle; c = 3: Fibonacci hemisphere; c > 3: axes and their pairwise
//     bisectors), then a pattern search on the sphere, halving the step down to final_step_rad;
//   - p = 0 or p = c leaves nothing to choose; other (p, c) fall back to the last p basis vectors.
// Ties in the score keep the earlier candidate (strict improvement only).
#include <Eigen/Core>
#include <functional>

namespace chaser::flight::fdi {

// Score of a candidate: `chosen` is [n x p] with orthonormal columns in span(basis); larger is better.
using SubspaceScore = std::function<double(const Eigen::MatrixXd& chosen)>;

struct SubspaceSearchOptions {
  int grid_points = 256;          // candidates of the initial grid
  double final_step_rad = 1e-6;   // [rad] pattern search stops below this step
  int max_moves = 10000;          // and after this many steps (moves or halvings) in any case
};

// Returns [n x p] orthonormal columns inside span(basis) (basis: [n x c], orthonormal columns).
Eigen::MatrixXd choose_subspace(const Eigen::MatrixXd& basis, int p, const SubspaceScore& score,
                                const SubspaceSearchOptions& options = {});

}  // namespace chaser::flight::fdi
