#include "flight/arm/task_space.hpp"

#include <Eigen/Geometry>

#include "flight/arm/spatial.hpp"

namespace chaser::flight::arm {

namespace {

// The vector part of q q_ref^-1 with its scalar part made >= 0 (the shorter of the two rotations).
Vec3 attitude_error(const Quat& q, const Quat& q_ref) {
  const Quat e = q.normalized() * q_ref.normalized().conjugate();
  return e.w() >= 0.0 ? Vec3(e.vec()) : Vec3(-e.vec());
}

}  // namespace

FrameMotion compose(const FrameMotion& parent, const FrameMotion& child_in_parent) {
  const Mat3 R = parent.q_world_from_frame.normalized().toRotationMatrix();
  const Vec3 d = R * child_in_parent.r_m;
  const Vec3 v_rel = R * child_in_parent.v_mps;
  const Vec3 omega_rel = R * child_in_parent.omega_radps;
  const Vec3& w = parent.omega_radps;
  FrameMotion out;
  out.r_m = parent.r_m + d;
  out.v_mps = parent.v_mps + w.cross(d) + v_rel;
  out.a_mps2 = parent.a_mps2 + parent.alpha_radps2.cross(d) + w.cross(w.cross(d)) + 2.0 * w.cross(v_rel) +
               R * child_in_parent.a_mps2;
  out.q_world_from_frame = (parent.q_world_from_frame * child_in_parent.q_world_from_frame).normalized();
  out.omega_radps = w + omega_rel;
  out.alpha_radps2 = parent.alpha_radps2 + R * child_in_parent.alpha_radps2 + w.cross(omega_rel);
  return out;
}

TaskJacobian extended_jacobian(const ArmKinematics& kinematics) {
  TaskJacobian J = TaskJacobian::Zero();
  J.topLeftCorner<3, 3>().setIdentity();
  J.block<3, 3>(3, 3) = kinematics.world_from_hub;
  J.block<6, kServicerDofs>(6, 0) = tool_jacobian(kinematics);
  J(12, kBaseDofs + kRedundancyJoint) = 1.0;
  return J;
}

TaskVector extended_jacobian_rate_times(const ArmKinematics& kinematics, const ServicerVector& velocity,
                                        const ServicerVector& w) {
  const ChainMotion c = chain_motion(kinematics, velocity, w);
  const Vec6& tool_velocity = c.velocity.back();  // link 7's
  const Vec6& tool_w = c.w.back();
  const Vec6& tool_w_rate = c.w_rate.back();
  // The tool point p: J_tool w = (lin W + ang W x (p - O); ang W), whose rate, p moving at
  // p' = lin V + ang V x (p - O), is (lin W' + ang W' x (p - O) + ang W x p'; ang W').
  const Vec3 p = kinematics.r_tool_world_m - kinematics.r_hub_world_m;
  const Vec3 p_rate = linear(tool_velocity) + angular(tool_velocity).cross(p);
  TaskVector out = TaskVector::Zero();
  out.segment<3>(3) = angular(c.velocity[0]).cross(angular(c.w[0]));  // d(R w_omega)/dt = omega x R w_omega
  out.segment<3>(6) = linear(tool_w_rate) + angular(tool_w_rate).cross(p) + angular(tool_w).cross(p_rate);
  out.segment<3>(9) = angular(tool_w_rate);
  return out;
}

Quat tool_attitude(const ArmKinematics& kinematics) {
  return Quat(kinematics.world_from_link[model::kArmJoints - 1]).normalized();
}

TaskErrors task_errors(const ArmKinematics& kinematics, const TaskJacobian& jacobian, const JointVector& joint_angles_rad,
                       const ServicerVector& velocity, const TaskReference& reference) {
  TaskErrors e;
  e.pose.segment<3>(0) = kinematics.r_hub_world_m - reference.hub.r_m;
  e.pose.segment<3>(3) = attitude_error(Quat(kinematics.world_from_hub), reference.hub.q_world_from_frame);
  e.pose.segment<3>(6) = kinematics.r_tool_world_m - reference.tool.r_m;
  e.pose.segment<3>(9) = attitude_error(tool_attitude(kinematics), reference.tool.q_world_from_frame);
  e.pose(12) = joint_angles_rad(kRedundancyJoint) - reference.joint_rad;
  e.reference_velocity << reference.hub.v_mps, reference.hub.omega_radps, reference.tool.v_mps,
      reference.tool.omega_radps, reference.joint_rate_radps;
  e.reference_acceleration << reference.hub.a_mps2, reference.hub.alpha_radps2, reference.tool.a_mps2,
      reference.tool.alpha_radps2, reference.joint_acceleration_radps2;
  e.velocity = jacobian * velocity - e.reference_velocity;
  return e;
}

}  // namespace chaser::flight::arm
