// Cost of one thruster allocation (Fonod 2015 sec. II.C) on the MSR branch-A geometry, over fixed
// sets of 1000 pre-generated demands: typical control demands (|F_j| <= 1 N, |C_j| <= 1 N m, all
// attainable), large unattainable ones (best effort), and a 90/10 mix of the two; and the warm start
// (AllocationWarmStart) against the cold solve on a controller-like sequence: a slowly varying
// attainable demand M t(k), t a random walk of 0.01 per step in [0, 1]^8; and the small and large
// demands on a 24-thruster set, which the width-32 simplex solves.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "core/random.hpp"
#include "flight/norm_allocation.hpp"
#include "flight/thruster_allocation.hpp"
#include "model/thruster_geometry.hpp"
#include "tests/support/msr_branch_a.hpp"

namespace chaser::flight {
namespace {

constexpr int kDemandCount = 1000;

AllocationParams msr_allocation() {
  const model::ThrusterSetParams set = testing::msr_branch_a_thrusters();
  AllocationParams params;
  params.config = model::configuration_matrix(set, model::all_thrusters(set), Vec3::Zero());
  params.thrusters = set.count;
  return params;
}

// 24 thrusters (COMRADE's count, solved by the width-32 simplex) at fixed pseudo-random positions
// in a 2 m box with random directions: three copies of MSR branch A, each copy's directions
// turned, so the set spans with margin.
AllocationParams wide_allocation() {
  const model::ThrusterSetParams branch = testing::msr_branch_a_thrusters();
  RandomStream rng(24, "bench/allocation_wide");
  model::ThrusterSetParams set;
  set.count = 24;
  for (int i = 0; i < set.count; ++i) {
    set.thrusters[i] = branch.thrusters[i % 8];
    const Vec3 tilt(rng.normal(), rng.normal(), rng.normal());
    set.thrusters[i].direction_body = (set.thrusters[i].direction_body + 0.3 * tilt.normalized()).normalized();
  }
  AllocationParams params;
  params.config = model::configuration_matrix(set, model::all_thrusters(set), Vec3::Zero());
  params.thrusters = set.count;
  return params;
}

Vec6 small_demand(RandomStream& rng) {
  Vec6 d;
  for (int j = 0; j < 6; ++j) d[j] = rng.uniform(-1.0, 1.0);  // [N] then [N m]
  return d;
}

// A random direction with a magnitude of 200 to 1000 (N and N m): beyond what the branch can
// produce (at most ~50 N along an axis), so every call solves the best-effort problem.
Vec6 large_demand(RandomStream& rng) {
  Vec6 d;
  for (int j = 0; j < 6; ++j) d[j] = rng.normal();
  return d * (rng.uniform(200.0, 1000.0) / d.norm());
}

// kind 0: small, 1: large, 2: one large in ten.
std::vector<Vec6> demands(int kind) {
  RandomStream rng(1, "bench/allocation");
  std::vector<Vec6> out;
  for (int k = 0; k < kDemandCount; ++k) {
    const bool large = kind == 1 || (kind == 2 && k % 10 == 9);
    out.push_back(large ? large_demand(rng) : small_demand(rng));
  }
  return out;
}

void run(benchmark::State& state, int kind, bool wide = false) {
  const AllocationParams params = wide ? wide_allocation() : msr_allocation();
  const std::vector<Vec6> set = demands(kind);
  std::size_t k = 0;
  long feasible = 0, pivots = 0;
  for (auto _ : state) {
    const AllocationResult result = allocate_thrusters(params, set[k]);
    benchmark::DoNotOptimize(result);
    feasible += result.feasible;
    pivots += result.iterations;
    k = k + 1 == set.size() ? 0 : k + 1;
  }
  const double calls = static_cast<double>(state.iterations());
  state.counters["feasible_fraction"] = static_cast<double>(feasible) / calls;
  state.counters["iterations_per_call"] = static_cast<double>(pivots) / calls;
  state.SetItemsProcessed(state.iterations());
}

void BM_AllocateSmallFeasible(benchmark::State& state) { run(state, 0); }
void BM_AllocateLargeInfeasible(benchmark::State& state) { run(state, 1); }
void BM_AllocateMixed(benchmark::State& state) { run(state, 2); }
void BM_AllocateSmallFeasible24(benchmark::State& state) { run(state, 0, true); }
void BM_AllocateLargeInfeasible24(benchmark::State& state) { run(state, 1, true); }

// The slowly varying sequence, solved cold (state.range(0) == 0) or with the warm start (1).
void BM_AllocateWarmSequence(benchmark::State& state) {
  const AllocationParams params = msr_allocation();
  RandomStream rng(1, "bench/allocation_walk");
  AllocationTon t = AllocationTon::Zero();
  t.head(params.thrusters).setConstant(0.3);
  std::vector<Vec6> set;
  for (int k = 0; k < kDemandCount; ++k) {
    for (int i = 0; i < params.thrusters; ++i) t[i] = std::clamp(t[i] + 0.01 * rng.normal(), 0.0, 1.0);
    set.push_back(params.config * t);
  }
  const bool use_warm = state.range(0) == 1;
  AllocationWarmStart warm;
  std::size_t k = 0;
  for (auto _ : state) {
    const AllocationResult result = use_warm ? allocate_thrusters(params, set[k], warm) : allocate_thrusters(params, set[k]);
    benchmark::DoNotOptimize(result);
    k = k + 1 == set.size() ? 0 : k + 1;
  }
  state.counters["warm_hit_fraction"] =
      use_warm ? static_cast<double>(warm.hits) / static_cast<double>(warm.hits + warm.solves) : 0.0;
  state.SetItemsProcessed(state.iterations());
}

// The norms of flight/norm_allocation.hpp on the 24-thruster set: range(0) = p (1, 2,
// or 0 for infinity), range(1) = demand kind (0 small and attainable, 1 large and unattainable);
// a fresh warm start per call, so that p = 1 is the cold solve and the rest is the norm's own cost.
void BM_AllocateNorm24(benchmark::State& state) {
  const AllocationParams params = wide_allocation();
  const std::vector<Vec6> set = demands(static_cast<int>(state.range(1)));
  const model::AllocationNorm norm = state.range(0) == 1   ? model::AllocationNorm::kOne
                                     : state.range(0) == 2 ? model::AllocationNorm::kTwo
                                                           : model::AllocationNorm::kInfinity;
  std::size_t k = 0;
  long iterations = 0;
  for (auto _ : state) {
    AllocationWarmStart warm;
    const AllocationResult result = allocate_thrusters(params, set[k], norm, warm);
    benchmark::DoNotOptimize(result);
    iterations += result.iterations;
    k = k + 1 == set.size() ? 0 : k + 1;
  }
  state.counters["iterations_per_call"] = static_cast<double>(iterations) / static_cast<double>(state.iterations());
  state.SetItemsProcessed(state.iterations());
}

BENCHMARK(BM_AllocateSmallFeasible);
BENCHMARK(BM_AllocateWarmSequence)->Arg(0)->Arg(1);
BENCHMARK(BM_AllocateLargeInfeasible);
BENCHMARK(BM_AllocateMixed);
BENCHMARK(BM_AllocateSmallFeasible24);
BENCHMARK(BM_AllocateLargeInfeasible24);
BENCHMARK(BM_AllocateNorm24)->ArgsProduct({{1, 2, 0}, {0, 1}});

}  // namespace
}  // namespace chaser::flight
