#pragma once
// The computed-torque precompensation of the servicer's 13 degrees of freedom in the extended task
// space (flight/arm/task_space.hpp), behind which COMRADE 2018's combined H-infinity controller
// designs its loops (sec. 6, as the synchronisation's sec. 5 does for the platform alone):
//
//   tau = H(q) J^-1 (x''_ref + u - J'(q, v) v) + C(q, v) v
//
// makes every task's error a double integrator in u, decoupled from the others:
// J v' + J' v = x''_ref + u, i.e. e'' = u for the positions and the joint, and (omega - omega_ref)'
// = u for the attitudes (the loops see twice eps, the small angle). The model is the flight
// software's; what it gets wrong (the hub's mass, the propellant, the arm's friction) is left to
// the loops. tau as in servicer_arm.hpp.
#include "core/types.hpp"
#include "flight/arm/arm_kinematics.hpp"
#include "flight/arm/servicer_arm.hpp"
#include "flight/arm/task_space.hpp"

namespace chaser::flight::arm {

struct ComputedTorque {
  ServicerVector generalized_force = ServicerVector::Zero();
  TaskErrors errors;
};

// task_acceleration: u (13), the loops' commanded acceleration of each task's error.
ComputedTorque computed_torque(const ServicerArmParams& params, const ArmKinematics& kinematics,
                               const JointVector& joint_angles_rad, const ServicerVector& velocity,
                               const TaskReference& reference, const TaskVector& task_acceleration);

// The errors the loops regulate: positions and the joint as they are, each attitude as 2 eps
// (its angle to first order) [m, rad].
TaskVector loop_errors(const TaskErrors& errors);

}  // namespace chaser::flight::arm
