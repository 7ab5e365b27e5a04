#include "flight/thruster_allocation.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "core/power_of_two.hpp"

// Method: one linear program in standard bounded form,
//
//   M ton + e_plus - e_minus = demand,   0 <= ton <= 1,   e_plus, e_minus >= 0,
//
// solved by a bounded-variable primal simplex in two phases (the textbook two-phase method, with
// the error variables e playing the artificials):
//  1. minimise sum_j w_j (e_plus_j + e_minus_j), i.e. problem (E) of the header. The start basis
//     is the error variables themselves (ton = 0, e = |demand|), primal feasible at once, so no
//     separate feasibility search is needed. The demand is attainable iff the optimum is 0.
//  2. minimise sum ton over the optimal face of phase 1. Feasible case: that face is {e = 0}, so
//     all error variables get the bounds [0, 0] (exact, no tolerance involved). Infeasible case:
//     by complementary slackness a point is optimal for (E) iff every nonbasic variable whose
//     phase-1 reduced cost is nonzero stays at its bound, so those are fixed there; the others
//     stay free. This is the lexicographic optimum (error first, then propellant), no blend.
// Why a hand-written simplex: the problem is tiny (6 rows, N + 12 columns), so a dense explicit basis
// inverse B^-1 (6x6) updated by one Gauss-Jordan step per pivot costs ~100 flops and a handful of
// pivots suffice; everything is fixed-size on the stack, deterministic (no threads, no randomness,
// fixed evaluation order) and bounded in time, which a general solver does not promise.
// Warm start (AllocationWarmStart): the duals y = B^-T c_B of a basis do not depend on the demand,
// so a basis optimal for (P) at one demand stays dual feasible for every demand; where its basic
// values x_B = B^-1 (b - N x_N) (nonbasic on-times at their bounds, error variables at 0) are within
// [0, 1] it is primal feasible too, hence optimal for the new demand: the answer costs one 6x6
// product and a refinement step. Only bases whose six basic variables are on-times are kept (a basic
// error variable would have to stay exactly 0), and the answer is checked like a solved one
// (`attainable`); anything else falls back to the two-phase solve, whose optimal basis is then
// kept. The infeasible case (E) is always solved.
// Numerics: the problem is scaled by powers of two (exact) so that |M_ij| <= 1 and w_j <= 1, which
// makes the tolerances below dimensionless; B^-1 is recomputed from an LU factorisation every
// kReinvertPeriod pivots, and before optimality is accepted the basic values and the duals are
// recomputed from the nonbasic values and the costs with one step of iterative refinement (cheaper
// than a new LU, ~400 ns, and as accurate); the ratio test is Harris's two-pass test (the largest
// pivot among near-ties) for stability; Dantzig pricing switches to Bland's smallest-index rule
// after a run of degenerate pivots, which rules out cycling.

