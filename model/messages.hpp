#pragma once
// The plain structs that cross between plant (truth) and flight software. Nothing else crosses.
#include <cstdint>

#include "core/time.hpp"
#include "core/types.hpp"
#include "model/thrusters.hpp"

namespace chaser::model {

// A target pose sample (model::TargetPoseSensorParams), delivered after its latency.
struct TargetPoseMeasurement {
  bool valid = false;                          // a sample was delivered this period
  double taken_s = 0;                          // [s] run time the sample was taken
  Quat q_body_from_target = Quat::Identity();  // the target's attitude in the chaser's body axes
};

// Plant -> flight: what the sensors deliver at the start of a control period.
struct SensorMeasurements {
  TimeNs t = 0;                                    // [ns] time of delivery
  Vec3 r_lvlh_m = Vec3::Zero();                    // LIDAR: chaser position from target, LVLH
  Quat q_inertial_from_body = Quat::Identity();    // star tracker
  Vec3 omega_body_radps = Vec3::Zero();            // gyro
  double propellant_used_kg = 0;                   // [kg] tank gauging: propellant used so far
  TargetPoseMeasurement target_pose{};             // pose sensor, when the scenario has one
};

// Flight -> plant: commanded on-times for the coming period, by thruster index (0 for the idle
// ones), and the latch valves of the redundancy groups.
struct ThrusterCommand {
  ThrusterOnTimes ton{};  // [-] on-time as a fraction of the control period, 0..1
  std::uint32_t latch_closed_groups = 0;  // bit g set: group g's latch valve is closed, cutting its flow
};

}  // namespace chaser::model
