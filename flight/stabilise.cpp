#include "flight/stabilise.hpp"

#include <algorithm>

#include "flight/arm/arm_kinematics.hpp"

namespace chaser::flight {

namespace {

// A body's inertia about the point p: its own about its CoM c plus m (|c - p|^2 I - (c - p)(c - p)^T).
Mat3 about_point(double mass_kg, const Vec3& com_m, const Mat3& inertia_com_kgm2, const Vec3& p_m) {
  const Vec3 d = com_m - p_m;
  return inertia_com_kgm2 + mass_kg * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
}

}  // namespace

CompositeInertia composite_inertia(const arm::ServicerArmParams& servicer, const arm::JointVector& joint_angles_rad,
                                   const GraspedTarget& target) {
  // The hub at the origin in its own axes: every frame below is in hub axes.
  const arm::ArmKinematics k = arm::arm_kinematics(servicer, Vec3::Zero(), Quat::Identity(), joint_angles_rad);
  // The target's frame from the tool's: R_hub_target = R_hub_tool R_tool_target, and its CoM the
  // tool point less the grasp point turned into hub axes.
  const Mat3 hub_from_tool = k.world_from_link[model::kArmJoints - 1];
  const Mat3 hub_from_target = hub_from_tool * target.q_target_from_tool.normalized().toRotationMatrix().transpose();
  const Vec3 target_com_m = k.r_tool_world_m - hub_from_target * target.grasp_point_target_m;
  const Mat3 target_inertia = hub_from_target * target.inertia_kgm2 * hub_from_target.transpose();

  CompositeInertia c;
  c.mass_kg = servicer.hub_mass_kg + target.mass_kg;
  Vec3 moment = target.mass_kg * target_com_m;  // the hub's CoM is the origin
  for (int i = 0; i < model::kArmJoints; ++i) {
    const auto& link = servicer.links[static_cast<std::size_t>(i)];
    c.mass_kg += link.mass_kg;
    moment += link.mass_kg * k.r_com_world_m[static_cast<std::size_t>(i)];
  }
  c.com_hub_m = moment / c.mass_kg;
  c.inertia_kgm2 = about_point(servicer.hub_mass_kg, Vec3::Zero(), servicer.hub_inertia_kgm2, c.com_hub_m) +
                   about_point(target.mass_kg, target_com_m, target_inertia, c.com_hub_m);
  for (int i = 0; i < model::kArmJoints; ++i) {
    const auto& link = servicer.links[static_cast<std::size_t>(i)];
    const Mat3& r = k.world_from_link[static_cast<std::size_t>(i)];
    c.inertia_kgm2 += about_point(link.mass_kg, k.r_com_world_m[static_cast<std::size_t>(i)],
                                  r * link.inertia_com_link_kgm2 * r.transpose(), c.com_hub_m);
  }
  return c;
}

double stabilise_reference_share(const model::StabiliseParams& params, const StabiliseState& state, double t_s) {
  return std::max(0.0, 1.0 - (t_s - state.started_s) / params.duration_s);
}

Vec3 stabilise_couple(const StabiliseLawParams& params, const arm::ServicerArmParams& servicer, StabiliseState& state,
                      const arm::JointVector& joint_angles_rad, const Quat& q_inertial_from_body,
                      const Vec3& omega_body_radps, double t_s) {
  if (!state.started()) {
    state.started_s = t_s;
    state.inertia_kgm2 = composite_inertia(servicer, joint_angles_rad, params.target).inertia_kgm2;
    state.momentum0_inertial_Nms = q_inertial_from_body * (state.inertia_kgm2 * omega_body_radps);
  }
  const Vec3 momentum_inertial = q_inertial_from_body * (state.inertia_kgm2 * omega_body_radps);
  const model::StabiliseParams& p = params.stabilise;
  const double share = stabilise_reference_share(p, state, t_s);
  const Vec3 reference = share * state.momentum0_inertial_Nms;
  const Vec3 reference_rate = share > 0.0 ? Vec3(-state.momentum0_inertial_Nms / p.duration_s) : Vec3::Zero();
  Vec3 couple_inertial;
  if (p.law == model::StabiliseLaw::kHinf) {
    for (int i = 0; i < 3; ++i)
      couple_inertial(i) = reference_rate(i) + step_loop(params.hinf_loops[static_cast<std::size_t>(i)],
                                                         state.loops[static_cast<std::size_t>(i)],
                                                         state.impulse_reference_Nms2(i) - state.impulse_Nms2(i));
    state.impulse_Nms2 += params.period_s * momentum_inertial;
    state.impulse_reference_Nms2 += params.period_s * reference;
  } else {
    couple_inertial = reference_rate + p.bandwidth_radps * (reference - momentum_inertial);
  }
  return q_inertial_from_body.conjugate() * couple_inertial;
}

}  // namespace chaser::flight
