#pragma once
// Sensors on the plant side: they see the truth and add their errors.
//   LIDAR:        r_meas = r_lvlh + bias + noise                       (per axis, LVLH)
//   star tracker: q_meas = q_inertial_from_body * exp(bias + noise)   (small body-frame rotation)
//   gyro:         omega_meas = omega_body + bias + noise                (per axis, body)
// Noise is white Gaussian, drawn when the sample is taken. Each sensor delivers the sample taken
// delay_s earlier (delay_s a whole number of control periods, at most kMaxSensorDelayPeriods),
// through a fixed ring buffer. Until the ring holds that many samples, the oldest sample available
// is delivered (at the first call: the one just taken).
#include <array>
#include <cstdint>

#include "core/random.hpp"
#include "core/time.hpp"
#include "core/types.hpp"
#include "model/messages.hpp"
#include "model/sensors.hpp"

namespace chaser::plant {

using model::kMaxSensorDelayPeriods;

// The three named streams, constructed by the caller (see make_sensor_noise).
struct SensorNoise {
  RandomStream lidar;         // "sensors/lidar"
  RandomStream star_tracker;  // "sensors/star_tracker"
  RandomStream gyro;          // "sensors/gyro"
};

// The streams of a run, with their standard names.
SensorNoise make_sensor_noise(std::uint64_t run_seed);

// A delay line of samples taken once per control period.
template <typename Sample>
struct DelayLine {
  std::array<Sample, kMaxSensorDelayPeriods + 1> ring{};
  int newest = -1;         // index of the newest sample, -1 when empty
  int filled = 0;          // samples held, up to ring.size()
  int delay_periods = 0;   // [periods] age of the delivered sample
};

// A LIDAR sample as taken: the measured position, or a gap (valid false, r zero).
struct LidarSample {
  Vec3 r_lvlh_m = Vec3::Zero();  // [m]
  bool valid = true;
};

struct SensorState {
  DelayLine<LidarSample> lidar_r_lvlh_m;
  DelayLine<Quat> star_q_inertial_from_body;
  DelayLine<Vec3> gyro_omega_body_radps;    // [rad/s]
  // The target pose sensor: its next sample's time and the sample awaiting delivery.
  double target_pose_next_s = 0.0;         // [s]
  model::TargetPoseMeasurement target_pose_pending;  // valid: taken, not yet delivered
  // The arm camera: the same for its samples.
  double arm_camera_next_s = 0.0;          // [s]
  model::RelativePoseMeasurement arm_camera_pending;
};

// A sensor whose samples are taken at control periods every period_s and delivered latency_s later
// (the target pose sensor, the arm camera): at run time t_s the pending sample is delivered if its
// latency has passed (before a new one replaces it: with period_s one control period and a
// latency, each sample goes out as the next is taken), then a sample is taken if its time has come
// (take(t_s) returns it, `valid` false when the sensor sees nothing), and a sample taken now with no
// latency goes out now too. Sample times are sums of period_s, so they carry a small tolerance: a
// sample due at 1/3 s is taken at the control period starting then, not one period late by rounding.
template <class Sample, class Take>
Sample sample_with_latency(double period_s, double latency_s, double t_s, double& next_s, Sample& pending, Take take) {
  constexpr double kTimeTolS = 1e-9;
  Sample out;
  const auto deliver = [&] {
    if (pending.valid && t_s + kTimeTolS >= pending.taken_s + latency_s) {
      out = pending;
      pending.valid = false;
    }
  };
  deliver();
  if (t_s + kTimeTolS >= next_s) {
    Sample taken = take(t_s);
    if (taken.valid) pending = taken;
    while (next_s <= t_s + kTimeTolS) next_s += period_s;
  }
  if (!out.valid) deliver();
  return out;
}

// The target pose sensor (model::TargetPoseSensorParams) at run time t_s, called once per control
// period after sample_sensors: takes a sample of the truth when its period has come (the target's
// attitude in the chaser's body axes, turned by a random small rotation of the noise), and returns
// the pending one once its latency has passed (invalid otherwise). Allocation-free.
// target_in_view: the LIDAR sees the target and it is within the pose sensor's range; a sample
// due while it is not is not taken (its noise drawn all the same).
model::TargetPoseMeasurement sample_target_pose(const model::TargetPoseSensorParams& params, SensorState& state,
                                                double t_s, const Quat& q_inertial_from_body,
                                                const Quat& q_inertial_from_target, RandomStream& noise,
                                                bool target_in_view = true);

// Delays in periods: round(delay_s / T), clamped to [0, kMaxSensorDelayPeriods] (the scenario
// validator checks both the range and that the delay is a whole number of periods).
SensorState make_sensor_state(const model::SensorParams& params, TimeNs period_ns);

// Takes this period's samples of the truth at time t and returns the delivered (delayed)
// measurements, stamped with t. Call once per control period. Allocation-free.
// target_in_view: whether the LIDAR sees the target now (lidar_sees_target); the noise is drawn
// either way, so that a gap does not shift the streams.
model::SensorMeasurements sample_sensors(const model::SensorParams& params, SensorState& state, TimeNs t,
                                         const Vec3& r_lvlh_m, const Quat& q_inertial_from_body,
                                         const Vec3& omega_body_radps, SensorNoise& noise, bool target_in_view = true);

// The target's CoM from the chaser's CoM in the chaser's body axes [m] (the LIDAR's line of sight).
Vec3 line_of_sight_body_m(const Vec3& r_lvlh_m, const Quat& q_inertial_from_lvlh, const Quat& q_inertial_from_body);

// Whether the target is inside the cone about the body's +x and within range_max_m.
bool sees_target(double fov_half_angle_rad, double range_max_m, const Vec3& line_of_sight_body_m);

}  // namespace chaser::plant
