// The p-norm thrust allocation (issue 18; flight/norm_allocation.hpp) checked against independent
// solvers: COIN-OR CLP for the two linear programs of p = infinity (the attainable scale, the least
// peak and the least propellant under it), a KKT certificate and CLP's quadratic solver for p = 2,
// on thousands of demands, attainable and not, with every single-thruster loss of an MSR branch and
// of a 24-thruster set; and closed forms where symmetry gives one.
#include "flight/norm_allocation.hpp"

#include <coin/ClpSimplex.hpp>
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/random.hpp"
#include "flight/least_energy_allocation.hpp"
#include "tests/flight/allocation_test_support.hpp"

namespace chaser::flight {
namespace {

using namespace allocation_test;
using model::AllocationNorm;

// Both codes end on an optimal vertex of the same LP, so their optimal values differ by rounding
// (~1e-15 relative): 1e-9 leaves six orders of margin and still catches a wrong vertex (O(1e-3)).
constexpr double kLpRelTol = 1e-9;
// The least-peak second stage runs at the cap t* of the scale LP; CLP's peak differs from it by
// rounding (~1e-15 relative), and the propellant under the cap moves with the cap at the LP's
// sensitivity (up to ~1e3 on these sets): 1e-9 relative.
constexpr double kCappedPropellantRelTol = 1e-9;
// KKT certificate of (Q): stationarity and the multipliers' signs to 1e-9 of the scaled problem
// (|M_ij| <= 1 after scaling): the active-set method ends on the exact subproblem optimum, so
// rounding (~1e-14) is all that separates it from zero.
constexpr double kKktTol = 1e-9;
// CLP's quadratic simplex stops at its own tolerances (its answers' energy within ~1e-7 of ours):
// the second opinion on p = 2 is a looser check than the certificate, which decides.
constexpr double kClpQpTol = 1e-6;

// The sets: MSR branch A and a 24-thruster set (three tilted copies of it, the benchmark's), each
// whole and less any one thruster (a lost thruster leaves the active set: its column goes).
AllocationParams without(const AllocationParams& full, int lost) {
  AllocationParams p = full;
  if (lost < 0) return p;
  for (int i = lost; i + 1 < full.thrusters; ++i) p.config.col(i) = full.config.col(i + 1);
  p.config.col(full.thrusters - 1).setZero();
  p.thrusters = full.thrusters - 1;
  return p;
}

AllocationParams wide_params() {
  RandomStream rng(24, "test/norm_allocation/wide");
  return random_params(rng, 24);
}

// Attainable (M t, t in the unit cube; small ones, 0.1 to 2 N or N m) and mostly unattainable
// (log-uniform from 30 to 3000).
Vec6 demand_of(RandomStream& rng, const AllocationParams& p, int kind) {
  if (kind == 0) return p.config * random_on_times(rng, p.thrusters);
  Vec6 d;
  for (int j = 0; j < 6; ++j) d[j] = rng.normal();
  const double magnitude = kind == 1 ? rng.uniform(0.1, 2.0) : std::exp(rng.uniform(std::log(30.0), std::log(3000.0)));
  return d * magnitude / d.norm();
}

std::vector<CoinBigIndex> column_starts(const Eigen::MatrixXd& a, std::vector<int>& index, std::vector<double>& value) {
  std::vector<CoinBigIndex> start{0};
  for (int c = 0; c < a.cols(); ++c) {
    for (int r = 0; r < a.rows(); ++r)
      if (a(r, c) != 0.0) index.push_back(r), value.push_back(a(r, c));
    start.push_back(static_cast<CoinBigIndex>(index.size()));
  }
  return start;
}

// CLP: max lambda s.t. M s - lambda w = 0, 0 <= s <= 1, lambda >= 0.
double clp_scale(const AllocationParams& p, const Vec6& w) {
  const int n = p.thrusters;
  Eigen::MatrixXd a(6, n + 1);
  a << p.config.leftCols(n), -w;
  std::vector<double> lb(n + 1, 0.0), ub(n + 1, 1.0), obj(n + 1, 0.0), zero(6, 0.0);
  ub[n] = COIN_DBL_MAX;
  obj[n] = -1.0;
  const ClpOutcome out = solve_clp(a, lb, ub, obj, zero, zero, true);
  EXPECT_TRUE(out.optimal);
  return -out.objective;
}

// CLP: the least peak t (min t s.t. M u = w, u_i - t <= 0, 0 <= u <= 1), then the least
// propellant with every u_i <= t.
struct PeakReference {
  double peak = 0, propellant = 0;
};
PeakReference clp_least_peak(const AllocationParams& p, const Vec6& w) {
  const int n = p.thrusters;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(6 + n, n + 1);
  a.topLeftCorner(6, n) = p.config.leftCols(n);
  a.bottomLeftCorner(n, n).setIdentity();
  a.bottomRightCorner(n, 1).setConstant(-1.0);
  std::vector<double> lb(n + 1, 0.0), ub(n + 1, 1.0), obj(n + 1, 0.0);
  obj[n] = 1.0;
  std::vector<double> row_lb(w.data(), w.data() + 6), row_ub = row_lb;
  row_lb.resize(6 + n, -COIN_DBL_MAX);
  row_ub.resize(6 + n, 0.0);
  PeakReference ref;
  const ClpOutcome peak = solve_clp(a, lb, ub, obj, row_lb, row_ub, true);
  EXPECT_TRUE(peak.optimal);
  ref.peak = peak.objective;
  const std::vector<double> rhs(w.data(), w.data() + 6);
  const ClpOutcome prop = solve_clp(p.config.leftCols(n), std::vector<double>(n, 0.0),
                                    std::vector<double>(n, ref.peak), std::vector<double>(n, 1.0), rhs, rhs, true);
  EXPECT_TRUE(prop.optimal);
  ref.propellant = prop.objective;
  return ref;
}

// CLP's quadratic primal simplex on (Q): min 1/2 |u|^2 s.t. M u = w, 0 <= u <= 1; empty when CLP
// does not prove optimality (it fails to on some demands near the attainable set's boundary).
Eigen::VectorXd clp_least_energy(const AllocationParams& p, const Vec6& w) {
  const int n = p.thrusters;
  std::vector<int> index;
  std::vector<double> value;
  const Eigen::MatrixXd m = p.config.leftCols(n);
  const std::vector<CoinBigIndex> start = column_starts(m, index, value);
  const std::vector<double> lb(n, 0.0), ub(n, 1.0), obj(n, 0.0), rhs(w.data(), w.data() + 6);
  ClpSimplex model;
  model.setLogLevel(0);
  model.loadProblem(n, 6, start.data(), index.data(), value.data(), lb.data(), ub.data(), obj.data(), rhs.data(),
                    rhs.data());
  std::vector<CoinBigIndex> q_start(n + 1);
  std::vector<int> q_column(n);
  const std::vector<double> q_value(n, 1.0);
  for (int i = 0; i <= n; ++i) q_start[i] = i;
  for (int i = 0; i < n; ++i) q_column[i] = i;
  model.loadQuadraticObjective(n, q_start.data(), q_column.data(), q_value.data());
  model.primal();
  if (!model.isProvenOptimal()) return {};
  return Eigen::Map<const Eigen::VectorXd>(model.primalColumnSolution(), n);
}

// The KKT certificate of (Q) at u, independent of the solver's working set: a multiplier y of
// M u = w with u_F + M_F^T y = 0 on the free on-times (strictly inside [0, 1]) and the bounds'
// multipliers non-negative: at 0, m_i^T y >= 0; at 1, -(1 + m_i^T y) >= 0. Where fewer than six
// on-times are free (an unattainable demand's wrench on the attainable set's boundary) y is not
// fixed by the free ones, so CLP looks for it: min the total violation of those conditions, which
// must be 0 (to kKktTol) at an optimum. In the scaled problem (|M| <= 1).
void expect_kkt(const AllocationParams& p, const Vec6& w, const AllocationTon& ton, const std::string& what) {
  const int n = p.thrusters;
  const double scale = p.config.leftCols(n).cwiseAbs().maxCoeff();
  const Eigen::MatrixXd m = p.config.leftCols(n) / scale;
  const Eigen::VectorXd u = ton.head(n);
  EXPECT_LE((m * u - w / scale).cwiseAbs().maxCoeff(), kKktTol * (1.0 + (w / scale).cwiseAbs().maxCoeff())) << what;
  constexpr double kInside = 1e-12;
  // Columns: y (6, free), then one violation v_i >= 0 per on-time (two for free ones: +-).
  // Rows: free i: m_i^T y + v+ - v- = -u_i; at 0: m_i^T y + v_i >= 0; at 1: m_i^T y - v_i <= -1.
  const int cols = 6 + 2 * n;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, cols);
  std::vector<double> col_lb(cols, 0.0), col_ub(cols, COIN_DBL_MAX), obj(cols, 1.0), row_lb(n), row_ub(n);
  for (int j = 0; j < 6; ++j) col_lb[j] = -COIN_DBL_MAX, obj[j] = 0.0;
  for (int i = 0; i < n; ++i) {
    a.row(i).head(6) = m.col(i).transpose();
    a(i, 6 + 2 * i) = 1.0;
    if (u[i] > kInside && u[i] < 1.0 - kInside) {
      a(i, 7 + 2 * i) = -1.0;
      row_lb[i] = row_ub[i] = -u[i];
    } else if (u[i] <= kInside) {
      row_lb[i] = 0.0, row_ub[i] = COIN_DBL_MAX;
    } else {
      a(i, 6 + 2 * i) = -1.0;
      row_lb[i] = -COIN_DBL_MAX, row_ub[i] = -1.0;
    }
  }
  const ClpOutcome violation = solve_clp(a, col_lb, col_ub, obj, row_lb, row_ub, true);
  EXPECT_TRUE(violation.optimal) << what;
  EXPECT_LE(violation.objective, kKktTol) << what << ": no multiplier certifies the answer";
}

double peak_of(const AllocationParams& p, const AllocationTon& t) { return t.head(p.thrusters).maxCoeff(); }

struct Counts {
  int attainable = 0, unattainable = 0;
  int clp_qp_compared = 0;  // attainable demands on which CLP's QP proved optimality
  int clp_qp_agreed = 0;    // of those, where CLP's energy came within its accuracy of ours
};

// Every norm on one set and one demand, against the references.
void check_norms(const AllocationParams& p, const Vec6& demand, const std::string& what, Counts& counts) {
  AllocationWarmStart warm1, warm2, warm_inf;
  const AllocationResult r1 = allocate_thrusters(p, demand);
  const AllocationResult n1 = allocate_thrusters(p, demand, AllocationNorm::kOne, warm1);
  const AllocationResult r2 = allocate_thrusters(p, demand, AllocationNorm::kTwo, warm2);
  const AllocationResult rinf = allocate_thrusters(p, demand, AllocationNorm::kInfinity, warm_inf);
  ASSERT_TRUE(r1.converged && n1.converged && r2.converged && rinf.converged)
      << what << ": " << r1.converged << n1.converged << r2.converged << rinf.converged << " iterations " << r2.iterations
      << " " << rinf.iterations;
  (r1.feasible ? counts.attainable : counts.unattainable) += 1;
  // Stage 1 is common: the same verdict and the same realised wrench, hence the same error.
  EXPECT_EQ(r2.feasible, r1.feasible) << what;
  EXPECT_EQ(rinf.feasible, r1.feasible) << what;
  const int n = p.thrusters;
  const Vec6 wrench = r1.feasible ? demand : Vec6(p.config.leftCols(n) * r1.ton.head(n));
  const double wrench_size = p.config.leftCols(n).cwiseAbs().maxCoeff() * n;
  for (const AllocationResult* r : {&r2, &rinf})
    EXPECT_LE((p.config.leftCols(n) * r->ton.head(n) - wrench).cwiseAbs().maxCoeff(), 1e-10 * wrench_size) << what;
  EXPECT_NEAR(n1.propellant, r1.propellant, kLpRelTol * std::max(1.0, r1.propellant)) << what;

  // p = infinity: the least peak and, under it, the least propellant, as CLP finds them.
  const PeakReference ref = clp_least_peak(p, wrench);
  EXPECT_NEAR(peak_of(p, rinf.ton), ref.peak, kLpRelTol * std::max(ref.peak, 1e-3)) << what;
  EXPECT_NEAR(rinf.propellant, ref.propellant, kCappedPropellantRelTol * std::max(ref.propellant, 1e-3)) << what;

  // p = 2: optimal by its KKT certificate, and CLP's QP agrees.
  expect_kkt(p, wrench, r2.ton, what + ", p = 2");
  if (r1.feasible) {  // on the boundary (unattainable demands) CLP's QP rarely proves optimality
    const Eigen::VectorXd clp_u = clp_least_energy(p, wrench);
    if (clp_u.size() == n) {
      ++counts.clp_qp_compared;
      // (Q)'s minimiser u* is unique and the energy strongly convex: for any feasible u,
      // |u|^2 - |u*|^2 >= |u - u*|^2. So CLP's answer may be no lower in energy than ours, and
      // its distance from ours is bounded by its excess energy (a rigorous check, whatever
      // CLP's accuracy: one time in ~1,000 it stops 0.1 off, higher in energy, calling it optimal).
      const double clp_energy = clp_u.squaredNorm();
      const double our_energy = r2.ton.head(n).squaredNorm();
      EXPECT_LE(our_energy, clp_energy * (1.0 + kLpRelTol) + 1e-15) << what;
      EXPECT_LE((clp_u - r2.ton.head(n)).squaredNorm(), clp_energy - our_energy + kClpQpTol * kClpQpTol) << what;
      if (clp_energy <= our_energy * (1.0 + kClpQpTol)) ++counts.clp_qp_agreed;
    }
  }

  // Each norm is the least of its own kind among the three answers (all realise the same wrench).
  const double slack = 1e-9;
  EXPECT_LE(r1.propellant, r2.propellant + slack) << what;
  EXPECT_LE(r1.propellant, rinf.propellant + slack) << what;
  EXPECT_LE(r2.ton.squaredNorm(), r1.ton.squaredNorm() + slack) << what;
  EXPECT_LE(r2.ton.squaredNorm(), rinf.ton.squaredNorm() + slack) << what;
  EXPECT_LE(peak_of(p, rinf.ton), peak_of(p, r1.ton) + slack) << what;
  EXPECT_LE(peak_of(p, rinf.ton), peak_of(p, r2.ton) + slack) << what;
}

void check_set_and_losses(const AllocationParams& full, const std::string& name, int demands_per_set) {
  RandomStream rng(18, "test/norm_allocation/" + name);
  Counts counts;
  for (int lost = -1; lost < full.thrusters; ++lost) {
    const AllocationParams p = without(full, lost);
    for (int k = 0; k < demands_per_set; ++k) {
      const std::string what = name + " less " + std::to_string(lost) + ", demand " + std::to_string(k);
      check_norms(p, demand_of(rng, p, k % 3), what, counts);
      if (::testing::Test::HasFatalFailure()) return;
    }
  }
  std::printf("[%s] attainable %d (CLP's QP proved %d of them, agreeing on %d), unattainable %d\n", name.c_str(),
              counts.attainable, counts.clp_qp_compared, counts.clp_qp_agreed, counts.unattainable);
  EXPECT_GE(counts.clp_qp_agreed, counts.attainable * 3 / 4);  // the second opinion is not a rare one
  EXPECT_GE(counts.attainable, demands_per_set * full.thrusters / 3);  // both kinds in numbers
  EXPECT_GE(counts.unattainable, demands_per_set * full.thrusters / 5);
}

TEST(NormAllocation, MsrBranchAndEverySingleLossMatchReferences) {
  check_set_and_losses(msr_params(), "msr", 150);  // 9 sets x 150 = 1,350 demands
}

TEST(NormAllocation, TwentyFourThrustersAndEverySingleLossMatchReferences) {
  check_set_and_losses(wide_params(), "wide24", 60);  // 25 sets x 60 = 1,500 demands
}

// The attainable scale against CLP, along random directions, on sets of 6 to 32 thrusters (the
// widths 8 to 40 of its simplex, one column more than the set's).
TEST(NormAllocation, AttainableScaleMatchesClp) {
  RandomStream rng(18, "test/norm_allocation/scale");
  for (const int n : {6, 7, 8, 15, 16, 24, 31, 32}) {
    for (int g = 0; g < 5; ++g) {
      const AllocationParams p = random_params(rng, n);
      for (int k = 0; k < 20; ++k) {
        Vec6 w;
        for (int j = 0; j < 6; ++j) w[j] = rng.normal();
        w *= std::exp(rng.uniform(std::log(1e-3), std::log(1e3)));
        const AttainableScale s = attainable_scale(p, w);
        ASSERT_TRUE(s.converged) << n;
        const double ref = clp_scale(p, w);
        // Relative, down to the scale at which lambda w is rounding of the set's columns (a set of
        // six or seven random thrusters may have no push at all along w: lambda* = 0, CLP 1e-13).
        const double floor = 1e-12 * n * p.config.leftCols(n).cwiseAbs().maxCoeff() / w.cwiseAbs().maxCoeff();
        EXPECT_NEAR(s.scale, ref, kLpRelTol * ref + floor) << n << " " << g << " " << k;
        // s realises lambda* w
        EXPECT_LE((p.config.leftCols(n) * s.ton.head(n) - s.scale * w).cwiseAbs().maxCoeff(),
                  1e-10 * p.config.leftCols(n).cwiseAbs().maxCoeff() * n);
      }
    }
  }
  AllocationParams msr = msr_params();
  const AttainableScale zero = attainable_scale(msr, Vec6::Zero());
  EXPECT_TRUE(zero.converged);
  EXPECT_TRUE(std::isinf(zero.scale));
  Vec6 bad = Vec6::Ones();
  bad[2] = std::nan("");
  EXPECT_FALSE(attainable_scale(msr, bad).converged);
}

// Closed form by symmetry: every thruster of MSR branch A doubled (16 columns, each twice). For a
// demand the single set realises with all on-times below 1, the least-energy answer of the doubled
// set splits each single on-time equally between the twins (the split minimises u1^2 + u2^2 for a
// given sum, and the bounds stay inactive), so it is exactly half the single set's.
TEST(NormAllocation, LeastEnergyOfTwinThrustersIsHalfTheSingleAnswer) {
  const AllocationParams single = msr_params();
  AllocationParams twins = single;
  twins.thrusters = 2 * kMsr;
  twins.config.middleCols(kMsr, kMsr) = single.config.leftCols(kMsr);
  RandomStream rng(18, "test/norm_allocation/twins");
  int checked = 0;
  for (int k = 0; k < 200; ++k) {
    const Vec6 demand = single.config * (0.3 * random_on_times(rng, kMsr));
    AllocationWarmStart warm_single, warm_twins;
    const AllocationResult s = allocate_thrusters(single, demand, AllocationNorm::kTwo, warm_single);
    const AllocationResult t = allocate_thrusters(twins, demand, AllocationNorm::kTwo, warm_twins);
    ASSERT_TRUE(s.converged && t.converged);
    if (s.ton.maxCoeff() >= 1.0) continue;
    ++checked;
    for (int i = 0; i < kMsr; ++i) {
      EXPECT_NEAR(t.ton[i], 0.5 * s.ton[i], 1e-12) << k;
      EXPECT_NEAR(t.ton[i + kMsr], 0.5 * s.ton[i], 1e-12) << k;
    }
  }
  EXPECT_GE(checked, 150);
}

// p = infinity on a demand 0.6 m_1 along one column m_1 of MSR branch A, with k - 1 more copies of
// m_1 added to the set: the k copies alone realise it at u = 0.6 / k each, the least peak unless a
// mix with branch A's other columns goes lower, which it does not here (a branch-A column's
// wrench is far from m_1's direction, so any other thruster's share must be cancelled by a third);
// and with propellant as the tie-break the copies carry all of it, 0.6 in all.
TEST(NormAllocation, LeastPeakSharesEquallyAmongCopies) {
  const AllocationParams branch = msr_params();
  for (const int copies : {2, 3, 5}) {
    AllocationParams p = branch;
    for (int c = 0; c < copies - 1; ++c) p.config.col(kMsr + c) = branch.config.col(0);
    p.thrusters = kMsr + copies - 1;
    const Vec6 demand = 0.6 * branch.config.col(0);
    AllocationWarmStart warm;
    const AllocationResult r = allocate_thrusters(p, demand, AllocationNorm::kInfinity, warm);
    ASSERT_TRUE(r.converged && r.feasible);
    // The least-peak answer: at most 0.6 / copies on each (the copies alone reach it), and with
    // propellant the tie-break, the copies carry it at exactly 0.6 / copies each.
    EXPECT_NEAR(peak_of(p, r.ton), 0.6 / copies, 1e-12) << copies;
    EXPECT_NEAR(r.propellant, 0.6, 1e-9) << copies;
  }
}

// Invalid input is flagged, never thrown; p = 1 through the norm interface is the allocator itself.
TEST(NormAllocation, InvalidInputAndTheOneNorm) {
  AllocationParams p = msr_params();
  AllocationWarmStart warm;
  Vec6 bad = Vec6::Ones();
  bad[0] = std::nan("");
  for (const AllocationNorm norm : {AllocationNorm::kOne, AllocationNorm::kTwo, AllocationNorm::kInfinity}) {
    const AllocationResult r = allocate_thrusters(p, bad, norm, warm);
    EXPECT_FALSE(r.converged);
    EXPECT_TRUE(r.ton.isZero(0.0));
  }
  EXPECT_FALSE(least_energy_on_times(p, Vec6::Ones(), AllocationTon::Constant(2.0)).converged);
  RandomStream rng(18, "test/norm_allocation/one");
  for (int k = 0; k < 100; ++k) {
    const Vec6 d = demand_of(rng, p, k % 3);
    AllocationWarmStart a, b;
    const AllocationResult plain = allocate_thrusters(p, d, a);
    const AllocationResult one = allocate_thrusters(p, d, AllocationNorm::kOne, b);
    EXPECT_EQ(plain.ton, one.ton);
    EXPECT_EQ(plain.feasible, one.feasible);
  }
}

}  // namespace
}  // namespace chaser::flight
