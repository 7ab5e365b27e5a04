#include "flight/attitude_filter.hpp"

#include "core/rotation.hpp"

namespace chaser::flight {

void propagate_attitude(const AttitudeFilterParams& params, AttitudeFilterState& state, const Vec3& gyro_radps) {
  // Trapezoidal mean of the two samples bounding the period: second-order accurate for a smooth rate.
  const Vec3 omega = 0.5 * (state.gyro_prev_radps + gyro_radps) - state.gyro_bias_radps;
  state.q_inertial_from_body = (state.q_inertial_from_body * quat_from_rotation_vector(omega * params.period_s))
                                   .normalized();
  state.gyro_prev_radps = gyro_radps;
}

void correct_attitude(const AttitudeFilterParams& params, AttitudeFilterState& state,
                      const Quat& q_star_tracker_inertial_from_body) {
  const Vec3 error = attitude_error_body(state.q_inertial_from_body, q_star_tracker_inertial_from_body);
  state.q_inertial_from_body =
      (state.q_inertial_from_body * quat_from_rotation_vector(params.attitude_gain * error)).normalized();
  state.gyro_bias_radps -= params.gyro_bias_gain * error;
}

}  // namespace chaser::flight
