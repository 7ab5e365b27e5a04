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

AttitudeError attitude_error(const NavEstimate& nav, const GuidanceRef& ref) {
  const Quat q_ref_from_body = ref.q_inertial_from_body.conjugate() * nav.q_inertial_from_body;
  return {.theta_rad = rotation_vector_from_quat(q_ref_from_body),
          .omega_ref_body_radps = q_ref_from_body.conjugate() * ref.omega_body_radps};
}

Vec3 attitude_feedforward(const Mat3& inertia_kgm2, const Vec3& omega_body_radps, const Vec3& omega_ref_body_radps) {
  return omega_body_radps.cross(inertia_kgm2 * omega_body_radps) -
         inertia_kgm2 * omega_body_radps.cross(omega_ref_body_radps);
}

Vec3 attitude_control(const AttitudeControlParams& params, const NavEstimate& nav, const GuidanceRef& ref) {
  const AttitudeError att = attitude_error(nav, ref);
  const Vec3& omega = nav.omega_body_radps;
  Vec6 error;
  error << att.theta_rad, omega - att.omega_ref_body_radps;
  return attitude_feedforward(params.inertia_kgm2, omega, att.omega_ref_body_radps) - params.K * error;
}

}  // namespace chaser::flight
