#pragma once
// The least-energy distribution of an attainable wrench over a thruster set (the p = 2
// allocation of flight/norm_allocation.hpp):
//
//   min  1/2 ||ton||_2^2   s.t.   M ton = wrench,   0 <= ton <= 1.                    (Q)
//
// A strictly convex quadratic program: its minimiser is unique, and it spreads the wrench over
// more thrusters, each firing shorter, than the least-propellant vertex of (P).
// Solved by the primal active-set method (Nocedal & Wright, Numerical Optimization, 2nd ed.,
// Algorithm 16.3) from a feasible start, e.g. the least-propellant on-times: the working set is
// the on-times held at a bound; on the others the equality-constrained problem has the closed form
// ton_F = M_F^T z with (M_F M_F^T) z = wrench - M_U 1 (the minimum-norm solution), and z is minus
// the multiplier of the wrench constraint, so a bound's multiplier is m_i^T z (at 1: -(1 + ...)).
// Fixed-size, allocation-free, deterministic; bounded in time (iteration cap).
#include "core/types.hpp"
#include "flight/thruster_allocation.hpp"

namespace chaser::flight {

struct LeastEnergyResult {
  AllocationTon ton = AllocationTon::Zero();  // [-] compact order, [0, thrusters) used
  int iterations = 0;                         // active-set changes and steps
  bool converged = false;  // false: iteration cap, an infeasible start or invalid input; ton is
                           // then the start (feasible, not least-energy)
};

// `start`: on-times in [0, 1] with M start = wrench (to rounding), e.g. allocate_thrusters' answer
// for an attainable wrench. Uses params.config and params.thrusters (the weights play no part).
LeastEnergyResult least_energy_on_times(const AllocationParams& params, const Vec6& wrench, const AllocationTon& start);

}  // namespace chaser::flight
