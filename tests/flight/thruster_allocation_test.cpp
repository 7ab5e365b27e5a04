// Thruster allocation (Fonod 2015 sec. II.C) checked against COIN-OR CLP, an independent simplex
// code, on the same linear programs: the equality LP (least propellant), and when that is
// infeasible the weighted-L1 best effort followed by least propellant among its minimisers.
#include "flight/thruster_allocation.hpp"

#include <coin/ClpSimplex.hpp>
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "core/constants.hpp"
#include "core/random.hpp"
#include "model/thruster_geometry.hpp"
#include "tests/flight/allocation_test_support.hpp"
#include "tests/support/msr_branch_a.hpp"

namespace chaser::flight {
namespace {

using namespace allocation_test;

// Agreement with CLP. Both codes return a basic optimal solution and the optimal values are unique,
// so they differ only by rounding (about 1e-15 relative for well-conditioned bases): 1e-9 relative
// leaves six orders of margin and still catches any wrong vertex, whose values differ at O(1e-3).
constexpr double kRelTol = 1e-9;
// Propellant is a sum of non-negative on-times, so it has no cancellation and its relative accuracy
// holds down to tiny demands; the floor covers optimal costs near zero, where an on-time that is
// truly 0 can come out at rounding level (5e-17 seen): 1e-14 is ~50 ulp of one full on-time.
constexpr double kPropellantFloor = 1e-14;
// The weighted error sums |M ton - d| where M ton is formed from eight terms of size |M|: rounding
// alone is ~8 eps |M| w per axis, so the floor is 1e-12 |M|_max w_max (1e3 times that).
constexpr double kErrorFloorRel = 1e-12;

// Demands of three kinds so that both verdicts occur in numbers: kind 0, M t with t inside the unit
// cube (attainable); kind 1, small control demands (|F_j| <= 1 N, |C_j| <= 1 N m); kinds 2 and 3,
// random directions with a log-uniform magnitude from 1 to 3000 (mostly unattainable).
Vec6 random_demand(RandomStream& rng, const AllocationParams& p, int kind) {
  Vec6 d;
  if (kind == 0) return p.config * random_on_times(rng, p.thrusters);
  for (int j = 0; j < 6; ++j) d[j] = kind == 1 ? rng.uniform(-1, 1) : rng.normal();
  if (kind >= 2) d *= std::exp(rng.uniform(0.0, std::log(3000.0))) / d.norm();
  return d;
}

struct Reference {
  bool feasible = false;
  double propellant = 0;      // optimum of the equality LP, or of stage 3 when infeasible
  double weighted_error = 0;  // optimum of the weighted-L1 LP (0 when feasible)
  bool ok = false;            // CLP reached a proven verdict in every stage
};

// floor: the on-times' lower bounds (allocate_thrusters_floored), zero for allocate_thrusters.
Reference clp_reference(const AllocationParams& p, const Vec6& d, const AllocationTon& floor = AllocationTon::Zero()) {
  const int n = p.thrusters;
  const Eigen::MatrixXd m = p.config.leftCols(n);
  const Vec6& w = p.error_weights;
  Reference ref;
  const std::vector<double> rhs(d.data(), d.data() + 6);
  const std::vector<double> ton_lb(floor.data(), floor.data() + n);
  const ClpOutcome eq = solve_clp(m, ton_lb, std::vector<double>(n, 1.0), std::vector<double>(n, 1.0), rhs, rhs, false);
  if (eq.optimal) {
    ref.feasible = ref.ok = true;
    ref.propellant = eq.objective;
    return ref;
  }
  if (!eq.infeasible) return ref;
  // Stage 2: M ton + e+ - e- = d, min w (e+ + e-).
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(7, n + 12);
  a.block(0, 0, 6, n) = m;
  a.block(0, n, 6, 6) = Eigen::MatrixXd::Identity(6, 6);
  a.block(0, n + 6, 6, 6) = -Eigen::MatrixXd::Identity(6, 6);
  std::vector<double> lb(n + 12, 0.0), ub(n + 12, COIN_DBL_MAX), obj(n + 12, 0.0);
  for (int i = 0; i < n; ++i) lb[i] = floor[i], ub[i] = 1.0;
  for (int j = 0; j < 6; ++j) obj[n + j] = obj[n + 6 + j] = w[j];
  const ClpOutcome err = solve_clp(a.topRows(6), lb, ub, obj, rhs, rhs, true);
  if (!err.optimal) return ref;
  ref.weighted_error = err.objective;
  // Stage 3: the same rows plus w (e+ + e-) <= E*, min sum ton.
  for (int j = 0; j < 6; ++j) a(6, n + j) = a(6, n + 6 + j) = w[j];
  std::vector<double> row_lb = rhs, row_ub = rhs;
  row_lb.push_back(-COIN_DBL_MAX);
  row_ub.push_back(err.objective);
  std::fill(obj.begin(), obj.end(), 0.0);
  std::fill(obj.begin(), obj.begin() + n, 1.0);
  const ClpOutcome prop = solve_clp(a, lb, ub, obj, row_lb, row_ub, true);
  ref.ok = prop.optimal;
  ref.propellant = prop.objective;
  return ref;
}

struct Tally {
  int feasible = 0, infeasible = 0;
  double worst_prop = 0, worst_error = 0;  // largest differences seen, relative to the tolerance
  int max_iterations = 0;
};

// One demand: our result against CLP's, every property the brief lists; with a floor (not null),
// allocate_thrusters_floored against CLP with those lower bounds.
void check_against_clp(const AllocationParams& params, const Vec6& d, Tally& tally,
                       const AllocationTon* floor = nullptr) {
  const AllocationResult res = floor ? allocate_thrusters_floored(params, d, *floor) : allocate_thrusters(params, d);
  const Reference ref = floor ? clp_reference(params, d, *floor) : clp_reference(params, d);
  ASSERT_TRUE(ref.ok) << "CLP gave no proven verdict for d = " << d.transpose();
  ASSERT_TRUE(res.converged);
  tally.max_iterations = std::max(tally.max_iterations, res.iterations);
  for (int i = 0; i < params.thrusters; ++i) {
    EXPECT_GE(res.ton[i], (floor ? (*floor)[i] : 0.0) - 1e-12);
    EXPECT_LE(res.ton[i], 1.0 + 1e-12);
  }
  for (int i = params.thrusters; i < model::kMaxThrusters; ++i) EXPECT_EQ(res.ton[i], 0.0);  // padding
  const double m_max = params.config.cwiseAbs().maxCoeff();
  ASSERT_EQ(res.feasible, ref.feasible) << "d = " << d.transpose() << ", our weighted error "
                                        << res.weighted_error;
  const double prop_tol = kRelTol * std::abs(ref.propellant) + kPropellantFloor;
  EXPECT_NEAR(res.propellant, ref.propellant, prop_tol) << "d = " << d.transpose();
  tally.worst_prop =
      std::max(tally.worst_prop, std::abs(res.propellant - ref.propellant) / prop_tol);
  if (res.feasible) {
    ++tally.feasible;
    const double scale = std::max(m_max, d.cwiseAbs().maxCoeff());
    EXPECT_LT(res.residual.cwiseAbs().maxCoeff(), 1e-9 * scale);
    return;
  }
  ++tally.infeasible;
  const double err_floor = kErrorFloorRel * m_max * params.error_weights.maxCoeff();
  const double err_tol = kRelTol * std::abs(ref.weighted_error) + err_floor;
  EXPECT_NEAR(res.weighted_error, ref.weighted_error, err_tol) << "d = " << d.transpose();
  tally.worst_error =
      std::max(tally.worst_error, std::abs(res.weighted_error - ref.weighted_error) / err_tol);
}

void report(const char* name, const Tally& t) {
  std::printf("[%s] feasible %d, infeasible %d, worst |dprop|/tol %.2e, worst |derr|/tol %.2e, "
              "max iterations %d\n",
              name, t.feasible, t.infeasible, t.worst_prop, t.worst_error, t.max_iterations);
}

// 1200 demands on the MSR branch-A geometry, unit weights: same verdict and optimal values as CLP.
TEST(ThrusterAllocation, MsrRandomDemandsMatchClp) {
  RandomStream rng(2015, "test/allocation/msr");
  AllocationParams params = msr_params();
  Tally tally;
  for (int k = 0; k < 1200; ++k) {
    check_against_clp(params, random_demand(rng, params, k % 4), tally);
    if (HasFatalFailure()) return;
  }
  report("msr", tally);
  EXPECT_GE(tally.feasible, 240);  // both verdicts are exercised in numbers (20% or more)
  EXPECT_GE(tally.infeasible, 240);
}

// Random geometries x 20 demands, random weights in [0.2, 5]: the allocator is not tuned to one
// layout, one width or to unit weights. Sets of up to eight are solved at width 8, larger ones at
// the capacity of 32 (thruster_allocation.cpp), so both solvers are checked: 6 thrusters (the
// fewest that can span), 8, 12, COMRADE's 24, and the full 32.
class RandomGeometries : public ::testing::TestWithParam<int> {};

TEST_P(RandomGeometries, MatchClp) {
  const int n = GetParam();
  RandomStream rng(2015, "test/allocation/random/" + std::to_string(n));
  Tally tally;
  const int geometries = n == 8 ? 60 : 20;
  for (int g = 0; g < geometries; ++g) {
    AllocationParams params = random_params(rng, n);
    for (int j = 0; j < 6; ++j)
      params.error_weights[j] = std::exp(rng.uniform(std::log(0.2), std::log(5.0)));
    for (int k = 0; k < 20; ++k) {
      check_against_clp(params, random_demand(rng, params, k % 4), tally);
      if (HasFatalFailure()) return;
    }
  }
  report(("random geometries, " + std::to_string(n) + " thrusters").c_str(), tally);
  EXPECT_GE(tally.feasible, geometries * 3);  // both verdicts are exercised in numbers (15% or more;
  EXPECT_GE(tally.infeasible, geometries * 3);  // 32 thrusters reach more of the random demands)
}

INSTANTIATE_TEST_SUITE_P(ThrusterAllocation, RandomGeometries, ::testing::Values(6, 8, 12, 24, 32));

// The width-8 and the width-32 solvers give the same optimum: MSR branch A solved as eight
// thrusters, and as nine whose ninth produces nothing (a zero column costs propellant and realises
// nothing, so no optimum fires it), on attainable and unattainable demands.
TEST(ThrusterAllocation, WideSolverAgreesWithNarrowOne) {
  RandomStream rng(17, "test/allocation/widths");
  const AllocationParams narrow = msr_params();
  AllocationParams wide = narrow;
  wide.thrusters = kMsr + 1;  // column 8 is zero already
  for (int k = 0; k < 400; ++k) {
    const Vec6 d = random_demand(rng, narrow, k % 4);
    const AllocationResult a = allocate_thrusters(narrow, d);
    const AllocationResult b = allocate_thrusters(wide, d);
    ASSERT_TRUE(a.converged && b.converged) << k;
    ASSERT_EQ(a.feasible, b.feasible) << k;
    EXPECT_NEAR(a.propellant, b.propellant, kRelTol * a.propellant + kPropellantFloor) << k;
    EXPECT_NEAR(a.weighted_error, b.weighted_error, kRelTol * a.weighted_error + 1e-12) << k;
    EXPECT_EQ(b.ton[kMsr], 0.0) << k;
  }
}

// Lexicographic best effort where the error minimisers are many: a planar layout (positions and
// directions in the x-y plane) produces only F_x, F_y and C_z, so F_z, C_x and C_y of the demand
// are missed whatever ton is, and every ton realising the other three axes minimises the error.
// Among them the allocator must take the least propellant, which is the equality LP on those three
// rows alone: an independent check of the second stage, which the random cases above rarely reach
// because their error minimiser is almost always unique.
TEST(ThrusterAllocation, PlanarLayoutBestEffortIsLeastPropellantOnReachableAxes) {
  RandomStream rng(5, "test/allocation/planar");
  Tally tally;
  int many_minimisers = 0;
  for (int g = 0; g < 20; ++g) {
    constexpr int kN = kMsr;
    model::ThrusterSetParams set;
    set.count = kN;
    for (int i = 0; i < kN; ++i) {
      const double angle = rng.uniform(0.0, 2.0 * kPi);
      set.thrusters[i] = {Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), 0.0),
                          Vec3(std::cos(angle), std::sin(angle), 0.0), 22.0};
    }
    AllocationParams params;
    params.config = model::configuration_matrix(set, model::all_thrusters(set), Vec3::Zero());
    params.thrusters = kN;
    for (int j = 0; j < 6; ++j) params.error_weights[j] = rng.uniform(0.5, 2.0);
    const int reachable[3] = {0, 1, 5};  // F_x, F_y, C_z
    Eigen::Matrix<double, 3, kN> m3;
    for (int r = 0; r < 3; ++r) m3.row(r) = params.config.row(reachable[r]).head<kN>();
    for (int k = 0; k < 10; ++k) {
      const AllocationTon t = random_on_times(rng, kN);
      Vec6 d = params.config * t;  // reachable axes attainable...
      for (const int j : {2, 3, 4}) d[j] = rng.uniform(-5, 5);  // ...the others not
      const AllocationResult res = allocate_thrusters(params, d);
      ASSERT_FALSE(res.feasible);
      const double missed = params.error_weights[2] * std::abs(d[2]) +
                            params.error_weights[3] * std::abs(d[3]) +
                            params.error_weights[4] * std::abs(d[4]);
      const double err_floor =
          kErrorFloorRel * params.config.cwiseAbs().maxCoeff() * params.error_weights.maxCoeff();
      EXPECT_NEAR(res.weighted_error, missed, err_floor);  // the reachable axes are met exactly
      const std::vector<double> rhs = {d[0], d[1], d[5]};
      const std::vector<double> zeros(kN, 0.0), ones(kN, 1.0);
      const ClpOutcome eq = solve_clp(m3, zeros, ones, ones, rhs, rhs, true);
      ASSERT_TRUE(eq.optimal);
      EXPECT_NEAR(res.propellant, eq.objective, kRelTol * eq.objective + kPropellantFloor);
      many_minimisers += eq.objective < t.sum() - 1e-6;  // t minimises the error, at more cost
      check_against_clp(params, d, tally);
    }
  }
  report("planar", tally);
  EXPECT_GE(many_minimisers, 150);  // the second stage mattered in most cases
}

