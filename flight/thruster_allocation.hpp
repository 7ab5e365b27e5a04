#pragma once
// Thruster allocation of the thruster management function (TMF, Fonod 2015 sec. II.C).
//
// Given the wrench w_d = [F_d; C_d] that the controller and modulator ask the active thrusters to
// realise on average over one control period, find the scaled on-times ton (0 <= ton_i <= 1,
// eq. 2: [F; C] = M ton) that realise it with the least propellant:
//
//   min  sum_i ton_i   s.t.  M ton = w_d,  0 <= ton <= 1.                         (P)
//
// When w_d lies outside the attainable set {M ton : 0 <= ton <= 1}, (P) has no solution and the
// allocator returns the weighted best effort, lexicographically:
//
//   E* = min  sum_j w_j |(M ton - w_d)_j|  over 0 <= ton <= 1,                    (E)
//   then min sum_i ton_i among the ton attaining E*.
//
// Both are solved exactly (to floating-point pivoting accuracy) by a hand-written bounded-variable
// primal simplex, deterministic and allocation-free; see thruster_allocation.cpp for the method.
#include <array>
#include <cstdint>

#include "core/types.hpp"
#include "model/thruster_geometry.hpp"

namespace chaser::flight {

using AllocationTon = Eigen::Matrix<double, model::kMaxThrusters, 1>;

struct AllocationParams {
  // M [N; N m]: column i is the force and torque of the set's thruster i open for a whole period
  // (eq. 2); columns [0, thrusters) used. A set is solved at its count rounded up to a multiple of
  // eight (thruster_allocation.cpp): the optimum is the same, the narrow solve faster.
  model::ConfigMatrix config = model::ConfigMatrix::Zero();
  int thrusters = 0;                  // 1..model::kMaxThrusters
  Vec6 error_weights = Vec6::Ones();  // [1/N; 1/(N m)] w_j of the best-effort problem (E), all > 0
};

struct AllocationResult {
  AllocationTon ton = AllocationTon::Zero();  // [-] scaled on-times, 0 <= ton_i <= 1, [0, thrusters) used
  bool feasible = false;                  // demand attainable: |M ton - demand| within tolerance
  double propellant = 0.0;                // [-] sum of ton, the cost of (P), in full-period firings
  Vec6 residual = Vec6::Zero();           // [N; N m] M ton - demand
  double weighted_error = 0.0;            // [-] sum_j w_j |residual_j|, the value of (E)
  int iterations = 0;                     // simplex iterations (pivots, bound flips), both phases
  bool converged = false;  // false: iteration cap hit or non-finite/invalid input; ton is still
                           // within [0, 1] but may not be optimal
};

// Solves (P), or (E) then least propellant when (P) is infeasible. Allocation-free, never throws,
// bounded in time (iteration cap). Preconditions: finite config, error_weights > 0; otherwise the
// result is ton = 0 with converged = false (also for thrusters outside 1..kMaxThrusters).
AllocationResult allocate_thrusters(const AllocationParams& params, const Vec6& demand_wrench);

// (P) and (E) with floors on the on-times, floor_i <= ton_i <= 1: an active check's test pulse,
// which the other thrusters cancel whenever the demand stays attainable (M ton = w_d
// still holds; the check costs only propellant). Solved as the problem in t = ton - floor,
// 0 <= t <= 1 - floor, with the demand w_d - M floor, by the same simplex, cold (the floors change
// the problem, so no warm start). floor: 0 <= floor_i <= 1, zero from params.thrusters on;
// otherwise, or for an invalid problem, ton = 0 with converged = false.
AllocationResult allocate_thrusters_floored(const AllocationParams& params, const Vec6& demand_wrench,
                                            const AllocationTon& floor);

// (P) and (E) with every on-time capped, 0 <= ton_i <= cap (0 < cap <= 1): the second stage of the
// least-peak allocation (flight/norm_allocation.hpp). Otherwise, ton = 0 with converged = false.
AllocationResult allocate_thrusters_capped(const AllocationParams& params, const Vec6& demand_wrench, double cap);

// How far the set can push along `wrench`: the largest lambda with lambda * wrench attainable,
//
//   lambda* = max lambda  s.t.  M s = lambda wrench,  0 <= s <= 1,
//
// the inverse of the attainable set's gauge (Durham's direct allocation scales a demand by it).
// The least peak on-time that realises an attainable wrench is 1 / lambda* (u = s / lambda*).
// Solved by the allocator's simplex with the wrench as one more column; infinity for a zero wrench.
struct AttainableScale {
  double scale = 0.0;                         // [-] lambda*, 0 when invalid
  AllocationTon ton = AllocationTon::Zero();  // [-] s at the optimum, compact order
  int iterations = 0;
  bool converged = false;  // false: iteration cap or invalid input (non-finite, thrusters not 1..32)
};
AttainableScale attainable_scale(const AllocationParams& params, const Vec6& wrench);

// Optimal bases of earlier attainable demands of one configuration matrix, tried before a solve
// (thruster_allocation.cpp, "Warm start"): a controller's demands change slowly, so the optimal
// basis of (P) often stays the same and the answer is one 6x6 product instead of a simplex.
struct AllocationWarmStart {
  static constexpr int kSlots = 4;
  struct Slot {
    bool valid = false;
    std::array<int, 6> basis{};  // on-time index basic in each row (all six basic are on-times)
    model::ThrusterMask upper = 0;  // bit i: nonbasic on-time i is at its upper bound 1
    Mat6 binv = Mat6::Zero();    // inverse of the scaled basis matrix
  };
  std::array<Slot, kSlots> slots{};
  int last_hit = 0;                                  // slot tried first
  int next_free = 0;                                 // slot replaced next (round robin)
  model::ConfigMatrix config = model::ConfigMatrix::Zero();  // the problem the slots belong to
  int thrusters = 0;
  Vec6 error_weights = Vec6::Zero();
  bool valid = false;                                // the problem's own check (finite, weights > 0)
  model::ConfigMatrix config_scaled = model::ConfigMatrix::Zero();  // config / wrench_scale, formed once
  model::ConfigMatrix config_scaled_abs = model::ConfigMatrix::Zero();  // |config_scaled|, the same
  double wrench_scale = 1.0;                         // [N or N m] power of two: the scaling is exact
  std::int64_t hits = 0;                             // answers from a slot (statistics)
  std::int64_t solves = 0;                           // answers from the simplex
};

// The same answer as allocate_thrusters (the same optimum of (P) or (E); where (P) has several
// optimal on-time vectors, possibly another of them), from a cached basis when one is still
// optimal; `warm` learns the optimal basis of every attainable demand it had to solve.
AllocationResult allocate_thrusters(const AllocationParams& params, const Vec6& demand_wrench,
                                    AllocationWarmStart& warm);

}  // namespace chaser::flight
