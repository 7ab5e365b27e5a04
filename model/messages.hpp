#pragma once
// The plain structs that cross between plant (truth) and flight software. Nothing else crosses.
#include "core/time.hpp"
#include "core/types.hpp"
#include "model/thrusters.hpp"

namespace chaser::model {

// Plant -> flight: what the sensors deliver at the start of a control period.
struct SensorMeasurements {
  TimeNs t = 0;                                    // [ns] time of delivery
  Vec3 r_lvlh_m = Vec3::Zero();                    // LIDAR: chaser position from target, LVLH
  Quat q_inertial_from_body = Quat::Identity();    // star tracker
  Vec3 omega_body_radps = Vec3::Zero();            // gyro
  double propellant_used_kg = 0;                   // [kg] tank gauging: propellant used so far
};

// Flight -> plant: commanded on-times for the coming period, all 16 thrusters (0 for the idle ones).
struct ThrusterCommand {
  Ton16 ton{};  // [-] on-time as a fraction of the control period, 0..1
  std::array<bool, 2> latch_open{true, true};  // latch valve of branch A, B: closed cuts the branch
};

}  // namespace chaser::model