namespace chaser::flight {
namespace {

// The solver is a template on its width N (on-time columns): the set's count rounded up to a
// multiple of eight (allocate_thrusters at the end). Columns past the set's own are zero with both
// bounds 0, so they never enter the basis and stay at 0: the same optimum as a solver of the exact
// width.
constexpr int kRows = 6;                          // wrench components [F; C]
template <int N>
using TonN = Eigen::Matrix<double, N, 1>;
template <int N>
using ConfigN = Eigen::Matrix<double, kRows, N>;
template <int N>
using ConfigMap = Eigen::Map<const ConfigN<N>>;
constexpr double kInf = std::numeric_limits<double>::infinity();

// Tolerances, all in the scaled problem (|M_ij| <= 1, w_j <= 1, ton in [0, 1]). The primal ones
// are relative to the size of the demand, so that a tiny demand is solved as accurately as a large
// one (the LP is positively homogeneous in the demand until on-times reach 1).
constexpr double kPrimalTol = 1e-12;       // how far a basic variable may overrun a bound in the
                                           // Harris ratio test, times |demand|_inf
constexpr double kFeasibilityTol = 1e-11;  // attainable when |M ton - demand|_inf is below this
                                           // times the terms' size, |demand|_inf + ||M| ton|_inf
constexpr double kDualTol = 1e-11;         // reduced costs below this are zero: optimality test and
                                           // which phase-1 variables stay free in phase 2
constexpr double kPivotTol = 1e-10;        // smallest |B^-1 a_q| entry accepted as a pivot
constexpr int kMaxIterations = 200;        // both phases; typical calls need 4 to 8, the most
                                           // seen in 80,000 random cases is 26
constexpr int kDegenerateRunForBland = 4;  // consecutive degenerate pivots before Bland's rule
constexpr int kReinvertPeriod = 16;        // pivots between LU recomputations of B^-1

enum class At : std::uint8_t { kBasic, kLower, kUpper };

template <int N>
struct Lp {
  static constexpr int kCols = N + 2 * kRows;  // 0..N-1: on-times, then e_plus, then e_minus
  int thrusters = N;                       // on-time columns of the set; the rest are padding
  Eigen::Matrix<double, kRows, kCols> a;  // [M, I, -I], scaled
  Vec6 b;                                 // scaled demand
  Eigen::Matrix<double, kCols, 1> cost;  // objective of the current phase
  std::array<double, kCols> lower{}, upper{}, x{};
  TonN<N> ton_upper = TonN<N>::Ones();    // the on-times' upper bounds (1, or 1 - a floor)
  std::array<At, Lp<N>::kCols> at{};
  std::array<int, kRows> basis{};  // variable basic in each row
  Mat6 binv;                       // B^-1
  double primal_tol = kPrimalTol;
  int iterations = 0;
  int since_reinvert = 0;
  bool fresh = false;  // basic values recomputed (and duals to be refined) since the last step
};


template <int N>
void init_phase1(Lp<N>& lp, const ConfigN<N>& m_scaled, const Vec6& w_scaled, const Vec6& b) {
  lp.a << m_scaled, Mat6::Identity(), -Mat6::Identity();
  lp.b = b;
  lp.primal_tol = kPrimalTol * b.cwiseAbs().maxCoeff();
  lp.binv.setZero();
  for (int j = 0; j < Lp<N>::kCols; ++j) {
    lp.lower[j] = 0.0;
    lp.upper[j] = j < lp.thrusters ? lp.ton_upper[j] : j < N ? 0.0 : kInf;  // padding columns are fixed at 0
    lp.cost[j] = j < N ? 0.0 : w_scaled[(j - N) % kRows];
    lp.x[j] = 0.0;
    lp.at[j] = At::kLower;
  }
  for (int r = 0; r < kRows; ++r) {  // ton = 0, e = |b|: feasible start basis, B = diag(+-1)
    const bool plus = b[r] >= 0.0;
    const int j = N + r + (plus ? 0 : kRows);
    lp.basis[r] = j;
    lp.at[j] = At::kBasic;
    lp.x[j] = std::abs(b[r]);
    lp.binv(r, r) = plus ? 1.0 : -1.0;
  }
}

// Basic values from the nonbasic ones, x_B = B^-1 (b - N x_N), plus one refinement step with the
// residual, which removes the error B^-1 has gathered through its updates.
// x_B = B^-1 rhs with one step of iterative refinement (B's columns: a's columns `basis`).
template <class Columns>
Vec6 refined_basics(const Mat6& binv, const Columns& a, const std::array<int, kRows>& basis, const Vec6& rhs) {
  Vec6 x_basic = binv * rhs;
  Vec6 residual = rhs;
  for (int r = 0; r < kRows; ++r) residual -= a.col(basis[r]) * x_basic[r];
  return x_basic + binv * residual;
}

template <int N>
void recompute_basics(Lp<N>& lp) {
  Vec6 rhs = lp.b;
  for (int j = 0; j < Lp<N>::kCols; ++j)
    if (lp.at[j] != At::kBasic && lp.x[j] != 0.0) rhs -= lp.a.col(j) * lp.x[j];
  const Vec6 x_basic = refined_basics(lp.binv, lp.a, lp.basis, rhs);
  for (int r = 0; r < kRows; ++r) lp.x[lp.basis[r]] = x_basic[r];
  lp.fresh = true;
}

// B^-1 from a new LU factorisation of the basis matrix.
template <int N>
void reinvert(Lp<N>& lp) {
  Mat6 basis_matrix;
  for (int r = 0; r < kRows; ++r) basis_matrix.col(r) = lp.a.col(lp.basis[r]);
  lp.binv = Eigen::PartialPivLU<Mat6>(basis_matrix).inverse();
  lp.since_reinvert = 0;
  recompute_basics(lp);
}

// Simplex multipliers y = B^-T c_B; refined like the basic values when they decide optimality.
template <int N>
Vec6 duals(const Lp<N>& lp, bool refine) {
  Vec6 cost_basic;
  for (int r = 0; r < kRows; ++r) cost_basic[r] = lp.cost[lp.basis[r]];
  Vec6 y = lp.binv.transpose() * cost_basic;
  if (!refine) return y;
  Vec6 residual;
  for (int r = 0; r < kRows; ++r) residual[r] = cost_basic[r] - lp.a.col(lp.basis[r]).dot(y);
  return y + lp.binv.transpose() * residual;
}

template <int N>
double reduced_cost(const Lp<N>& lp, const Vec6& y, int j) { return lp.cost[j] - y.dot(lp.a.col(j)); }

// Entering variable: the largest improving reduced cost (Dantzig), or the first one (Bland);
// -1 when none improves by more than kDualTol, i.e. the basis is optimal.
template <int N>
int price(const Lp<N>& lp, const Vec6& y, bool bland) {
  Eigen::Matrix<double, Lp<N>::kCols, 1> d;  // reduced costs c_j - y' a_j; error columns are +-I
  d.template head<N>() = lp.cost.template head<N>() - lp.a.template leftCols<N>().transpose() * y;
  d.template segment<kRows>(N) = lp.cost.template segment<kRows>(N) - y;
  d.template tail<kRows>() = lp.cost.template tail<kRows>() + y;
  int best = -1;
  double best_gain = kDualTol;
  for (int j = 0; j < Lp<N>::kCols; ++j) {
    if (lp.at[j] == At::kBasic || lp.lower[j] == lp.upper[j]) continue;
    const double gain = lp.at[j] == At::kLower ? -d[j] : d[j];
    if (gain <= best_gain) continue;
    if (bland) return j;
    best = j;
    best_gain = gain;
  }
  return best;
}

struct Step {
  int row = -1;         // leaving row, -1 for a bound flip of the entering variable
  double length = 0.0;  // how far the entering variable moves
  bool bounded = true;
};

// Distance of basic row r to the bound it moves towards when it changes at `rate` (never < 0).
template <int N>
double room(const Lp<N>& lp, int r, double rate) {
  const int j = lp.basis[r];
  return std::max(0.0, rate < 0.0 ? lp.x[j] - lp.lower[j] : lp.upper[j] - lp.x[j]);
}

// Harris two-pass ratio test. The entering variable moves by dir * t; basic row r changes at
// -dir * alpha_r. Pass 1 finds the longest step keeping all basics within bound + tolerance; pass 2
// takes, among the rows blocking before it, the largest pivot (or, under Bland, the lowest index
// with the exact least ratio, which needs a zero tolerance).
template <int N>
Step ratio_test(const Lp<N>& lp, int q, double dir, const Vec6& alpha, bool bland) {
  const double tol = bland ? 0.0 : lp.primal_tol;
  double t_max = kInf;
  for (int r = 0; r < kRows; ++r) {
    if (std::abs(alpha[r]) <= kPivotTol) continue;
    const double rate = -dir * alpha[r];
    t_max = std::min(t_max, (room(lp, r, rate) + tol) / std::abs(rate));
  }
  Step step;
  const double range = lp.upper[q] - lp.lower[q];
  if (range == kInf && t_max == kInf) {
    step.bounded = false;
    return step;
  }
  if (range <= t_max) {
    step.length = range;  // the entering variable reaches its other bound first
    return step;
  }
  double best_key = -kInf;
  for (int r = 0; r < kRows; ++r) {
    if (std::abs(alpha[r]) <= kPivotTol) continue;
    const double rate = -dir * alpha[r];
    const double t = room(lp, r, rate) / std::abs(rate);
    if (t > t_max) continue;
    const double key = bland ? -static_cast<double>(lp.basis[r]) : std::abs(alpha[r]);
    if (key > best_key) {
      best_key = key;
      step.row = r;
      step.length = t;
    }
  }
  return step;
}

template <int N>
void apply_step(Lp<N>& lp, int q, double dir, const Vec6& alpha, const Step& step) {
  for (int r = 0; r < kRows; ++r) lp.x[lp.basis[r]] -= dir * step.length * alpha[r];
  if (step.row < 0) {  // bound flip: no basis change
    lp.at[q] = lp.at[q] == At::kLower ? At::kUpper : At::kLower;
    lp.x[q] = lp.at[q] == At::kLower ? lp.lower[q] : lp.upper[q];
    return;
  }
  const int r = step.row;
  const int leaving = lp.basis[r];
  lp.at[leaving] = -dir * alpha[r] < 0.0 ? At::kLower : At::kUpper;
  lp.x[leaving] = lp.at[leaving] == At::kLower ? lp.lower[leaving] : lp.upper[leaving];
  lp.x[q] += dir * step.length;
  lp.at[q] = At::kBasic;
  lp.basis[r] = q;
  // Gauss-Jordan update of B^-1 for column q replacing row r's variable.
  const Eigen::Matrix<double, 1, kRows> pivot_row = lp.binv.row(r) / alpha[r];
  lp.binv -= alpha * pivot_row;
  lp.binv.row(r) = pivot_row;
}

// Primal simplex from the current (primal feasible) basis. True when optimal, false when the
// iteration cap is hit (or, impossibly since all costs are >= 0, the objective is unbounded).
template <int N>
bool run_simplex(Lp<N>& lp) {
  int degenerate_run = 0;
  while (lp.iterations < kMaxIterations) {
    const bool bland = degenerate_run >= kDegenerateRunForBland;
    const int q = price(lp, duals(lp, lp.fresh), bland);
    if (q < 0) {
      if (lp.fresh) return true;
      recompute_basics(lp);  // accept optimality only on accurate basic values and duals
      continue;
    }
    const double dir = lp.at[q] == At::kLower ? 1.0 : -1.0;
    const Vec6 alpha = lp.binv * lp.a.col(q);
    const Step step = ratio_test(lp, q, dir, alpha, bland);
    if (!step.bounded) return false;
    apply_step(lp, q, dir, alpha, step);
    ++lp.iterations;
    degenerate_run = step.length > 0.0 ? 0 : degenerate_run + 1;
    lp.fresh = false;
    if (step.row >= 0 && ++lp.since_reinvert >= kReinvertPeriod) reinvert(lp);
  }
  return false;
}

// Restricts the LP to the optimal face of phase 1 and sets the propellant cost (see the top).
template <int N>
void start_phase2(Lp<N>& lp, bool feasible) {
  if (feasible) {
    for (int j = N; j < Lp<N>::kCols; ++j) lp.upper[j] = 0.0;
  } else {
    const Vec6 y = duals(lp, true);
    for (int j = 0; j < Lp<N>::kCols; ++j) {
      if (lp.at[j] == At::kBasic || std::abs(reduced_cost(lp, y, j)) <= kDualTol) continue;
      lp.lower[j] = lp.upper[j] = lp.x[j];
    }
  }
  for (int j = 0; j < Lp<N>::kCols; ++j) lp.cost[j] = j < N ? 1.0 : 0.0;
}

template <int N>
TonN<N> ton_of(const Lp<N>& lp) {
  TonN<N> ton;
  for (int i = 0; i < N; ++i) ton[i] = std::clamp(lp.x[i], 0.0, lp.ton_upper[i]);  // clears Harris overruns
  return ton;
}

// `achieved`: the wrench the on-times give, config * ton.
template <int N>
void fill_result(const AllocationParams& params, const Vec6& achieved, const Vec6& demand, const TonN<N>& ton,
                 AllocationResult& result) {
  result.ton.template head<N>() = ton;  // the rest is zero: `result` is fresh
  result.propellant = ton.sum();
  result.residual = achieved - demand;
  result.weighted_error = params.error_weights.cwiseProduct(result.residual.cwiseAbs()).sum();
}
template <int N>
void fill_result(const AllocationParams& params, const ConfigMap<N>& config, const Vec6& demand, const TonN<N>& ton,
                 AllocationResult& result) {
  fill_result<N>(params, Vec6(config * ton), demand, ton, result);
}

// Phase-1 verdict: M ton = b up to rounding of the terms that form it (M, b scaled), from
// achieved = M ton and magnitudes = |M| ton.
inline bool attains(const Vec6& achieved, const Vec6& magnitudes, const Vec6& b) {
  const double residual = (achieved - b).cwiseAbs().maxCoeff();
  const double terms = b.cwiseAbs().maxCoeff() + magnitudes.maxCoeff();
  return residual <= kFeasibilityTol * terms;
}
template <class Config, class Ton>
bool attains(const Config& m, const Vec6& b, const Ton& ton) {
  return attains(Vec6(m * ton), Vec6(m.cwiseAbs() * ton), b);
}
template <int N>
bool attainable(const Lp<N>& lp, const TonN<N>& ton) { return attains(lp.a.template leftCols<N>(), lp.b, ton); }

// `config`: the set's columns at the solver's width (config_of), the only ones the solver reads.
template <int N>
bool valid_problem(const AllocationParams& params, const ConfigMap<N>& config) {
  return params.thrusters >= 1 && params.thrusters <= N && config.allFinite() && params.error_weights.allFinite() &&
         (params.error_weights.array() > 0.0).all();
}

// The answers that need no LP: an invalid problem or demand (ton = 0, converged = false) and a zero
// demand (ton = 0 is the unique zero-cost solution). True when `result` is final.
inline bool answered_without_lp(const AllocationParams& params, bool valid, const Vec6& demand,
                                AllocationResult& result) {
  // `result` is fresh: its on-times are already zero.
  result.propellant = 0.0;
  result.residual = -demand;
  result.weighted_error = params.error_weights.cwiseProduct(demand.cwiseAbs()).sum();
  if (!valid || !demand.allFinite()) return true;
  if ((demand.array() == 0.0).all()) {
    result.feasible = result.converged = true;
    return true;
  }
  return false;
}

struct Scaling {
  double wrench = 1.0;  // [N or N m] power of two, |M_ij| / wrench <= 1
  double weight = 1.0;  // power of two, w_j / weight <= 1
};

// The set's configuration at the solver's width: its own columns, then zero padding. A view of the
// capacity-wide matrix's first N columns (column-major: contiguous), not a copy.
template <int N>
ConfigMap<N> config_of(const AllocationParams& params) {
  return ConfigMap<N>(params.config.data());
}

// The padding columns are zero, so the largest entry of the solver's columns is the set's.
template <int N>
Scaling scaling_of(const AllocationParams& params, const ConfigMap<N>& config) {
  return {power_of_two_above(config.cwiseAbs().maxCoeff()), power_of_two_above(params.error_weights.maxCoeff())};
}

// The two-phase solve; `lp` keeps the final basis.
template <int N>
void solve(const AllocationParams& params, const ConfigMap<N>& config, const Vec6& demand, const Scaling& scale,
           Lp<N>& lp, AllocationResult& result) {
  lp.thrusters = params.thrusters;
  init_phase1<N>(lp, config / scale.wrench, params.error_weights / scale.weight, demand / scale.wrench);
  const bool phase1_done = run_simplex(lp);
  TonN<N> ton = ton_of(lp);
  result.feasible = attainable(lp, ton);
  result.converged = phase1_done;
  if (phase1_done) {
    start_phase2(lp, result.feasible);
    result.converged = run_simplex(lp);
    ton = ton_of(lp);
  }
  fill_result<N>(params, config, demand, ton, result);
  result.iterations = lp.iterations;
}

// M ton over the columns of `support` (the on-times outside it are zero), lowest index first: for
// the wide sets, where a basic solution has at most 6 + |upper| nonzero on-times of 24 or 32.
template <int N>
Vec6 support_product(const ConfigMap<N>& m, const TonN<N>& ton, model::ThrusterMask support) {
  Vec6 sum = Vec6::Zero();
  for (; support != 0; support &= support - 1) {
    const int i = std::countr_zero(support);
    sum += ton[i] * m.col(i);
  }
  return sum;
}

// The on-times of a cached basis at the scaled demand b, if they are within bounds (up to the
// solver's own Harris tolerance) and attain b, as a solved answer must; `achieved`: M ton then
// (m_abs = |M|, formed once per problem).
template <int N>
bool try_slot(const AllocationWarmStart::Slot& slot, const ConfigMap<N>& m_scaled, const ConfigMap<N>& m_abs,
              const Vec6& b, TonN<N>& ton, Vec6& achieved) {
  // The nonbasic on-times at their upper bound, lowest index first (the order of the sums), by
  // their set bits: most slots have none or a few of the N.
  Vec6 rhs = b;
  for (model::ThrusterMask m = slot.upper; m != 0; m &= m - 1) rhs -= m_scaled.col(std::countr_zero(m));
  const Vec6 x = refined_basics(slot.binv, m_scaled, slot.basis, rhs);
  const double tol = kPrimalTol * b.cwiseAbs().maxCoeff();
  if ((x.array() < -tol).any() || (x.array() > 1.0 + tol).any()) return false;
  ton.setZero();
  model::ThrusterMask support = slot.upper;
  for (model::ThrusterMask m = slot.upper; m != 0; m &= m - 1) ton[std::countr_zero(m)] = 1.0;
  for (int r = 0; r < kRows; ++r) {
    ton[slot.basis[r]] = std::clamp(x[r], 0.0, 1.0);
    support |= model::thruster_bit(slot.basis[r]);
  }
  if constexpr (N <= 8) {  // MSR's width: the dense products, whose sums its pinned results depend on
    achieved = m_scaled * ton;
    return attains(achieved, Vec6(m_abs * ton), b);
  } else {  // at most 6 basic and the upper on-times are nonzero: a few columns of the N
    Vec6 magnitudes;
    achieved = support_product<N>(m_scaled, ton, support);
    magnitudes = support_product<N>(m_abs, ton, support);
    return attains(achieved, magnitudes, b);
  }
}

// Keeps the optimal basis of a solved attainable demand when its basic variables are on-times.
template <int N>
void remember(const Lp<N>& lp, AllocationWarmStart& warm) {
  AllocationWarmStart::Slot slot;
  Mat6 basis_matrix;
  for (int r = 0; r < kRows; ++r) {
    if (lp.basis[r] >= N) return;
    slot.basis[r] = lp.basis[r];
    basis_matrix.col(r) = lp.a.col(lp.basis[r]);
  }
  for (int i = 0; i < N; ++i)
    if (lp.at[i] == At::kUpper) slot.upper |= model::thruster_bit(i);
  const Eigen::PartialPivLU<Mat6> lu(basis_matrix);  // fresh, not the updated B^-1 of the pivots
  slot.binv = lu.inverse();
  slot.valid = true;
  warm.slots[static_cast<std::size_t>(warm.next_free)] = slot;
  warm.last_hit = warm.next_free;
  warm.next_free = (warm.next_free + 1) % AllocationWarmStart::kSlots;
}

template <int N>
AllocationResult allocate_cold(const AllocationParams& params, const Vec6& demand_wrench) {
  AllocationResult result;
  const ConfigMap<N> config = config_of<N>(params);
  if (answered_without_lp(params, valid_problem<N>(params, config), demand_wrench, result)) return result;
  Lp<N> lp;
  solve<N>(params, config, demand_wrench, scaling_of<N>(params, config), lp, result);
  return result;
}

// Floors: the problem in t = ton - floor, 0 <= t <= 1 - floor, demand w_d - M floor (the header).
template <int N>
AllocationResult allocate_floored(const AllocationParams& params, const Vec6& demand_wrench, const AllocationTon& floor) {
  AllocationResult result;
  const ConfigMap<N> config = config_of<N>(params);
  const bool floors_valid = floor.allFinite() && (floor.array() >= 0.0).all() && (floor.array() <= 1.0).all() &&
                            (params.thrusters >= model::kMaxThrusters ||
                             floor.tail(model::kMaxThrusters - params.thrusters).isZero(0.0));
  if (!floors_valid || !valid_problem<N>(params, config) || !demand_wrench.allFinite()) {
    answered_without_lp(params, false, demand_wrench, result);  // ton = 0, converged = false
    return result;
  }
  const TonN<N> lower = floor.template head<N>();
  const Vec6 shifted = demand_wrench - config * lower;
  TonN<N> t = TonN<N>::Zero();
  result.feasible = result.converged = true;  // a zero shifted demand: t = 0 is the unique optimum
  if (!shifted.isZero(0.0)) {
    Lp<N> lp;
    lp.ton_upper = TonN<N>::Ones() - lower;
    AllocationResult shifted_result;
    solve<N>(params, config, shifted, scaling_of<N>(params, config), lp, shifted_result);
    t = shifted_result.ton.template head<N>();
    result.feasible = shifted_result.feasible;
    result.converged = shifted_result.converged;
    result.iterations = shifted_result.iterations;
  }
  const TonN<N> ton = (lower + t).cwiseMin(1.0);  // t <= 1 - floor up to rounding
  fill_result<N>(params, config, demand_wrench, ton, result);
  return result;
}

// Caps: the problem (P)/(E) with ton_i <= cap for every on-time (the p = infinity allocation's
// second stage, flight/norm_allocation.cpp).
template <int N>
AllocationResult allocate_capped(const AllocationParams& params, const Vec6& demand_wrench, double cap) {
  AllocationResult result;
  const ConfigMap<N> config = config_of<N>(params);
  const bool valid = std::isfinite(cap) && cap > 0.0 && cap <= 1.0 && valid_problem<N>(params, config);
  if (answered_without_lp(params, valid, demand_wrench, result)) return result;
  Lp<N> lp;
  lp.ton_upper = TonN<N>::Constant(cap);
  solve<N>(params, config, demand_wrench, scaling_of<N>(params, config), lp, result);
  return result;
}

// The homogeneous LP of attainable_scale: max nu s.t. M_s s + nu c = 0, 0 <= s <= 1, nu >= 0, with
// M_s = M / wrench scale and c = -wrench / p (p a power of two with |c| <= 1), so lambda = nu wrench
// scale / p exactly. The solver's own machinery: the column c rides as an extra "on-time" with
// bounds [0, inf) at index `thrusters` (W >= thrusters + 1 columns), the error variables are fixed
// at 0 (the start basis is them, all at 0: b = 0 is feasible at once), and the cost is -nu.
template <int W>
AttainableScale scale_of(const AllocationParams& params, const Vec6& wrench) {
  AttainableScale out;
  const int n = params.thrusters;
  if (n < 1 || n > model::kMaxThrusters || n >= W) return out;
  const auto config = params.config.leftCols(n);
  if (!config.allFinite() || !wrench.allFinite()) return out;
  const double wrench_max = wrench.cwiseAbs().maxCoeff();
  if (wrench_max == 0.0) {  // every lambda: the zero wrench needs no firing
    out.scale = kInf;
    out.converged = true;
    return out;
  }
  const double config_scale = power_of_two_above(config.cwiseAbs().maxCoeff());
  const double column_scale = power_of_two_above(wrench_max);
  ConfigN<W> m = ConfigN<W>::Zero();
  m.leftCols(n) = config / config_scale;
  m.col(n) = -wrench / column_scale;
  Lp<W> lp;
  lp.thrusters = n + 1;
  lp.ton_upper.setOnes();
  lp.ton_upper[n] = kInf;
  init_phase1<W>(lp, m, Vec6::Ones(), Vec6::Zero());
  lp.primal_tol = kPrimalTol;  // the variables' own size: s in [0, 1], nu ~ lambda
  for (int j = W; j < Lp<W>::kCols; ++j) lp.upper[j] = 0.0;
  lp.cost.setZero();
  lp.cost[n] = -1.0;
  out.converged = run_simplex(lp);
  const double nu = std::max(0.0, lp.x[static_cast<std::size_t>(n)]);
  out.scale = nu * config_scale / column_scale;
  for (int i = 0; i < n; ++i) out.ton[i] = std::clamp(lp.x[static_cast<std::size_t>(i)], 0.0, 1.0);
  out.iterations = lp.iterations;
  return out;
}

// The slots belong to the same set: the solver's columns compared at its width (the padding is
// zero in both).
template <int N>
bool same_problem(const AllocationParams& params, const ConfigMap<N>& config, const AllocationWarmStart& warm) {
  // The same bytes are the same problem (a -0.0 against a 0.0 only costs a cache miss). memcmp of
  // the 6 x N block, contiguous in both (column-major), instead of Eigen's element-wise ==: this
  // check runs every period and was a sixth of the allocation's time.
  static_assert(!model::ConfigMatrix::IsRowMajor);
  return warm.thrusters == params.thrusters && warm.error_weights == params.error_weights &&
         std::memcmp(warm.config.data(), config.data(), sizeof(double) * kRows * N) == 0;
}

template <int N>
AllocationResult allocate_warm(const AllocationParams& params, const Vec6& demand_wrench, AllocationWarmStart& warm) {
  AllocationResult result;
  const ConfigMap<N> config = config_of<N>(params);
  if (!same_problem<N>(params, config, warm)) {  // another problem: the kept bases do not belong to it
    warm.slots = {};
    warm.last_hit = warm.next_free = 0;
    warm.config = params.config;
    warm.thrusters = params.thrusters;
    warm.error_weights = params.error_weights;
    warm.valid = valid_problem<N>(params, config);  // checked once per problem, like the scaling
    warm.wrench_scale = scaling_of<N>(params, config).wrench;
    warm.config_scaled = params.config / warm.wrench_scale;
    warm.config_scaled_abs = warm.config_scaled.cwiseAbs();
  }
  if (answered_without_lp(params, warm.valid, demand_wrench, result)) return result;
  const ConfigMap<N> m_scaled(warm.config_scaled.data());
  const ConfigMap<N> m_abs(warm.config_scaled_abs.data());
  const Vec6 b = demand_wrench / warm.wrench_scale;
  for (int k = 0; k < AllocationWarmStart::kSlots; ++k) {
    const int s = (warm.last_hit + k) % AllocationWarmStart::kSlots;
    const AllocationWarmStart::Slot& slot = warm.slots[static_cast<std::size_t>(s)];
    TonN<N> ton;
    Vec6 achieved_scaled;
    if (!slot.valid || !try_slot<N>(slot, m_scaled, m_abs, b, ton, achieved_scaled)) continue;
    warm.last_hit = s;
    ++warm.hits;
    result.feasible = result.converged = true;
    // config * ton exactly: the scale is a power of two, so scaling back is exact.
    fill_result<N>(params, Vec6(achieved_scaled * warm.wrench_scale), demand_wrench, ton, result);
    return result;
  }
  Lp<N> lp;
  solve<N>(params, config, demand_wrench, scaling_of<N>(params, config), lp, result);
  ++warm.solves;
  if (result.feasible && result.converged) remember(lp, warm);
  return result;
}

}  // namespace

// The solver's width: the set's count rounded up to a multiple of eight (8 for MSR, 24 for COMRADE),
// so that the padding columns, which cost as much as real ones in every product, stay few.
AllocationResult allocate_thrusters(const AllocationParams& params, const Vec6& demand_wrench) {
  static_assert(model::kMaxThrusters == 32, "one solver width per multiple of eight up to the capacity");
  if (params.thrusters <= 8) return allocate_cold<8>(params, demand_wrench);
  if (params.thrusters <= 16) return allocate_cold<16>(params, demand_wrench);
  if (params.thrusters <= 24) return allocate_cold<24>(params, demand_wrench);
  return allocate_cold<32>(params, demand_wrench);
}

AllocationResult allocate_thrusters_floored(const AllocationParams& params, const Vec6& demand_wrench,
                                            const AllocationTon& floor) {
  if (params.thrusters <= 8) return allocate_floored<8>(params, demand_wrench, floor);
  if (params.thrusters <= 16) return allocate_floored<16>(params, demand_wrench, floor);
  if (params.thrusters <= 24) return allocate_floored<24>(params, demand_wrench, floor);
  return allocate_floored<32>(params, demand_wrench, floor);
}

AllocationResult allocate_thrusters_capped(const AllocationParams& params, const Vec6& demand_wrench, double cap) {
  if (params.thrusters <= 8) return allocate_capped<8>(params, demand_wrench, cap);
  if (params.thrusters <= 16) return allocate_capped<16>(params, demand_wrench, cap);
  if (params.thrusters <= 24) return allocate_capped<24>(params, demand_wrench, cap);
  return allocate_capped<32>(params, demand_wrench, cap);
}

// One more column than the set's (the wrench's): the width above the count.
AttainableScale attainable_scale(const AllocationParams& params, const Vec6& wrench) {
  if (params.thrusters < 8) return scale_of<8>(params, wrench);
  if (params.thrusters < 16) return scale_of<16>(params, wrench);
  if (params.thrusters < 24) return scale_of<24>(params, wrench);
  if (params.thrusters < 32) return scale_of<32>(params, wrench);
  return scale_of<40>(params, wrench);
}

AllocationResult allocate_thrusters(const AllocationParams& params, const Vec6& demand_wrench,
                                    AllocationWarmStart& warm) {
  if (params.thrusters <= 8) return allocate_warm<8>(params, demand_wrench, warm);
  if (params.thrusters <= 16) return allocate_warm<16>(params, demand_wrench, warm);
  if (params.thrusters <= 24) return allocate_warm<24>(params, demand_wrench, warm);
  return allocate_warm<32>(params, demand_wrench, warm);
}

}  // namespace chaser::flight
