#pragma once
// The target's frame as the capture's joint loop carries it between two control periods, in the
// combined law's world (inertial axes, origin at the target's estimated CoM): the target estimator's
// attitude carried to t_s by its rate and rate derivative (flight/target_estimator.hpp), then, where
// the arm camera has corrected it (flight/reach.hpp's update_from_camera), offset and turned by the
// correction.
#include "core/types.hpp"
#include "flight/arm/task_space.hpp"
#include "flight/target_estimator.hpp"

namespace chaser::flight {

// The estimate carried to t_s: at rest at the origin, turning at the estimated rate.
arm::FrameMotion estimated_target_frame(const TargetEstimate& estimate, double t_s);

// The same with the camera's correction: its origin at offset_m (world axes), turned by the
// rotation vector rotation_rad (target axes).
arm::FrameMotion corrected_target_frame(const TargetEstimate& estimate, const Vec3& offset_m, const Vec3& rotation_rad,
                                        double t_s);

}  // namespace chaser::flight
