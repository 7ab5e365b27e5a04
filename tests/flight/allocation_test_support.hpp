#pragma once
// Shared by the allocation tests of this folder: CLP as the independent LP solver, and the thruster
// sets the allocators are checked on.
#include <coin/ClpSimplex.hpp>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/random.hpp"
#include "flight/thruster_allocation.hpp"
#include "model/thruster_geometry.hpp"
#include "tests/support/msr_branch_a.hpp"

namespace chaser::flight::allocation_test {

constexpr int kMsr = 8;  // MSR's active branch

// MSR branch A (layout of Fonod 2015 Fig. 3, values from the project brief), centre of mass at the
// origin; column i = [22 d_i; p_i x 22 d_i] (eq. 2).
inline AllocationParams msr_params() {
  AllocationParams p;
  p.config = model::configuration_matrix(testing::msr_branch_a_thrusters(), model::first_thrusters(kMsr),
                                         Vec3::Zero());
  p.thrusters = kMsr;
  return p;
}

// n thrusters at random positions in a 2 m box with random unit directions, redrawn until M has
// rank 6 with a margin (smallest singular value above 1% of the largest).
inline AllocationParams random_params(RandomStream& rng, int n) {
  for (;;) {
    model::ThrusterSetParams set;
    set.count = n;
    for (int i = 0; i < n; ++i) {
      const Vec3 pos(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
      const Vec3 dir = Vec3(rng.normal(), rng.normal(), rng.normal()).normalized();
      set.thrusters[i] = {pos, dir, 22.0};
    }
    AllocationParams p;
    p.config = model::configuration_matrix(set, model::all_thrusters(set), Vec3::Zero());
    p.thrusters = n;
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(p.config.leftCols(n));
    if (svd.singularValues()[5] > 0.01 * svd.singularValues()[0]) return p;
  }
}

// n random on-times in [0, 1], the rest zero.
inline AllocationTon random_on_times(RandomStream& rng, int n) {
  AllocationTon t = AllocationTon::Zero();
  for (int i = 0; i < n; ++i) t[i] = rng.uniform();
  return t;
}

struct ClpOutcome {
  bool optimal = false;
  bool infeasible = false;
  double objective = 0;
};

// min obj x s.t. row_lb <= A x <= row_ub, col_lb <= x <= col_ub by CLP's dual simplex, which ends
// on a vertex meeting the rows, the error-budget row of stage 3 included (its primal simplex stops
// at points overrunning that row by up to its tolerance). Stages 2 and 3 are feasible by
// construction, so a tolerance at which CLP calls them infeasible is simply too tight for it.
inline ClpOutcome solve_clp(const Eigen::MatrixXd& a, const std::vector<double>& col_lb,
                     const std::vector<double>& col_ub, const std::vector<double>& obj,
                     const std::vector<double>& row_lb, const std::vector<double>& row_ub,
                     bool feasible_by_construction) {
  std::vector<CoinBigIndex> start{0};
  std::vector<int> index;
  std::vector<double> value;
  for (int c = 0; c < a.cols(); ++c) {
    for (int r = 0; r < a.rows(); ++r)
      if (a(r, c) != 0.0) index.push_back(r), value.push_back(a(r, c));
    start.push_back(static_cast<CoinBigIndex>(index.size()));
  }
  // CLP's tolerances are absolute and it may leave a bound or row overrun by up to them. Near a
  // vertex, propellant among the error minimisers can fall with the error budget at slopes up to
  // ~1e6, so a 1e-10 overrun alone would break the 1e-9 comparison: use the tightest tolerance,
  // relative to the largest right-hand side, at which CLP still proves a verdict.
  double rhs_max = 1.0;
  for (const double v : row_ub)
    if (v < COIN_DBL_MAX) rhs_max = std::max(rhs_max, std::abs(v));
  ClpOutcome out;
  for (const double tol : {1e-13, 1e-12, 1e-11, 1e-10}) {
    ClpSimplex model;
    model.setLogLevel(0);
    model.loadProblem(static_cast<int>(a.cols()), static_cast<int>(a.rows()), start.data(),
                      index.data(), value.data(), col_lb.data(), col_ub.data(), obj.data(),
                      row_lb.data(), row_ub.data());
    model.setPrimalTolerance(tol * rhs_max);
    model.setDualTolerance(tol);
    model.scaling(0);  // tolerances then hold on the problem as stated, not on a scaled copy
    model.dual();
    out = {model.isProvenOptimal(), model.isProvenPrimalInfeasible(), model.objectiveValue()};
    if (out.optimal || (out.infeasible && !feasible_by_construction)) break;
  }
  return out;
}

}  // namespace chaser::flight::allocation_test
