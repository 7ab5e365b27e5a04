#pragma once
// COMRADE 2018's combined H-infinity controller of the servicer's 13 degrees of freedom (sec. 6,
// beside the compliance controller of flight/arm/compliance_control.hpp): the computed-torque
// precompensation in the extended task space (flight/arm/computed_torque.hpp) leaves each task's
// error a double integrator in its commanded acceleration, and one SISO mixed-sensitivity loop per
// task (control/axis_design.hpp, synthesised by SLICOT's SB10AD as the synchronisation's six
// are) closes it, discretised by Tustin at the law's rate:
//   u_i = K_i(-e_i),  tau = H J^-1 (x''_ref + u - J' v) + C v.
// The loops see the tasks' pose errors only (each attitude as 2 eps, its small angle), as the
// synchronisation's do; the rates are the controllers' own.
#include <array>
#include <string>

#include "control/axis_design.hpp"
#include "flight/arm/computed_torque.hpp"
#include "flight/hinf_control.hpp"

namespace chaser::flight {

// One group of tasks' loop: its acceleration authority, the loop's delay and the weights
// (control::AxisDesignSpec's fields, the name set per task).
struct ArmHinfGroupSpec {
  double authority = 1.0;        // [m/s^2 | rad/s^2]
  double delay_s = 1e-3;         // [s]
  double bandwidth_radps = 1.0;  // [rad/s]
  double peak_sensitivity = 2.0;
  double low_frequency_gain = 1e-3;
  double error_scale = 0.01;     // [m | rad]
  double input_disturbance = 0.0;
};

struct ArmHinfSpec {
  ArmHinfGroupSpec hub_position, hub_attitude, tool_position, tool_attitude, joint;
  double period_s = 1e-3;  // the law's rate (the joints' 1 kHz)
};

struct ArmHinfParams {
  std::array<DiscreteLoop, arm::kTaskDofs> loops;  // hub x y z, hub rx ry rz, tool x y z, tool rx ry rz, joint 3
};

struct ArmHinfState {
  std::array<LoopState, arm::kTaskDofs> x = zero_array<LoopState, arm::kTaskDofs>();
};

// The thirteen designs (the three axes of a group share their spec). Throws std::runtime_error
// naming the task whose design fails.
ArmHinfParams make_arm_hinf_control(const ArmHinfSpec& spec);

// One step of the law: the loops advanced on the errors now, the generalized force to hold until
// the next step.
arm::ComputedTorque arm_hinf_control(const ArmHinfParams& params, ArmHinfState& state,
                                     const arm::ServicerArmParams& servicer, const arm::ArmKinematics& kinematics,
                                     const arm::JointVector& joint_angles_rad, const arm::ServicerVector& velocity,
                                     const arm::TaskReference& reference);

}  // namespace chaser::flight
