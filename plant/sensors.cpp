#include "plant/sensors.hpp"

#include <algorithm>
#include <cmath>

#include "core/rotation.hpp"

namespace chaser::plant {
namespace {

int delay_in_periods(double delay_s, TimeNs period_ns) {
  const double periods = std::round(delay_s * static_cast<double>(kNsPerSecond) / static_cast<double>(period_ns));
  return static_cast<int>(std::clamp(periods, 0.0, static_cast<double>(kMaxSensorDelayPeriods)));
}

// Pushes the new sample and returns the one delay_periods old (or the oldest held).
template <typename Sample>
const Sample& push_and_deliver(DelayLine<Sample>& line, const Sample& sample) {
  const int size = static_cast<int>(line.ring.size());
  line.newest = (line.newest + 1) % size;
  line.ring[static_cast<std::size_t>(line.newest)] = sample;
  line.filled = std::min(line.filled + 1, size);
  const int age = std::min(line.delay_periods, line.filled - 1);
  return line.ring[static_cast<std::size_t>((line.newest - age + size) % size)];
}

Vec3 white_noise(RandomStream& stream, double sigma) {
  const double x = stream.normal(), y = stream.normal(), z = stream.normal();
  return sigma * Vec3(x, y, z);  // draws in x, y, z order: evaluation order is fixed
}

// q_inertial_from_measured = q_inertial_from_body * q_body_from_measured, the error a body-frame
// rotation vector. A zero error returns the truth bit for bit.
Quat perturbed_attitude(const Quat& q_inertial_from_body, const Vec3& error_body_rad) {
  if (error_body_rad.isZero(0.0)) return q_inertial_from_body;
  return (q_inertial_from_body * quat_from_rotation_vector(error_body_rad)).normalized();
}

}  // namespace

SensorNoise make_sensor_noise(std::uint64_t run_seed) {
  return SensorNoise{RandomStream(run_seed, "sensors/lidar"), RandomStream(run_seed, "sensors/star_tracker"),
                     RandomStream(run_seed, "sensors/gyro")};
}

SensorState make_sensor_state(const model::SensorParams& params, TimeNs period_ns) {
  SensorState state;
  state.lidar_r_lvlh_m.delay_periods = delay_in_periods(params.lidar.delay_s, period_ns);
  state.star_q_inertial_from_body.delay_periods = delay_in_periods(params.star_tracker.delay_s, period_ns);
  state.gyro_omega_body_radps.delay_periods = delay_in_periods(params.gyro.delay_s, period_ns);
  return state;
}

model::SensorMeasurements sample_sensors(const model::SensorParams& params, SensorState& state, TimeNs t,
                                         const Vec3& r_lvlh_m, const Quat& q_inertial_from_body,
                                         const Vec3& omega_body_radps, SensorNoise& noise, bool target_in_view) {
  const Vec3 r_meas = r_lvlh_m + params.lidar.bias_m + white_noise(noise.lidar, params.lidar.noise_sigma_m);
  const Vec3 attitude_error =
      params.star_tracker.bias_rad + white_noise(noise.star_tracker, params.star_tracker.noise_sigma_rad);
  const Quat q_meas = perturbed_attitude(q_inertial_from_body, attitude_error);
  const Vec3 omega_meas =
      omega_body_radps + params.gyro.bias_radps + white_noise(noise.gyro, params.gyro.noise_sigma_radps);

  model::SensorMeasurements out;
  out.t = t;
  const LidarSample& lidar =
      push_and_deliver(state.lidar_r_lvlh_m, target_in_view ? LidarSample{r_meas, true} : LidarSample{Vec3::Zero(), false});
  out.r_lvlh_m = lidar.r_lvlh_m;
  out.lidar_valid = lidar.valid;
  out.q_inertial_from_body = push_and_deliver(state.star_q_inertial_from_body, q_meas);
  out.omega_body_radps = push_and_deliver(state.gyro_omega_body_radps, omega_meas);
  return out;
}

model::TargetPoseMeasurement sample_target_pose(const model::TargetPoseSensorParams& params, SensorState& state,
                                                double t_s, const Quat& q_inertial_from_body,
                                                const Quat& q_inertial_from_target, RandomStream& noise,
                                                bool target_in_view) {
  return sample_with_latency(params.period_s, params.latency_s, t_s, state.target_pose_next_s,
                             state.target_pose_pending, [&](double taken_s) {
                               const Vec3 error(noise.normal(), noise.normal(), noise.normal());
                               model::TargetPoseMeasurement m;
                               m.valid = target_in_view;
                               m.taken_s = taken_s;
                               m.q_body_from_target = (q_inertial_from_body.conjugate() * q_inertial_from_target *
                                                       quat_from_rotation_vector(params.attitude_noise_rad * error))
                                                          .normalized();
                               return m;
                             });
}

Vec3 line_of_sight_body_m(const Vec3& r_lvlh_m, const Quat& q_inertial_from_lvlh, const Quat& q_inertial_from_body) {
  return q_inertial_from_body.conjugate() * (q_inertial_from_lvlh * (-r_lvlh_m));
}

bool sees_target(double fov_half_angle_rad, double range_max_m, const Vec3& line_of_sight_body_m) {
  const double range_m = line_of_sight_body_m.norm();
  return range_m <= range_max_m && line_of_sight_body_m.x() >= range_m * std::cos(fov_half_angle_rad);
}

}  // namespace chaser::plant
