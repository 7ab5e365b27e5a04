#pragma once
// The plain structs that cross between plant (truth) and flight software. Nothing else crosses.
#include <array>
#include <cstdint>
#include <optional>

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

// A relative pose sample of a camera (the arm camera's view of the grasp fixture), delivered after
// its latency.
struct RelativePoseMeasurement {
  bool valid = false;                          // a sample was delivered this period
  double taken_s = 0;                          // [s] run time the sample was taken
  Vec3 r_camera_m = Vec3::Zero();              // [m] the fixture's origin, camera axes
  Quat q_camera_from_fixture = Quat::Identity();
};

// A 7-DOF arm's joints (COMRADE 2018, sec. 4; joint sensors at 1 kHz, sec. 6.2.1).
inline constexpr int kMaxArmJoints = 7;
using JointArray = std::array<double, kMaxArmJoints>;

// Plant -> flight, when the plant has an arm: the joint sensors, the gripper, the arm camera.
struct ArmMeasurements {
  int joints = 0;                   // entries used in each array
  JointArray q_rad{};               // [rad] joint angles
  JointArray q_dot_radps{};         // [rad/s] joint rates
  JointArray torque_Nm{};           // [N m] joint torques measured
  bool gripper_closed = false;      // the jaws hold the fixture: both fingers touch it (their switches)
  double gripper_opening_m = 0;     // [m] the fingers' inner faces apart
  bool gripper_locked = false;      // the gripper is closed rigidly on the fixture
  bool brakes_engaged = false;      // the joints' brakes hold
  bool probe_latched = false;       // berthing: the drogue's latches hold the probe's tip (soft dock)
  bool probe_hard_docked = false;   // berthing: the retraction ended and the pins hold (hard dock)
  RelativePoseMeasurement fixture;  // the grasp fixture seen by the arm camera
};

// Flight -> plant, when the plant has an arm.
struct ArmCommand {
  int joints = 0;
  JointArray torque_Nm{};       // [N m] joint torque demands to the inner torque loops
  bool close_gripper = false;   // the jaws close (form closure); false: they open
  bool lock_gripper = false;    // the gripper closes rigidly: done only while the jaws hold the fixture
  bool engage_brakes = false;   // the joints' brakes (rigidisation)
  bool retract_probe = false;   // berthing: the probe's central mechanism retracts (done only once latched)
};

// Plant -> flight: what the sensors deliver at the start of a control period.
struct SensorMeasurements {
  TimeNs t = 0;                                    // [ns] time of delivery
  Vec3 r_lvlh_m = Vec3::Zero();                    // LIDAR: chaser position from target, LVLH
  Quat q_inertial_from_body = Quat::Identity();    // star tracker
  Vec3 omega_body_radps = Vec3::Zero();            // gyro
  double propellant_used_kg = 0;                   // [kg] tank gauging: propellant used so far
  TargetPoseMeasurement target_pose{};             // pose sensor, when the scenario has one
  std::optional<ArmMeasurements> arm{};            // a plant with an arm only (disengaged: nothing copied)
  bool lidar_valid = true;                         // false: a LIDAR gap, the target out of its view (r_lvlh_m zero)
};

// Flight -> plant: commanded on-times for the coming period, by thruster index (0 for the idle
// ones), and the latch valves of the redundancy groups.
struct ThrusterCommand {
  ThrusterOnTimes ton{};  // [-] on-time as a fraction of the control period, 0..1
  std::uint32_t latch_closed_groups = 0;  // bit g set: group g's latch valve is closed, cutting its flow
  std::optional<ArmCommand> arm{};        // to a plant with an arm only
};

}  // namespace chaser::model
