#include "flight/position_control.hpp"

#include "core/riccati.hpp"

namespace chaser::flight {

PositionControlParams design_position_control(const model::ControlParams& weights, double mass_kg,
                                              double mean_motion_radps, double period_s) {
  const DiscreteLinear6 model = discrete_hcw(mean_motion_radps, period_s);
  Vec6 q;
  q << Vec3::Constant(weights.position_q_pos), Vec3::Constant(weights.position_q_vel);
  const Mat63 b_force = model.Bd / mass_kg;  // input in newtons, so r_force weighs N^2
  const LqrDesign lqr = dlqr(model.Ad, b_force, Mat6(q.asDiagonal()),
                             weights.position_r_force * Mat3::Identity());
  PositionControlParams params;
  params.K = lqr.K;
  params.mass_kg = mass_kg;
  params.mean_motion_radps = mean_motion_radps;
  params.period_s = period_s;
  params.design_converged = lqr.converged;
  return params;
}

PositionControlParams make_position_control(const model::Scenario& scenario) {
  return design_position_control(scenario.control, scenario.chaser.mass_kg, scenario.orbit.mean_motion_radps(),
                                 scenario.control_period_s);
}

PositionControlParams with_mass(const PositionControlParams& params, double mass_kg) {
  PositionControlParams out = params;
  out.K *= mass_kg / params.mass_kg;
  out.mass_kg = mass_kg;
  return out;
}

Vec3 position_feedforward(const PositionControlParams& params, const GuidanceRef& ref) {
  const double half = 0.5 * params.period_s;  // mid-period values, to first order in T/2
  const Vec3 r_mid = ref.r_lvlh_m + half * ref.v_lvlh_mps;
  const Vec3 v_mid = ref.v_lvlh_mps + half * ref.a_lvlh_mps2;
  const Vec3 a_mid = ref.a_lvlh_mps2 + half * ref.j_lvlh_mps3;
  return params.mass_kg * (a_mid - hcw_acceleration(params.mean_motion_radps, r_mid, v_mid));
}

Vec3 position_control(const PositionControlParams& params, const NavEstimate& nav, const GuidanceRef& ref) {
  Vec6 error;
  error << nav.r_lvlh_m - ref.r_lvlh_m, nav.v_lvlh_mps - ref.v_lvlh_mps;
  return position_feedforward(params, ref) - params.K * error;
}

}  // namespace chaser::flight