// Zero demand: ton = 0 is the only zero-propellant point and it is exact.
TEST(ThrusterAllocation, ZeroDemandNeedsNoFiring) {
  AllocationParams params = msr_params();
  const AllocationResult res = allocate_thrusters(params, Vec6::Zero());
  EXPECT_TRUE(res.feasible);
  EXPECT_TRUE(res.converged);
  EXPECT_EQ(res.propellant, 0.0);
  EXPECT_TRUE((res.ton.array() == 0.0).all());
  EXPECT_TRUE((res.residual.array() == 0.0).all());
}

// A demand on the boundary of the attainable set: d = M t* with t* maximising c' M t over the cube,
// i.e. t*_i = 1 where c' M_i > 0 and 0 elsewhere. Every t with M t = d attains that maximum, so t*
// is the only solution: the allocator must find it, with its ton_i at 1 (to 1e-10). Pushing d out
// by 1e-6 relative makes it unattainable, and the best effort then misses by about 1e-6 |d|.
TEST(ThrusterAllocation, BoundaryDemandNeedsFullOnTimes) {
  RandomStream rng(7, "test/allocation/boundary");
  AllocationParams params = msr_params();
  Tally tally;
  for (int k = 0; k < 50; ++k) {
    Vec6 c;
    for (int j = 0; j < 6; ++j) c[j] = rng.normal();
    AllocationTon t_star = AllocationTon::Zero();
    for (int i = 0; i < kMsr; ++i) t_star[i] = c.dot(params.config.col(i)) > 0.0 ? 1.0 : 0.0;
    const Vec6 d = params.config * t_star;
    const AllocationResult res = allocate_thrusters(params, d);
    EXPECT_TRUE(res.feasible);
    EXPECT_LT((res.ton - t_star).cwiseAbs().maxCoeff(), 1e-10);
    check_against_clp(params, d, tally);
    const AllocationResult out = allocate_thrusters(params, d * (1.0 + 1e-6));
    EXPECT_FALSE(out.feasible);
    EXPECT_LT(out.weighted_error, 1e-5 * d.cwiseAbs().sum());  // the miss is of order 1e-6 |d|
    check_against_clp(params, d * (1.0 + 1e-6), tally);
  }
  report("boundary", tally);
}

