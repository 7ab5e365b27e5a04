#pragma once
// Thrust allocation with a choice of norm, over any thruster set (COMRADE 2018, sec. 6.3,
// names p = 1, 2 and infinity but prints no problem: this formulation is ours, docs/gnc.md).
//
// Lexicographically: first the wrench, then the on-times.
//  1. The wrench realised: the demand when attainable; otherwise the best effort of
//     allocate_thrusters, the least weighted error sum_j w_j |(M ton - w_d)_j| (problem (E) of
//     thruster_allocation.hpp). The same for every p, so a lost thruster's authority is shared
//     out identically whatever the norm.
//  2. Among the on-times 0 <= ton <= 1 realising that wrench, the least ||ton||_p:
//     p = 1: least propellant, problem (P): allocate_thrusters itself, unchanged;
//     p = 2: least energy, the strictly convex QP (Q) of least_energy_allocation.hpp, from the
//            p = 1 answer (a feasible vertex) by the primal active-set method;
//     p = infinity: least peak, t* = 1 / lambda* with lambda* = attainable_scale of the wrench (an
//            LP), then, since the least-peak on-times form a polytope, the least propellant among
//            them: (P) with every on-time capped at t* (feasible to the simplex's tolerances: were
//            it not, the scale LP's own least-peak on-times are the answer).
// A thruster declared faulty is out of the active set (its column is not in M): COMRADE's
// u_max = 0 for it.
#include "core/types.hpp"
#include "flight/thruster_allocation.hpp"
#include "model/gnc.hpp"

namespace chaser::flight {

// Same contract as allocate_thrusters (never throws, allocation-free, bounded in time); `warm`
// serves the first stage. converged = false when a stage did not converge: the on-times are then
// those of the last stage that did (still within [0, 1] and realising the wrench).
AllocationResult allocate_thrusters(const AllocationParams& params, const Vec6& demand_wrench,
                                    model::AllocationNorm norm, AllocationWarmStart& warm);

}  // namespace chaser::flight
