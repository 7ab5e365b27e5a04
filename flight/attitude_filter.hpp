#pragma once
// Attitude navigation: multiplicative complementary filter with gyro-bias estimation.
//
//   propagate: omega_hat = (gyro(k-1) + gyro(k)) / 2 - b_hat,  q- = q+ * exp(omega_hat T)
//   correct:   e = attitude_error_body(q-, q_star_tracker)  (rotation estimate -> measurement)
//              q+ = q- * exp(k_q e),   b_hat <- b_hat - k_b e
//
// Per axis the error pair (delta = angle error, beta = bias error) obeys
//   [delta; beta]+ = [[1 - k_q, -(1 - k_q) T], [k_b, 1 - k_b T]] [delta; beta],
// characteristic polynomial z^2 - (2 - k_q - k_b T) z + (1 - k_q): for k_b T << k_q the poles are
// z ~ 1 - k_q (attitude, time constant T / k_q) and z ~ 1 - k_b T / k_q (bias, time constant
// k_q / k_b). The gains are navigation.attitude_gain = k_q and navigation.gyro_bias_gain = k_b.
#include "core/types.hpp"

namespace chaser::flight {

struct AttitudeFilterParams {
  double period_s = 0.1;          // [s] T
  double attitude_gain = 0.1;     // [-] k_q, fraction of the star-tracker error removed per period
  double gyro_bias_gain = 0.001;  // [1/s] k_b
};

struct AttitudeFilterState {
  Quat q_inertial_from_body = Quat::Identity();  // estimate
  Vec3 gyro_bias_radps = Vec3::Zero();           // [rad/s] estimated gyro bias
  Vec3 gyro_prev_radps = Vec3::Zero();           // [rad/s] last raw gyro sample
};

void propagate_attitude(const AttitudeFilterParams& params, AttitudeFilterState& state, const Vec3& gyro_radps);
void correct_attitude(const AttitudeFilterParams& params, AttitudeFilterState& state,
                      const Quat& q_star_tracker_inertial_from_body);

}  // namespace chaser::flight