// Degenerate demands along one column: s M_i is attainable with ton = s e_i, so the optimum costs
// at most s, and it matches CLP whichever (possibly cheaper) combination is optimal.
TEST(ThrusterAllocation, SingleColumnDemands) {
  AllocationParams params = msr_params();
  Tally tally;
  for (int i = 0; i < kMsr; ++i) {
    for (const double s : {1e-6, 0.3, 1.0}) {
      const Vec6 d = s * params.config.col(i);
      const AllocationResult res = allocate_thrusters(params, d);
      EXPECT_TRUE(res.feasible);
      EXPECT_LE(res.propellant, s * (1.0 + 1e-12));
      check_against_clp(params, d, tally);
    }
  }
  report("single column", tally);
}

// Same input twice gives bit-identical output: no hidden state, no uninitialised memory.
TEST(ThrusterAllocation, Deterministic) {
  RandomStream rng(11, "test/allocation/determinism");
  AllocationParams params = msr_params();
  for (int k = 0; k < 300; ++k) {
    const Vec6 d = random_demand(rng, params, k % 4);
    const AllocationResult a = allocate_thrusters(params, d);
    const AllocationResult b = allocate_thrusters(params, d);
    EXPECT_EQ(std::memcmp(a.ton.data(), b.ton.data(), sizeof(double) * model::kMaxThrusters), 0);
    EXPECT_EQ(std::memcmp(a.residual.data(), b.residual.data(), sizeof(double) * 6), 0);
    EXPECT_EQ(std::memcmp(&a.propellant, &b.propellant, sizeof(double)), 0);
    EXPECT_EQ(std::memcmp(&a.weighted_error, &b.weighted_error, sizeof(double)), 0);
    EXPECT_EQ(a.feasible, b.feasible);
    EXPECT_EQ(a.iterations, b.iterations);
  }
}

