#include "flight/norm_allocation.hpp"

#include <algorithm>
#include <cmath>

#include "flight/least_energy_allocation.hpp"

namespace chaser::flight {
namespace {

// The result's figures for on-times `ton` against the demand (the first stage's flags kept).
void refill(const AllocationParams& params, const Vec6& demand_wrench, const AllocationTon& ton,
            AllocationResult& result) {
  result.ton = ton;
  const int n = params.thrusters;
  result.propellant = ton.head(n).sum();
  result.residual = params.config.leftCols(n) * ton.head(n) - demand_wrench;
  result.weighted_error = params.error_weights.cwiseProduct(result.residual.cwiseAbs()).sum();
}

}  // namespace

AllocationResult allocate_thrusters(const AllocationParams& params, const Vec6& demand_wrench,
                                    model::AllocationNorm norm, AllocationWarmStart& warm) {
  AllocationResult result = allocate_thrusters(params, demand_wrench, warm);
  if (norm == model::AllocationNorm::kOne || !result.converged) return result;
  const int n = params.thrusters;
  // The wrench of stage 1: the demand itself when attainable (M ton equals it to rounding).
  const Vec6 wrench =
      result.feasible ? demand_wrench : Vec6(params.config.leftCols(n) * result.ton.head(n));
  if ((wrench.array() == 0.0).all()) return result;  // ton = 0 is the only answer for every p

  if (norm == model::AllocationNorm::kTwo) {
    const LeastEnergyResult energy = least_energy_on_times(params, wrench, result.ton);
    result.iterations += energy.iterations;
    if (!energy.converged) {
      result.converged = false;
      return result;
    }
    refill(params, demand_wrench, energy.ton, result);
    return result;
  }

  const AttainableScale scale = attainable_scale(params, wrench);
  result.iterations += scale.iterations;
  if (!scale.converged || !(scale.scale > 0.0) || !std::isfinite(scale.scale)) {
    result.converged = false;
    return result;
  }
  const double peak = std::min(1.0, 1.0 / scale.scale);
  const AllocationResult capped =
      allocate_thrusters_capped(params, wrench, peak);
  result.iterations += capped.iterations;
  if (capped.feasible && capped.converged) {
    refill(params, demand_wrench, capped.ton, result);
  } else {  // the least-peak on-times of the scale LP itself, without the propellant tie-break (not
            // seen in the tests' 2,850 demands: the capped LP is solved at exactly t*)
    AllocationTon ton = AllocationTon::Zero();
    ton.head(n) = (scale.ton.head(n) / scale.scale).cwiseMin(1.0);
    refill(params, demand_wrench, ton, result);
  }
  return result;
}

}  // namespace chaser::flight
