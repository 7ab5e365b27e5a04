#include "flight/fdi/design/residual_design.hpp"

#include <limits>
#include <stdexcept>
#include <string>

#include "flight/fdi/design/delay_discretization.hpp"

namespace chaser::flight::fdi {

using Eigen::Index;
using Eigen::MatrixXd;

namespace {

void validate(const DesignInputs& in) {
  std::string problems;
  const auto require = [&](bool ok, const char* what) {
    if (!ok) problems += std::string("\n  ") + what;
  };
  const Index n = in.A.rows();
  require(n > 0 && in.A.cols() == n, "A must be square and non-empty");
  require(in.B.rows() == n && in.B.cols() > 0, "B must have n_x rows");
  require(in.C.cols() == n && in.C.rows() > 0 && in.C.rows() <= n, "C must be n_y x n_x, n_y <= n_x");
  require(in.E_f.rows() == n || in.E_f.size() == 0, "E_f must have n_x rows");
  require(in.fault_inputs.size() == 0 ||
              (in.fault_inputs.rows() == in.B.cols() && in.fault_inputs.cols() == in.E_f.cols()),
          "fault_inputs must be n_u x n_f");
  require(in.period_s > 0.0, "period_s must be > 0");
  require(0.0 <= in.delta_min_s && in.delta_min_s <= in.delta_max_s && in.delta_max_s <= in.period_s,
          "need 0 <= delta_min_s <= delta_max_s <= period_s");
  require(in.taylor_order >= 1, "taylor_order must be >= 1");
  require(in.residual_dim >= 1 && in.residual_dim <= in.C.rows(), "residual_dim must be in 1..n_y");
  require(static_cast<Index>(in.eigenvalues.size()) == n, "need exactly n_x eigenvalues");
  require(in.use_cayley_hamilton || in.use_taylor, "use at least one polytope");
  if (!problems.empty()) throw std::invalid_argument("invalid FDI design inputs:" + problems);
}

void build_unknown_input(const DesignInputs& in, ResidualDesign& d) {
  if (in.use_cayley_hamilton)
    d.cayley_hamilton = cayley_hamilton_polytope(in.A, in.B, in.period_s, in.delta_min_s,
                                                 in.delta_max_s, in.ch_grid_points);
  if (in.use_taylor)
    d.taylor = taylor_polytope(in.A, in.B, in.period_s, in.delta_min_s, in.delta_max_s,
                               in.taylor_order);
  d.E_d = unknown_input_matrix(d.cayley_hamilton.vertices, d.taylor.vertices);  // eq. 28
}

MatrixXd choose_discarded(const DesignInputs& in, const ResidualDesign& d) {
  if (in.weighting == WeightingChoice::kSvdOrder || d.low_rank.choose == 0 || in.E_f.cols() == 0)
    return svd_order_choice(d.low_rank);
  // Every trial shares A_bar, C and the eigenvalues: their assignable subspaces are computed once.
  const std::vector<AssignableSubspace> subspaces = assignable_subspaces(d.A_bar, in.C, in.eigenvalues);
  const SubspaceScore score = [&](const MatrixXd& chosen) {
    return weakest_dc_fault_gain(d.A_bar, in.C, low_rank_Q(d.low_rank, chosen), subspaces, d.E_f_bar);
  };
  return choose_subspace(d.low_rank.tied, d.low_rank.choose, score, in.search);
}

void reduce_and_weight(const DesignInputs& in, ResidualDesign& d) {
  d.low_rank = low_rank_choice(d.E_d, in.C, in.residual_dim, in.low_rank, in.tie_rel_tol);
  d.discarded = choose_discarded(in, d);
  const LowRankResult lr = low_rank_solution(d.E_d, d.low_rank, d.discarded);
  d.E_d_star = lr.E_star;
  d.Q = lr.Q;
  d.low_rank_error = lr.frobenius_error;
  d.low_rank_optimum = optimal_low_rank_error(d.E_d, in.C, in.residual_dim);
  d.E_d_factors = full_column_rank_factors(d.E_d_star);
  d.H = d.Q * in.C;
}

ObserverUnderTest observer_under_test(const DesignInputs& in, const ResidualDesign& d) {
  ObserverUnderTest o{d.A_bar, in.C, d.L, d.Q, d.E_d, d.E_d_star, d.E_f_bar, {},
                      in.fault_inputs, in.period_s};
  const int points = std::max(in.figures.delay_points, 2);
  for (int j = 0; j < points; ++j) {
    const double delta = in.delta_min_s + (in.delta_max_s - in.delta_min_s) * j / (points - 1.0);
    o.gamma1_samples.push_back(gamma1(in.A, in.B, in.period_s, delta));
  }
  return o;
}

}  // namespace

double weakest_dc_fault_gain(const MatrixXd& A_bar, const MatrixXd& C, const MatrixXd& Q,
                             const std::vector<double>& eigenvalues, const MatrixXd& E_f_bar) {
  return weakest_dc_fault_gain(A_bar, C, Q, assignable_subspaces(A_bar, C, eigenvalues), E_f_bar);
}

double weakest_dc_fault_gain(const MatrixXd& A_bar, const MatrixXd& C, const MatrixXd& Q,
                             const std::vector<AssignableSubspace>& subspaces, const MatrixXd& E_f_bar) {
  const EigenstructureAssignment a = assign_left_eigenstructure(subspaces, Q * C);
  if (!(a.p_condition < 1e10)) return -std::numeric_limits<double>::infinity();
  return dc_fault_gains(A_bar - a.L * C, Q * C, E_f_bar).minCoeff();
}

ResidualDesign design_residual_generator(const DesignInputs& in) {
  validate(in);
  ResidualDesign d;
  d.inputs = in;
  const DelayFreeDiscretization disc = discretize(in.A, in.B, in.period_s);  // eqs. 21-22
  d.A_bar = disc.A_bar;
  d.B_bar = disc.B_bar;
  d.E_f_bar = exp_and_integral(in.A, in.E_f.size() ? in.E_f : MatrixXd(in.A.rows(), 0), in.period_s)
                  .integral_B;
  build_unknown_input(in, d);
  reduce_and_weight(in, d);
  d.assignment = assign_left_eigenstructure(d.A_bar, in.C, d.H, in.eigenvalues);  // eqs. 35-38
  d.L = d.assignment.L;
  if (in.compute_figures) d.figures = compute_design_figures(observer_under_test(in, d), in.figures);
  return d;
}

}  // namespace chaser::flight::fdi
