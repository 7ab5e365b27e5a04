#pragma once
// The capture's reach on board (COMRADE 2018, sec. 4 and 6.2.1): the chaser holds the capture point
// while the gripper follows a path to the pre-grasp pose beside the fixture, under one combined
// controller of the 13 degrees of freedom (flight/arm/compliance_control.hpp or
// flight/arm_hinf_control.hpp) run at the joints' rate. Its joint torques go to the arm's inner
// loops at that rate; its platform force and torque are what the thrusters fly, sampled by the
// flight software's period (step_flight reads them instead of the position and attitude loops).
//
// The structure is the paper's Fig. 12: feedback on joint data at the joints' rate, the platform's
// and the target's state from navigation. Between two periods the joint loop carries the last
// estimates forward (the hub's attitude by its measured rate, the chaser's position by its
// velocity, the target's attitude by the estimator's own prediction).
//
// The law's world: inertial axes, the origin at the target's estimated centre of mass (its orbital
// acceleration and the frame's are the same to the tide, ~1e-5 m/s^2 at 3.5 m, left to the loops).
#include <array>
#include <optional>

#include "core/time.hpp"
#include "flight/arm/compliance_control.hpp"
#include "flight/arm/servicer_arm.hpp"
#include "flight/arm/task_space.hpp"
#include "flight/arm_hinf_control.hpp"
#include "flight/escape.hpp"
#include "flight/grasp.hpp"
#include "flight/navigation.hpp"
#include "flight/rigidise.hpp"
#include "flight/stabilise.hpp"
#include "flight/target_estimator.hpp"
#include "model/capture.hpp"
#include "model/messages.hpp"
#include "model/scenario.hpp"
#include "model/target_orbit.hpp"