// The warm start returns an optimum of the same problem: on a controller-like sequence (a slowly
// turning attainable demand, with jumps, unattainable demands and a change of configuration, as at
// a branch switch) every answer has the cold solve's feasibility verdict and propellant (the LP's
// optimal value is unique, so equal cost at a feasible point means optimal: tolerances as for CLP),
// meets an attainable demand to the cold residual's accuracy, and is bitwise the cold answer where
// it had to solve (unattainable demands). The fast path must actually serve most slow steps.
TEST(ThrusterAllocation, WarmStartGivesTheColdOptimum) {
  RandomStream rng(2024, "warm_start");
  AllocationParams params = msr_params();
  const AllocationParams other = random_params(rng, kMsr);
  AllocationWarmStart warm;
  AllocationTon t = AllocationTon::Zero();
  t.head<kMsr>().setConstant(0.3);
  int slow_steps = 0;
  for (int k = 0; k < 4000; ++k) {
    const bool switched = k >= 3000;  // the last quarter on another configuration
    const AllocationParams& p = switched ? other : params;
    for (int i = 0; i < kMsr; ++i) t[i] = std::clamp(t[i] + 0.01 * rng.normal(), 0.0, 1.0);
    Vec6 d = p.config * t;
    if (k % 97 == 0) d = random_demand(rng, p, 1);            // a jump
    else if (k % 53 == 0) d = random_demand(rng, p, 3);       // unattainable
    else ++slow_steps;
    const AllocationResult cold = allocate_thrusters(p, d);
    const std::int64_t solves_before = warm.solves;
    const AllocationResult hot = allocate_thrusters(p, d, warm);
    ASSERT_EQ(hot.feasible, cold.feasible) << k;
    EXPECT_TRUE(hot.converged) << k;
    EXPECT_NEAR(hot.propellant, cold.propellant, kRelTol * cold.propellant + kPropellantFloor) << k;
    if (cold.feasible) {
      const double scale = d.cwiseAbs().maxCoeff() + (p.config.cwiseAbs() * hot.ton).maxCoeff();
      EXPECT_LE(hot.residual.cwiseAbs().maxCoeff(), 1e-11 * scale) << k;
      EXPECT_TRUE((hot.ton.array() >= 0.0).all() && (hot.ton.array() <= 1.0).all()) << k;
    }
    if (warm.solves > solves_before) {
      EXPECT_EQ(std::memcmp(hot.ton.data(), cold.ton.data(), sizeof(double) * model::kMaxThrusters), 0) << k;
    }
  }
  EXPECT_EQ(warm.config, other.config);  // the slots were dropped at the switch
  EXPECT_GT(warm.hits, slow_steps / 2) << "hits " << warm.hits << " of " << slow_steps << " slow steps";
  std::printf("warm start: %lld of 4000 answered from a kept basis\n", static_cast<long long>(warm.hits));
}

