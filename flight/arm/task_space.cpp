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

TaskVector extended_jacobian_rate_times(const ServicerArmParams& params, const ArmKinematics& kinematics,
                                        const ServicerVector& velocity, const ServicerVector& w) {
  (void)params;
  const Vec3 omega_world = kinematics.world_from_hub * velocity.segment<3>(3);
  const Vec3 w_omega_world = kinematics.world_from_hub * w.segment<3>(3);
  const Vec3 v_hub = velocity.head<3>();

  // Link 7's spatial velocity V (from v), W = J_7 w and (dJ_7/dt) w, about the fixed point O where
  // the hub's origin is now (flight/arm/coriolis_force.hpp, the same forward pass).
  Vec6 body_velocity = spatial(omega_world, v_hub);
  Vec6 body_w = spatial(w_omega_world, w.head<3>());
  Vec6 body_w_rate = spatial(omega_world.cross(w_omega_world), v_hub.cross(w_omega_world));
  for (std::size_t i = 0; i < static_cast<std::size_t>(model::kArmJoints); ++i) {
    const Vec6 subspace =
        hinge_subspace(kinematics.axis_world[i], kinematics.r_link_world_m[i] - kinematics.r_hub_world_m);
    const auto dof = static_cast<Eigen::Index>(kBaseDofs + i);
    body_velocity += subspace * velocity(dof);
    const Vec6 joint_w = subspace * w(dof);
    body_w += joint_w;
    body_w_rate += cross_motion(body_velocity, joint_w);
  }
  // The tool point p: J_tool w = (lin W + ang W x (p - O); ang W), whose rate, p moving at
  // p' = lin V + ang V x (p - O), is (lin W' + ang W' x (p - O) + ang W x p'; ang W').
  const Vec3 p = kinematics.r_tool_world_m - kinematics.r_hub_world_m;
  const Vec3 p_rate = linear(body_velocity) + angular(body_velocity).cross(p);
  TaskVector out = TaskVector::Zero();
  out.segment<3>(3) = omega_world.cross(w_omega_world);
  out.segment<3>(6) = linear(body_w_rate) + angular(body_w_rate).cross(p) + angular(body_w).cross(p_rate);
  out.segment<3>(9) = angular(body_w_rate);
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
