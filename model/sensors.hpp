#pragma once
// Sensor specifications. Each sensor adds a constant bias and white Gaussian noise, and delivers its
// sample a whole number of control periods late (delay_s is validated to be a multiple of T).
#include <optional>

#include "core/types.hpp"
#include "model/fdi.hpp"

namespace chaser::model {

// Longest sensor delay in control periods: the plant's delay lines have this many slots and the
// scenario loader rejects longer delays.
inline constexpr int kMaxSensorDelayPeriods = 32;

// Relative position of the chaser from the target, MSR LVLH axes. It sees the target only while the
// target's CoM is inside its cone about the body's +x and within its range: a sample taken then is
// valid; one taken outside is a gap (model::SensorMeasurements::lidar_valid false), never a value.
struct LidarParams {
  double noise_sigma_m = 0.001;     // [m] per axis, 1-sigma
  Vec3 bias_m = Vec3::Zero();       // [m]
  double delay_s = 0.0;             // [s]
  double fov_half_angle_rad = 0.35; // [rad] the cone's half angle about body +x
  double range_max_m = 5000.0;      // [m] a rendezvous LIDAR's ranging reach
};

struct StarTrackerParams {  // chaser attitude q_inertial_from_body
  double noise_sigma_rad = 1e-5;    // [rad] per axis, 1-sigma, body frame
  Vec3 bias_rad = Vec3::Zero();     // [rad] constant misalignment, body frame
  double delay_s = 0.0;             // [s]
};

struct GyroParams {  // chaser body rate omega_body
  double noise_sigma_radps = 1e-6;  // [rad/s] per axis, 1-sigma
  Vec3 bias_radps = Vec3::Zero();   // [rad/s]
  double delay_s = 0.0;             // [s]
};

// A pose sensor on the target: the target's attitude relative to the chaser's body, as a
// camera or LIDAR pose estimate gives it, taken every period_s and delivered latency_s later
// (COMRADE 2018 gives 3 Hz for the reach phase; we use it from the synchronisation on). It looks
// along the LIDAR's boresight: a sample is taken only while the LIDAR sees the target and the
// target is within range_max_m (a pose from a point cloud needs it closer than a range does).
struct TargetPoseSensorParams {
  double period_s = 1.0 / 3.0;        // [s] between samples, in [control period, 10]
  double attitude_noise_rad = 0.0175;  // [rad] 1-sigma per axis, a small rotation in target axes
  double latency_s = 0.1;             // [s] from taking to delivery, in [0, period_s)
  double range_max_m = 5000.0;        // [m]
};

// The arm camera (COMRADE 2018, sec. 6.2.1: the gripper-to-grasping-point pose at 10 Hz): on the
// gripper, looking along the tool's x, it measures the fixture's pose (its position and attitude
// in camera axes) when the fixture is inside its cone and range; each sample taken at a control
// period every period_s and delivered latency_s later, with white noise on the position (per
// camera axis) and on the attitude (a small rotation, fixture axes). The fixture's frame: at
// target.body.grasp_point_target_m, turned from the target's axes by
// guidance.synchronised.q_target_from_body (its x the gripper's approach).
struct ArmCameraParams {
  double period_s = 0.1;                // [s] between samples, in [control period, 10]
  double position_noise_m = 0.001;      // [m] 1-sigma per axis
  double attitude_noise_rad = 0.0035;   // [rad] 1-sigma per axis
  double latency_s = 0.05;              // [s] in [0, period_s)
  double fov_half_angle_rad = 0.7;      // [rad] the fixture within this cone about the tool's x
  double range_max_m = 3.0;             // [m]
  // [m] the camera's eye behind the tool point along the tool's x (it looks past the jaws): the
  // cone and the range are the eye's; the pose it reports is the fixture's from the tool point.
  double setback_m = 0.2;
  // [m] a constant error of the reported position (the camera's calibration, camera axes): what the
  // capture's closure or the berthing drogue's cone must absorb. Optional, zero by default.
  Vec3 position_bias_m = Vec3::Zero();
};

struct SensorParams {
  LidarParams lidar;
  StarTrackerParams star_tracker;
  GyroParams gyro;
  PropellantSensorParams propellant;
  std::optional<TargetPoseSensorParams> target_pose;  // absent: no pose sensor
  std::optional<ArmCameraParams> arm_camera;          // absent: no arm camera (needs chaser.arm)
};

}  // namespace chaser::model