// Floors (an active check's test pulse): one or two random thrusters held to at least a random
// on-time in [0.05, 0.5], MSR's 8 and COMRADE-like 24-thruster random geometries, random weights:
// the same verdict and optimal values as CLP with those lower bounds, every on-time at or above its
// floor. Where the demand stays attainable the floored thrusters' force and torque are cancelled by
// the others (residual at rounding) and the answer costs at least the unfloored one.
TEST(ThrusterAllocation, FlooredOnTimesMatchClp) {
  for (const int n : {8, 24}) {
    RandomStream rng(2020, "test/allocation/floored/" + std::to_string(n));
    Tally tally;
    int cancelled = 0;
    for (int g = 0; g < 20; ++g) {
      AllocationParams params = n == kMsr && g == 0 ? msr_params() : random_params(rng, n);
      for (int j = 0; j < 6; ++j) params.error_weights[j] = std::exp(rng.uniform(std::log(0.2), std::log(5.0)));
      for (int k = 0; k < 20; ++k) {
        AllocationTon floor = AllocationTon::Zero();
        for (int c = 0; c < 1 + k % 2; ++c)
          floor[static_cast<int>(rng.uniform() * n) % n] = rng.uniform(0.05, 0.5);
        const Vec6 d = random_demand(rng, params, k % 4);
        check_against_clp(params, d, tally, &floor);
        if (HasFatalFailure()) return;
        const AllocationResult floored = allocate_thrusters_floored(params, d, floor);
        const AllocationResult free = allocate_thrusters(params, d);
        if (floored.feasible) {
          ++cancelled;
          EXPECT_GE(floored.propellant, free.propellant - 1e-12);
        }
      }
    }
    report(("floored, " + std::to_string(n) + " thrusters").c_str(), tally);
    EXPECT_GE(tally.feasible, 60);  // both verdicts in numbers
    EXPECT_GE(tally.infeasible, 60);
    EXPECT_EQ(cancelled, tally.feasible);
  }
}

