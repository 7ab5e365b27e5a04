#pragma once
// The capture's grasp on board (COMRADE 2018, sec. 4: "as soon as the gripper is in the right
// position for grasping it closes rapidly establishing a form closure ... Then the gripper closes
// rigidly"; sec. 6.2: "the gripper control function ... issues the gripper closure command as soon
// as the gripper is in the desired position and attitude for capture"). Its steps:
//   approach  the tool moves from the pre-grasp pose onto the fixture (flight/reach.hpp's path);
//   closing   once the path has ended, closure_samples arm camera samples in a row put the fixture
//             inside COMRADE Table 2's grappling envelope: the jaws close;
//   locking   both fingers have held the lip (the jaws' switches) for lock_dwell_s: the gripper
//             closes rigidly;
//   captured  the gripper reports itself locked: the capture is confirmed.
// No closure within grasp_timeout_s of the path's end: abandoned, the jaws stay open.
// ASSIST's berthing (capture.berthing) takes the same steps with a probe for the jaws:
//   approach  the probe's tip onto the socket, into the drogue;
//   locking   the drogue's latches hold the tip (their switch: the soft dock): the probe's
//             retraction is commanded (the tool's path follows it: flight/reach.hpp);
//   captured  the pins report the hard dock.
// No latch within grasp_timeout_s of the path's end: abandoned.
#include "model/capture.hpp"
#include "model/messages.hpp"

namespace chaser::flight {

enum class GraspStep { kReach, kApproach, kClosing, kLocking, kCaptured, kAbandoned };

struct GraspParams {
  double approach_start_s = 0.0;  // [s] the tool leaves the pre-grasp pose
  double approach_end_s = 0.0;    // [s] it is on the fixture (the path's end)
  double timeout_s = 30.0;        // [s] after approach_end_s
  int closure_samples = 3;
  double lock_dwell_s = 0.2;      // [s]
  bool berthing = false;          // the probe and the drogue (capture.berthing)
  double retraction_m = 0.0;      // [m] berthing: the probe's retraction
  double retraction_duration_s = 0.0;  // [s]
};

GraspParams make_grasp(const model::CaptureParams& capture);

struct GraspState {
  GraspStep step = GraspStep::kReach;
  int inside_samples = 0;        // consecutive camera samples inside the envelope
  double closure_s = -1.0;       // [s] the jaws were commanded closed (-1: not yet)
  double holding_since_s = -1.0; // [s] both fingers hold the lip since
  double lock_s = -1.0;          // [s] the rigid closure (berthing: the retraction) was commanded
  double captured_s = -1.0;      // [s] the gripper reported itself locked
};

// Whether a camera sample puts the fixture inside the grappling envelope (its position per axis
// and its attitude about each axis, in the fixture's axes, x the approach).
bool inside_grappling_envelope(const model::RelativePoseMeasurement& sample);

// A period's arm camera sample at t_s (valid or not: an invalid one breaks the run of samples).
void grasp_camera_sample(const GraspParams& params, GraspState& state, const model::RelativePoseMeasurement& sample,
                         double t_s);

// A joint step at t_s: the grasp's steps advanced on the gripper's sensors, and its commands
// (close_gripper, lock_gripper) written into `command`.
void grasp_joint_step(const GraspParams& params, GraspState& state, const model::ArmMeasurements& arm, double t_s,
                      model::ArmCommand& command);

const char* to_string(GraspStep step);

}  // namespace chaser::flight
