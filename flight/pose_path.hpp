#pragma once
// A rest-to-rest path between two poses in one frame, for the arm's tool (the reach's path to the
// pre-grasp pose and onto the fixture, the escape's retraction to the stowed pose): the position
// along the straight line and the attitude about the one axis of the rotation between the ends, both
// with the quintic's progress, so that speed and acceleration are zero at both ends.
#include "core/types.hpp"
#include "flight/arm/task_space.hpp"

namespace chaser::flight {

// A quintic blend from 0 to 1 over [0, T] (zero rate and acceleration at both ends): its progress,
// rate [1/s] and acceleration [1/s^2] at t_s (0 before, 1 after).
struct Blend {
  double s = 1.0, rate = 0.0, acceleration = 0.0;
};
Blend quintic(double t_s, double duration_s);

// The pose at elapsed_s of duration_s from (r0, q0) to (r1, q1), the frame's axes; velocities in them.
arm::FrameMotion pose_path(const Vec3& r0_m, const Quat& q0, const Vec3& r1_m, const Quat& q1, double elapsed_s,
                           double duration_s);

}  // namespace chaser::flight
