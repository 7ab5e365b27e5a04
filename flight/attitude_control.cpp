#include "flight/attitude_control.hpp"

#include "core/riccati.hpp"
#include "core/rotation.hpp"

namespace chaser::flight {

AttitudeControlParams design_attitude_control(const model::ControlParams& weights, const Mat3& inertia_kgm2,
                                              double period_s) {
  const DiscreteLinear6 model = discrete_attitude(inertia_kgm2, period_s);
  Vec6 q;
  q << Vec3::Constant(weights.attitude_q_angle), Vec3::Constant(weights.attitude_q_rate);
  const LqrDesign lqr = dlqr(model.Ad, model.Bd, Mat6(q.asDiagonal()), weights.attitude_r_torque * Mat3::Identity());
  AttitudeControlParams params;
  params.K = lqr.K;
  params.inertia_kgm2 = inertia_kgm2;
  params.design_converged = lqr.converged;
  return params;
}

AttitudeControlParams make_attitude_control(const model::Scenario& scenario) {
  return design_attitude_control(scenario.control, scenario.chaser.inertia_kgm2, scenario.control_period_s);
}

Vec3 attitude_control(const AttitudeControlParams& params, const NavEstimate& nav, const GuidanceRef& ref) {
  const Quat q_ref_from_body = ref.q_inertial_from_body.conjugate() * nav.q_inertial_from_body;
  const Vec3 theta = rotation_vector_from_quat(q_ref_from_body);
  const Vec3 omega_ref_in_body = q_ref_from_body.conjugate() * ref.omega_body_radps;
  const Vec3& omega = nav.omega_body_radps;
  Vec6 error;
  error << theta, omega - omega_ref_in_body;
  const Mat3& inertia = params.inertia_kgm2;
  const Vec3 feedforward = omega.cross(inertia * omega) - inertia * omega.cross(omega_ref_in_body);
  return feedforward - params.K * error;
}

}  // namespace chaser::flight