// A zero floor is the unfloored problem, bit for bit; bad floors are flagged like bad input.
TEST(ThrusterAllocation, ZeroFloorIsTheUnflooredAnswerAndBadFloorsAreFlagged) {
  AllocationParams params = msr_params();
  RandomStream rng(7, "test/allocation/zero-floor");
  for (int k = 0; k < 200; ++k) {
    const Vec6 d = random_demand(rng, params, k % 4);
    const AllocationResult a = allocate_thrusters(params, d);
    const AllocationResult b = allocate_thrusters_floored(params, d, AllocationTon::Zero());
    EXPECT_EQ(std::memcmp(a.ton.data(), b.ton.data(), sizeof(double) * model::kMaxThrusters), 0) << k;
    EXPECT_EQ(a.feasible, b.feasible);
  }
  AllocationTon floor = AllocationTon::Zero();
  for (const double bad : {-0.1, 1.5, std::numeric_limits<double>::quiet_NaN()}) {
    floor[3] = bad;
    const AllocationResult r = allocate_thrusters_floored(params, Vec6::Constant(0.1), floor);
    EXPECT_FALSE(r.converged) << bad;
    EXPECT_TRUE((r.ton.array() == 0.0).all());
  }
  floor.setZero();
  floor[kMsr] = 0.2;  // beyond the set
  EXPECT_FALSE(allocate_thrusters_floored(params, Vec6::Constant(0.1), floor).converged);
  // A floor alone under a zero demand: the others cancel it.
  floor.setZero();
  floor[0] = 0.1;
  const AllocationResult pulse = allocate_thrusters_floored(params, Vec6::Zero(), floor);
  EXPECT_TRUE(pulse.converged && pulse.feasible);
  EXPECT_GE(pulse.ton[0], 0.1);
  EXPECT_LT(pulse.residual.cwiseAbs().maxCoeff(), 1e-12 * params.config.cwiseAbs().maxCoeff());
}

// Invalid input never hangs or throws: it returns ton = 0 and says it did not converge.
TEST(ThrusterAllocation, InvalidInputIsFlagged) {
  AllocationParams params = msr_params();
  Vec6 d = Vec6::Constant(0.1);
  d[2] = std::numeric_limits<double>::quiet_NaN();
  const AllocationResult nan_demand = allocate_thrusters(params, d);
  EXPECT_FALSE(nan_demand.converged);
  EXPECT_FALSE(nan_demand.feasible);
  EXPECT_TRUE((nan_demand.ton.array() == 0.0).all());
  params.error_weights[4] = 0.0;
  const AllocationResult zero_weight = allocate_thrusters(params, Vec6::Constant(0.1));
  EXPECT_FALSE(zero_weight.converged);
  EXPECT_TRUE((zero_weight.ton.array() == 0.0).all());
}

}  // namespace
}  // namespace chaser::flight
