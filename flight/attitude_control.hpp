#pragma once
// Attitude controller K_att (Fonod 2015, Fig. 4): discrete LQR on the rigid body linearised about
// the guidance attitude, plus the feed-forward that cancels the nonlinear rigid-body terms.
//
//   theta     = attitude_error_body(q_ref, q_hat)          rotation reference -> body, body axes
//   omega_r   = q_err^-1 * omega_ref                       reference rate seen in body axes
//   C_d = omega_hat x (I omega_hat) - I (omega_hat x omega_r) - K [theta; omega_hat - omega_r]
//
// Euler's equation I omega' = C - omega x I omega: the first term cancels the gyroscopic torque, the
// second the apparent change of the reference rate seen from the turning body, so the error obeys
// the double integrator the gain was designed on (theta' = delta_omega, I delta_omega' = C_fb).
// K is the LQR gain of that model, ZOH-discretised with the nominal inertia, state weight
// diag(q_angle I, q_rate I), input weight r_torque I (model::ControlParams).
#include "core/types.hpp"
#include "flight/guidance.hpp"
#include "core/linear_models.hpp"
#include "flight/navigation.hpp"
#include "model/scenario.hpp"

namespace chaser::flight {

struct AttitudeControlParams {
  Mat36 K = Mat36::Zero();                 // [N m/rad | N m s/rad] gain on [theta; delta_omega]
  Mat3 inertia_kgm2 = Mat3::Identity();    // [kg m^2] nominal inertia
  bool design_converged = false;           // the LQR Riccati solver converged
};

AttitudeControlParams design_attitude_control(const model::ControlParams& weights, const Mat3& inertia_kgm2,
                                              double period_s);
AttitudeControlParams make_attitude_control(const model::Scenario& scenario);

// The attitude error of the header: theta (rotation reference -> body, body axes) and the
// reference rate seen in body axes, omega_r.
struct AttitudeError {
  Vec3 theta_rad = Vec3::Zero();
  Vec3 omega_ref_body_radps = Vec3::Zero();
};
AttitudeError attitude_error(const NavEstimate& nav, const GuidanceRef& ref);

// The computed torque of the header, omega x (I omega) - I (omega x omega_r) [N m]: with it, the
// error obeys the double integrator I delta_omega' = C_fb.
Vec3 attitude_feedforward(const Mat3& inertia_kgm2, const Vec3& omega_body_radps, const Vec3& omega_ref_body_radps);

// Desired torque C_d in body axes [N m].
Vec3 attitude_control(const AttitudeControlParams& params, const NavEstimate& nav, const GuidanceRef& ref);

}  // namespace chaser::flight
