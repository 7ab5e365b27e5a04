#include "flight/arm/computed_torque.hpp"

#include <Eigen/LU>

#include "flight/arm/coriolis_force.hpp"
#include "flight/arm/floating_base_mass_matrix.hpp"

namespace chaser::flight::arm {

ComputedTorque computed_torque(const ServicerArmParams& params, const ArmKinematics& kinematics,
                               const JointVector& joint_angles_rad, const ServicerVector& velocity,
                               const TaskReference& reference, const TaskVector& task_acceleration) {
  const TaskJacobian J = extended_jacobian(kinematics);
  ComputedTorque out;
  out.errors = task_errors(kinematics, J, joint_angles_rad, velocity, reference);
  const ServicerVector acceleration = Eigen::PartialPivLU<TaskJacobian>(J).solve(
      out.errors.reference_acceleration + task_acceleration -
      extended_jacobian_rate_times(kinematics, velocity, velocity));
  out.generalized_force = floating_base_mass_matrix(params, kinematics) * acceleration +
                          coriolis_force(params, kinematics, velocity);
  return out;
}

TaskVector loop_errors(const TaskErrors& errors) {
  TaskVector e = errors.pose;
  e.segment<3>(3) *= 2.0;
  e.segment<3>(9) *= 2.0;
  return e;
}

}  // namespace chaser::flight::arm
