#pragma once
// The reach judged against COMRADE 2018 Table 2 (the requirements at the end of the reach and at
// the grasp): the gripper against the pose the reach aims at (the pre-grasp pose, true values in its
// axes, x the approach), over the hold that follows the tool's path, and the chaser at the end.
// The gripper's Table 2 envelope is written for the grasp; the reach holds it standoff_m short of
// the fixture, so its errors are taken from that pose.
#include <array>
#include <limits>

#include "core/types.hpp"
#include "model/arm.hpp"
#include "plant/arm_joints.hpp"

namespace chaser::sim {

// COMRADE 2018 Table 2.
inline constexpr double kTable2GripperErrorM[3] = {0.010, 0.022, 0.022};      // [m] x (approach), y, z
inline constexpr double kTable2GripperAttitudeDeg = 2.74;                       // [deg] about each axis
inline constexpr double kTable2GripperVelocityMps = 0.005;                      // [m/s] per axis
inline constexpr double kTable2GripperRateDegps = 0.1;                          // [deg/s] per axis
inline constexpr double kTable2ChaserPositionM = 0.05;                          // [m]
inline constexpr double kTable2ChaserVelocityMps = 0.005;                       // [m/s]
inline constexpr double kTable2ChaserAttitudeDeg = 2.0;                         // [deg]
inline constexpr double kTable2ChaserRateDegps = 0.5;                           // [deg/s]
// The gripper's Table 2 limit per figure (0 position [m], 1 velocity [m/s], 2 attitude [deg], 3 rate
// [deg/s], the order of COMRADE Table 6) and axis (x the approach).
constexpr double table2_gripper_limit(int figure, int axis) {
  switch (figure) {
    case 0: return kTable2GripperErrorM[axis];
    case 1: return kTable2GripperVelocityMps;
    case 2: return kTable2GripperAttitudeDeg;
    default: return kTable2GripperRateDegps;
  }
}
// The hold judged starts this long after the tool's path ends (its settling).
inline constexpr double kReachSettleS = 10.0;  // [s]

struct ReachResult {
  bool flown = false;                 // the arm woke
  double hold_from_s = 0.0;           // [s] the window judged: [hold_from_s, end of run]
  int hold_periods = 0;
  // The largest |value| per axis over the hold, and the values at the end.
  Vec3 max_gripper_error_m = Vec3::Zero();
  Vec3 max_gripper_velocity_mps = Vec3::Zero();
  Vec3 max_gripper_attitude_rad = Vec3::Zero();
  Vec3 max_gripper_rate_radps = Vec3::Zero();
  plant::GripperTruth final_gripper;
  std::array<double, model::kArmJoints> peak_joint_torque_Nm{};  // [N m] the commands, every joint step of the reach
  // [m] the tool point's least distance to the target's keep-out volume over the reach (each
  // control period; negative inside), and when; NaN without target.body.keep_out.
  double min_tool_clearance_m = std::numeric_limits<double>::quiet_NaN();
  double min_tool_clearance_at_s = std::numeric_limits<double>::quiet_NaN();
  int camera_samples = 0;             // arm camera samples the flight software used
};

// One control period of the reach: the gripper's truth at t_s and the tool point's clearance from the
// keep-out volume (NaN: none). The largest values are taken over the hold (t_s >= hold_from_s), the
// least clearance over the whole reach; the last period's values are the final ones.
void add_reach_period(ReachResult& r, const plant::GripperTruth& gripper, double t_s, double clearance_m);

// Whether the gripper stayed inside Table 2 over the hold (every axis of each of the four).
bool gripper_meets_table2(const ReachResult& r);

}  // namespace chaser::sim