namespace chaser::flight {

struct ReachParams {
  double start_s = 0.0;                      // [s]
  model::CaptureLaw law = model::CaptureLaw::kCompliance;
  double path_duration_s = 60.0;             // [s]
  TimeNs joint_period_ns = 1'000'000;        // [ns]
  double braked_step_s = 0.01;               // [s] the escape's arm braked, the joint loop's step
  double platform_period_s = 0.1;            // [s] the platform command's (capture.platform_rate_hz)
  arm::ServicerArmParams servicer;           // the flight software's model of hub and arm
  Vec3 hub_from_chaser_com_body_m = Vec3::Zero();  // [m] the hub's CoM from the chaser's (arm stowed) CoM
  // In the target's frame: where the chaser's CoM holds and its attitude (the synchronised hold's),
  // the tool's pre-grasp pose (standoff short of the fixture along the tool's x, its grasp attitude).
  Vec3 capture_point_target_m = Vec3::Zero();
  Quat q_target_from_body = Quat::Identity();
  Vec3 grasp_point_target_m = Vec3::Zero();  // the fixture (its frame: q_target_from_tool, as the camera sees it)
  Vec3 pre_grasp_target_m = Vec3::Zero();
  // Where the approach's path ends: the fixture, or with a berthing the drogue's socket and
  // capture.berthing.insertion_overtravel_m beyond (the tool's stiffness presses the tip home).
  Vec3 approach_end_target_m = Vec3::Zero();
  Quat q_target_from_tool = Quat::Identity();
  // The approach from the pre-grasp pose onto the fixture and the grasp (flight/grasp.hpp); without
  // a grasp (approach_duration_s 0) the tool stays at the pre-grasp pose.
  double approach_duration_s = 0.0;          // [s]
  GraspParams grasp;
  double torque_limit_Nm = 176.0;            // [N m] each joint's command, the drives' repeated peak
  arm::ComplianceGains gains;                // the compliance law's, designed at the stowed arm
  ArmHinfParams hinf;                        // the H-infinity law's loops
  // Captured: the rigidisation (flight/rigidise.hpp) in place of the combined law, the thrusters
  // inhibited; without it the combined law flies on.
  std::optional<RigidiseLawParams> rigidise;
  // Once the rigidisation's brakes hold: the stabilisation (flight/stabilise.hpp), the thrusters
  // detumbling the composite; without it they stay inhibited.
  std::optional<StabiliseLawParams> stabilise;
  // The escape (flight/escape.hpp): on command or a failed grasp, its plan in place of the reach's
  // path; without it a failed grasp leaves the tool at the fixture.
  std::optional<EscapeLawParams> escape;
};

// With capture (and chaser.arm): the reach's parameters; the H-infinity loops designed here.
std::optional<ReachParams> make_reach(const model::Scenario& scenario);

// The tool's pose as the joint loop computed it (its own kinematics on the carried estimates), kept
// for the arm camera's samples, which arrive a latency after they were taken.
struct ToolPoseSample {
  double t_s = -1.0;
  Vec3 r_m = Vec3::Zero();
  Quat q = Quat::Identity();
};
inline constexpr int kToolPoseHistory = 512;  // [joint steps] 0.5 s at 1 kHz: more than the camera's latency

// The arm camera's correction of the target's frame (the paper's Fig. 11: feedback on the camera's
// gripper-to-fixture pose): the frame the fixture's measured pose implies, against the target
// estimator's, low-passed (kCameraGain per sample) so that acquiring the fixture moves the
// references smoothly and the camera's noise is averaged.
inline constexpr double kCameraGain = 0.05;  // [-] per sample: a time constant of 20 samples, 2 s at 10 Hz

struct ReachState {
  // The last period's estimates, carried forward by the joint loop.
  NavEstimate nav;
  std::optional<TargetEstimate> target;
  double nav_t_s = 0.0;
  model::LvlhFrame lvlh;
  // The tool's pose in the target's frame when the reach began (the path's start).
  bool started = false;
  Vec3 tool_start_target_m = Vec3::Zero();
  Quat q_target_from_tool_start = Quat::Identity();
  double joint3_start_rad = 0.0;
  ArmHinfState hinf;
  std::array<ToolPoseSample, kToolPoseHistory> tool_history{};
  int tool_history_next = 0;
  // The camera's correction: the target's frame offset [m] (world axes) and turned by the rotation
  // vector [rad] (target axes); the samples used.
  Vec3 frame_offset_m = Vec3::Zero();
  Vec3 frame_rotation_rad = Vec3::Zero();
  int camera_samples = 0;
  // The law's last output: the platform's force (inertial axes) and torque (body axes, about the
  // chaser's CoM), the joint torques as commanded (clamped) and the tasks' errors.
  bool has_output = false;
  Vec3 platform_force_inertial_N = Vec3::Zero();
  Vec3 platform_torque_body_Nm = Vec3::Zero();
  // The platform's command as the thrusters fly it: the law's, sampled at the platform's rate.
  double next_platform_s = 0.0;  // [s] the next tick
  Vec3 held_force_inertial_N = Vec3::Zero();
  Vec3 held_torque_body_Nm = Vec3::Zero();
  arm::JointVector joint_torque_Nm = arm::JointVector::Zero();
  arm::TaskErrors errors;
  GraspState grasp;
  RigidiseState rigidise;
  StabiliseState stabilise;
  EscapeState escape;
};

// The rigidisation flies (it began at the capture's confirmation): the thrusters are inhibited,
// until the brakes hold where a stabilisation follows.
inline bool thrusters_inhibited(const ReachParams& params, const ReachState& state) {
  return state.rigidise.started() && !(params.stabilise && state.rigidise.brakes_s >= 0.0);
}
// The brakes hold and a stabilisation follows: the thrusters detumble the composite.
inline bool stabilising(const ReachParams& params, const ReachState& state) {
  return params.stabilise && state.rigidise.started() && state.rigidise.brakes_s >= 0.0;
}


// The period's estimates for the joint loop (called by step_flight every period of the reach).
void hold_estimates(ReachState& state, const NavEstimate& nav, const std::optional<TargetEstimate>& target, double t_s,
                    const model::LvlhFrame& lvlh);

// The platform's force (inertial axes) and torque (body axes, about the chaser's CoM) for the control
// period starting at t_s: the law's last output at a platform tick (the first period at or after
// it), held otherwise. False until the law has run.
bool platform_command(const ReachParams& params, ReachState& state, double t_s, Vec3& force_inertial_N,
                      Vec3& torque_body_Nm);

// An arm camera sample (delivered this period): the fixture's pose in the law's world from the
// tool's pose when it was taken, the target's frame it implies, and the correction moved towards it.
void update_from_camera(const ReachParams& params, ReachState& state, const model::RelativePoseMeasurement& sample);

// One step of the joint loop at t_s: the law on the joints measured now and the estimates carried
// to t_s; the joint torques to hold until the next step. Once captured, with a rigidisation, its
// law instead, and the thrusters inhibited from then on. Once an escape is triggered (here, on
// command or a failed grasp), the law tracks its plan, the jaws open. Until the target's estimate exists, the
// joints hold still (zero torque is not holding: they are commanded to their angles by the law's
// own joint-space damping only once the reach has started).
model::ArmCommand step_reach(const ReachParams& params, ReachState& state, const model::ArmMeasurements& joints,
                             double t_s);

// The tool's path in the target's frame at t_s (a quintic blend from the start pose to the
// pre-grasp pose over path_duration_s, the attitude turned about one axis; from the grasp's
// approach_start_s, a second from the pre-grasp pose onto the fixture over approach_duration_s).
arm::FrameMotion tool_path(const ReachParams& params, const ReachState& state, double t_s);

}  // namespace chaser::flight
