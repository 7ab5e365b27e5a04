#include "flight/navigation.hpp"

#include <stdexcept>

namespace chaser::flight {

NavParams make_nav_params(const model::Scenario& s) {
  NavParams params;
  params.translation = design_translation_filter(s.orbit.mean_motion_radps(), s.control_period_s, s.chaser.mass_kg,
                                                 s.navigation.position_process_noise_mps2,
                                                 s.sensors.lidar.noise_sigma_m);
  params.attitude = AttitudeFilterParams{s.control_period_s, s.navigation.attitude_gain, s.navigation.gyro_bias_gain};
  return params;
}

NavState init_nav(const NavParams& /*params*/, const model::SensorMeasurements& first) {
  if (!first.lidar_valid)
    throw std::runtime_error(
        "the LIDAR does not see the target at the run's start (outside sensors.lidar's fov_half_angle_deg or "
        "range_max_m): the navigation has no position to start from; point the chaser's +x at the target");
  NavState state;
  state.translation.x << first.r_lvlh_m, Vec3::Zero();
  state.attitude.q_inertial_from_body = first.q_inertial_from_body.normalized();
  state.attitude.gyro_prev_radps = first.omega_body_radps;
  state.t_last = first.t;
  return state;
}

NavEstimate nav_estimate(const NavState& state) {
  return NavEstimate{state.translation.x.head<3>(), state.translation.x.tail<3>(),
                     state.attitude.q_inertial_from_body,
                     state.attitude.gyro_prev_radps - state.attitude.gyro_bias_radps};
}

NavEstimate step_nav(const NavParams& params, NavState& state, const model::SensorMeasurements& meas,
                     const Vec3& force_cmd_lvlh_N_prev) {
  if (meas.t == state.t_last) return nav_estimate(state);
  predict_translation(params.translation, state.translation, force_cmd_lvlh_N_prev);
  // A LIDAR gap (the target outside its view): the filter propagates on the commanded force alone.
  if (meas.lidar_valid) correct_translation(params.translation, state.translation, meas.r_lvlh_m);
  propagate_attitude(params.attitude, state.attitude, meas.omega_body_radps);
  correct_attitude(params.attitude, state.attitude, meas.q_inertial_from_body);
  state.t_last = meas.t;
  return nav_estimate(state);
}

}  // namespace chaser::flight
