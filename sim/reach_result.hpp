#pragma once
// The reach judged against COMRADE 2018 Table 2 (the requirements at the end of the reach and at
// the grasp): the gripper against the pose the reach aims at (the pre-grasp pose, true values in its
// axes, x the approach), over the hold that follows the tool's path, and the chaser at the end.
// The gripper's Table 2 envelope is written for the grasp; the reach holds it standoff_m short of
// the fixture, so its errors are taken from that pose.
#include <array>
#include <limits>

#include "core/types.hpp"
#include "flight/grasp.hpp"
#include "flight/rigidise.hpp"
#include "flight/stabilise.hpp"
#include "model/arm.hpp"
#include "model/capture.hpp"
#include "plant/arm_joints.hpp"
#include "sim/berth_result.hpp"
#include "sim/mission_monitor.hpp"

namespace chaser::sim {

// COMRADE 2018 Table 2.
inline constexpr const double (&kTable2GripperErrorM)[3] = model::kGrapplingEnvelopeM;  // [m] x (approach), y, z
inline constexpr double kTable2GripperAttitudeDeg = model::kGrapplingEnvelopeDeg;        // [deg] about each axis
inline constexpr double kTable2GripperVelocityMps = model::kGraspRelativeVelocityMps;    // [m/s] per axis
inline constexpr double kTable2GripperRateDegps = model::kGraspRelativeRateDegps;        // [deg/s] per axis
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

// The grasp (flight/grasp.hpp) judged against COMRADE Table 2 when the jaws are commanded closed:
// the gripper against the fixture (true values in the grasp pose's axes, x the approach), the
// chaser against its reference at the capture point. Times NaN where the step never came.
struct GraspResult {
  bool attempted = false;          // the approach began within the run
  const char* outcome = "reach";   // the grasp's last step (flight::to_string(GraspStep))
  double closure_s = std::numeric_limits<double>::quiet_NaN();   // [s] the jaws commanded closed
  double lock_s = std::numeric_limits<double>::quiet_NaN();      // [s] the rigid closure commanded
  double captured_s = std::numeric_limits<double>::quiet_NaN();  // [s] the gripper reported locked
  bool judged = false;             // closure was commanded: the figures below are set
  plant::GripperTruth at_closure;
  double chaser_position_m = std::numeric_limits<double>::quiet_NaN();    // [m] |r - r_ref|
  double chaser_velocity_mps = std::numeric_limits<double>::quiet_NaN();  // [m/s]
  double chaser_attitude_deg = std::numeric_limits<double>::quiet_NaN();  // [deg] the rotation's angle
  double chaser_rate_deg_s = std::numeric_limits<double>::quiet_NaN();    // [deg/s] |w - w_ref|
};

// Whether the grasp was judged and met every figure of Table 2 at the closure: the gripper inside the
// envelope, its relative velocity and rate per axis, the chaser's four.
bool grasp_meets_table2(const GraspResult& g);

// The rigidisation (flight/rigidise.hpp; COMRADE 2018 Table 7's figures): when it began (the capture
// confirmed) and the brakes engaged, each joint's peak torque command over it, and at the run's end
// each joint's angle from where the rigidisation held it and its rate. NaN where it never came.
struct RigidiseResult {
  bool flown = false;
  double start_s = std::numeric_limits<double>::quiet_NaN();   // [s]
  double brakes_s = std::numeric_limits<double>::quiet_NaN();  // [s]
  std::array<double, model::kArmJoints> peak_torque_Nm{};      // [N m] the commands, every joint step
  std::array<double, model::kArmJoints> final_angle_error_rad{};  // [rad] q - q_d at the end
  std::array<double, model::kArmJoints> final_rate_radps{};       // [rad/s] at the end
  // [N m] each brake's largest load (plant::brake_loads_Nm), every joint step from the engagement on
  std::array<double, model::kArmJoints> peak_brake_load_Nm{};
};

// The stabilisation (flight/stabilise.hpp; COMRADE 2018 Tables 3 and 8): when it began, the
// target's true rate (the composite's: it is rigid) against Table 3's kStabilisedRateDegps, the
// propellant it took. The braked joints' loads over it are the rigidisation's peak_brake_load_Nm.
struct StabiliseResult {
  bool flown = false;
  double start_s = std::numeric_limits<double>::quiet_NaN();        // [s]
  double initial_rate_degps = std::numeric_limits<double>::quiet_NaN();  // [deg/s] |w| at the start
  // [s] the rate below the goal from then to the end (NaN: above it at the end)
  double below_goal_s = std::numeric_limits<double>::quiet_NaN();
  Vec3 final_rate_target_degps = Vec3::Zero();  // [deg/s] at the end, the target's axes (Table 8's)
  double start_mass_kg = 0.0;                   // [kg] the chaser's at the start
  double propellant_kg = 0.0;                   // [kg] from the start to the end
  double load_limit_Nm = 0.0;                   // [N m] the drives' repeated peak (chaser.arm), Table 3's
};

struct ReachResult {
  bool flown = false;                 // the arm woke
  double hold_from_s = 0.0;           // [s] the window judged: [hold_from_s, hold_to_s) within the run
  double hold_to_s = std::numeric_limits<double>::infinity();  // [s] the approach's start (the reach's end)
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
  GraspResult grasp;
  BerthResult berthing;  // capture.berthing: the grasp's steps are the probe's
  RigidiseResult rigidise;
  StabiliseResult stabilise;
};

// One control period of the reach: the gripper's truth at t_s and the tool point's clearance from the
// keep-out volume (NaN: none). The largest values are taken over the hold (t_s >= hold_from_s), the
// least clearance over the whole reach; the last period's values are the final ones. Periods from
// hold_to_s on (the approach onto the fixture) are not the reach's: ignored.
void add_reach_period(ReachResult& r, const plant::GripperTruth& gripper, double t_s, double clearance_m);

// Whether the gripper stayed inside Table 2 over the hold (every axis of each of the four).
bool gripper_meets_table2(const ReachResult& r);

// A control period of the capture: the grasp's steps as the flight software has them, and, at the
// period the jaws are commanded closed, the gripper's truth against the fixture and the chaser's
// errors (the mission monitor's sample at t_s).
void add_grasp_period(GraspResult& g, const flight::GraspState& state, const plant::GripperTruth& gripper_at_fixture,
                      const MonitorSample& sample);

// A control period with the rigidisation flown (state.started()): its times, and the joints now as
// the final ones.
void add_rigidise_period(RigidiseResult& r, const flight::RigidiseState& state, const model::ArmMeasurements& joints);

// Table 3 met: the rate below kStabilisedRateDegps at the end, every braked joint's peak load within
// the drives' repeated peak.
bool stabilise_meets_table3(const ReachResult& r);
double peak_brake_load_Nm(const ReachResult& r);  // [N m] over the joints

// A control period with the stabilisation flown (state.started()): the target's true rate (its
// axes) and the chaser's mass at t_s.
void add_stabilise_period(StabiliseResult& r, const flight::StabiliseState& state, const Vec3& omega_target_radps,
                          double chaser_mass_kg, double load_limit_Nm, double t_s);

}  // namespace chaser::sim
