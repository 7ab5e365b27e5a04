#pragma once
// The flight software's estimate of a tumbling target's attitude and rate (the
// synchronisation phase flies the target's motion as feed-forward, and the flight software does
// not know the truth). A multiplicative extended Kalman filter (Markley & Crassidis, "Fundamentals
// of Spacecraft Attitude Determination and Control", 2014, sec. 6.2) on
//
//   state: q_inertial_from_target (the reference, kept unit) and omega [rad/s, target axes];
//   error: delta_theta (3, target axes: q = q_hat (x) dq(delta_theta)) and delta_omega (3);
//   model: torque-free Euler, I omega' = -omega x I omega, with the target's nominal inertia (the
//          unmodelled torques, gravity gradient first, as a white torque noise);
//   measurement: the target's attitude, q_inertial_from_target = q_inertial_from_chaser (star
//          tracker) (x) q_chaser_from_target (a LIDAR-like pose sensor), noise per axis.
//
// Latency: each measurement carries the time it was taken; the filter holds its state at the last
// measurement's time and predict() carries it to any later time (the flight software's now), so a
// measurement's delay costs no more than its propagation. Out-of-order measurements are refused.
// Not estimated here: the inertia ratios, which the Euler model then
// takes from the scenario; an error in them shows as torque noise.
#include "core/types.hpp"

namespace chaser::flight {

struct TargetEstimatorParams {
  Mat3 inertia_kgm2 = Mat3::Identity();  // [kg m^2] the target's nominal inertia, target axes
  double torque_noise_Nm = 0.01;         // [N m] 1-sigma white torque density per axis, ~ per sqrt(s)
  double attitude_noise_rad = 0.0175;    // [rad] 1-sigma per axis of one attitude measurement
  double initial_rate_sigma_radps = 0.05;  // [rad/s] 1-sigma per axis of the first rate guess
  int substeps_per_second = 20;          // RK4 steps of the Euler model per simulated second (>= 1)
};

// What the filter believes at a time: attitude, rate and the rate's derivative (Euler), with the
// 1-sigma bounds of the first two from the covariance at the last update (not grown to the time:
// over the <= 0.43 s between a pose and the next, by 1-2 % of the attitude's; they feed nothing but
// telemetry).
struct TargetEstimate {
  double t_s = 0.0;
  Quat q_inertial_from_target = Quat::Identity();
  Vec3 omega_target_radps = Vec3::Zero();      // [rad/s] target axes
  Vec3 omega_dot_target_radps2 = Vec3::Zero();  // [rad/s^2] target axes, from Euler's equations
  Vec3 attitude_sigma_rad = Vec3::Zero();
  Vec3 rate_sigma_radps = Vec3::Zero();
};

class TargetEstimator {
 public:
  explicit TargetEstimator(const TargetEstimatorParams& params);

  // The first measurement initialises the attitude (rate 0 with initial_rate_sigma_radps); later
  // ones propagate to t_s and update. Returns false (and changes nothing) for a measurement older
  // than the filter's time or a non-finite one.
  bool update(double t_s, const Quat& q_inertial_from_target_measured);

  bool initialised() const { return initialised_; }
  // The estimate carried from the filter's time to t_s >= it (without changing the filter).
  TargetEstimate predict(double t_s) const;
  // Normalised estimation error squared of the last update's innovation (for consistency checks:
  // chi-square with 3 degrees of freedom when the filter is consistent).
  double last_innovation_nis() const { return last_nis_; }

 private:
  using Mat6x6 = Eigen::Matrix<double, 6, 6>;
  void propagate(double dt_s, Quat& q, Vec3& omega, Mat6x6* covariance) const;

  TargetEstimatorParams params_;
  Mat3 inertia_inv_ = Mat3::Identity();
  bool initialised_ = false;
  double t_s_ = 0.0;
  Quat q_ = Quat::Identity();
  Vec3 omega_ = Vec3::Zero();
  Mat6x6 p_ = Mat6x6::Identity();
  double last_nis_ = 0.0;
};

}  // namespace chaser::flight
