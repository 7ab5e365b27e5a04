#include "flight/modulation.hpp"

#include "model/recovery.hpp"
#include "model/thruster_geometry.hpp"

namespace chaser::flight {
namespace {

// Largest wrench per axis a set of thrusters can produce in either direction: the larger of the
// sums of the positive and of the negative entries of each row of M (all helpful thrusters fully
// open). Zero columns (the capacity's unused ones) add nothing.
Vec6 set_authority(const model::ConfigMatrix& m) {
  return m.cwiseMax(0.0).rowwise().sum().cwiseMax((-m).cwiseMax(0.0).rowwise().sum());
}

// The largest authority of the sets the vehicle may fly: the starting active set and each set a
// recovery can switch to.
Vec6 largest_authority(const model::Scenario& s) {
  Vec6 authority = Vec6::Zero();
  for (const model::ReachableConfiguration& r : model::reachable_configurations(s.thrusters, s.fdi.recovery))
    authority = authority.cwiseMax(
        set_authority(model::configuration_matrix(s.thrusters, r.configuration.active, s.chaser.com_body_m)));
  return authority;
}

}  // namespace

TmuParams make_tmu_params(const model::Scenario& s) {
  TmuParams params;
  params.period_s = s.control_period_s;
  params.threshold << Vec3::Constant(s.control.tmu_force_threshold_Ns),
      Vec3::Constant(s.control.tmu_torque_threshold_Nms);
  const Vec6 windup = s.control.tmu_windup_periods * s.control_period_s * largest_authority(s);
  params.limit = windup.cwiseMax(2.0 * params.threshold);
  return params;
}

Vec6 tmu_release(const TmuParams& params, TmuState& state, const Vec6& demand_wrench) {
  state.accumulated += demand_wrench * params.period_s;
  state.accumulated = state.accumulated.cwiseMax(-params.limit).cwiseMin(params.limit);
  const bool fire = (state.accumulated.cwiseAbs().array() >= params.threshold.array()).any();
  return fire ? Vec6(state.accumulated / params.period_s) : Vec6::Zero();
}

void tmu_account(const TmuParams& params, TmuState& state, const Vec6& realised_wrench) {
  state.accumulated -= realised_wrench * params.period_s;
}

}  // namespace chaser::flight
