#include "plant/multibody/mjcf.hpp"

#include <iterator>

#include <fmt/format.h>

namespace chaser::plant::multibody {

namespace {

std::string vec(const Vec3& v) { return fmt::format("{} {} {}", v.x(), v.y(), v.z()); }

// MuJoCo's fullinertia: "ixx iyy izz ixy ixz iyz".
std::string full_inertia(const Mat3& I) {
  return fmt::format("{} {} {} {} {} {}", I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2), I(1, 2));
}

void append_link(std::string& out, int index, const model::ArmLinkParams& link, const Vec3& position_parent_m,
                 int depth) {
  const std::string indent(static_cast<std::size_t>(2 * depth), ' ');
  fmt::format_to(std::back_inserter(out),
                 "{0}<body name=\"link{1}\" pos=\"{2}\">\n"
                 "{0}  <inertial pos=\"{3}\" mass=\"{4}\" diaginertia=\"{5}\"/>\n"
                 "{0}  <joint name=\"joint{1}\" type=\"hinge\" axis=\"{6}\" limited=\"true\" range=\"{7} {8}\""
                 " frictionloss=\"{9}\" damping=\"{10}\" armature=\"{11}\"/>\n",
                 indent, index + 1, vec(position_parent_m), vec(link.com_link_m), link.mass_kg, vec(link.inertia_kgm2),
                 vec(link.joint_axis), link.lower_rad, link.upper_rad, link.friction_Nm, link.damping_Nms,
                 link.armature_kgm2);
}

}  // namespace

std::string mjcf_of(const model::MultibodySceneParams& scene) {
  const model::ArmParams& arm = scene.arm;
  std::string out;
  fmt::format_to(std::back_inserter(out),
                 "<mujoco model=\"chaser_scene\">\n"
                 "  <compiler angle=\"radian\"/>\n"
                 "  <option timestep=\"{}\" integrator=\"{}\" gravity=\"0 0 0\">\n"
                 "    <flag contact=\"disable\"/>\n"
                 "  </option>\n"
                 "  <worldbody>\n"
                 "    <body name=\"hub\" pos=\"0 0 0\">\n"
                 "      <freejoint name=\"hub_free\"/>\n"
                 "      <inertial pos=\"0 0 0\" mass=\"{}\" fullinertia=\"{}\"/>\n",
                 scene.timestep_s, scene.integrator, scene.hub_mass_kg, full_inertia(scene.hub_inertia_kgm2));
  for (int i = 0; i < model::kArmJoints; ++i) {
    const model::ArmLinkParams& link = arm.links[static_cast<std::size_t>(i)];
    // The hub's frame is at its CoM: the mount moves by the CoM's offset from the reference point.
    const Vec3 position = i == 0 ? Vec3(arm.mount_body_m - scene.hub_com_body_m + link.joint_position_parent_m)
                                 : link.joint_position_parent_m;
    append_link(out, i, link, position, 3 + i);
  }
  const std::string indent(static_cast<std::size_t>(2 * (3 + model::kArmJoints)), ' ');
  fmt::format_to(std::back_inserter(out),
                 "{0}<body name=\"gripper\" pos=\"0 0 0\">\n"
                 "{0}  <inertial pos=\"{1}\" mass=\"{2}\" diaginertia=\"{3}\"/>\n"
                 "{0}  <site name=\"tool\" pos=\"{4}\"/>\n"
                 "{0}</body>\n",
                 indent, vec(arm.gripper.com_link7_m), arm.gripper.mass_kg, vec(arm.gripper.inertia_kgm2),
                 vec(arm.gripper.position_link7_m));
  for (int i = model::kArmJoints - 1; i >= 0; --i)
    fmt::format_to(std::back_inserter(out), "{}</body>\n", std::string(static_cast<std::size_t>(2 * (3 + i)), ' '));
  fmt::format_to(std::back_inserter(out),
                 "    </body>\n"
                 "    <body name=\"target\" pos=\"{}\">\n"
                 "      <freejoint name=\"target_free\"/>\n"
                 "      <inertial pos=\"0 0 0\" mass=\"{}\" fullinertia=\"{}\"/>\n"
                 "    </body>\n"
                 "  </worldbody>\n"
                 "  <actuator>\n",
                 vec(scene.target_position_m), scene.target_mass_kg, full_inertia(scene.target_inertia_kgm2));
  for (int i = 1; i <= model::kArmJoints; ++i)
    fmt::format_to(std::back_inserter(out),
                   "    <motor name=\"motor{0}\" joint=\"joint{0}\" gear=\"1\" ctrllimited=\"true\" ctrlrange=\"{1} {2}\"/>\n",
                   i, -arm.torque_momentary_Nm, arm.torque_momentary_Nm);
  out += "  </actuator>\n";
  if (scene.arm_locks || scene.grasp_weld) out += "  <equality>\n";
  if (scene.arm_locks) {
    // q_i = stowed_i: polycoef's constant term with joint2 absent (MuJoCo's <equality><joint>).
    for (int i = 0; i < model::kArmJoints; ++i)
      fmt::format_to(std::back_inserter(out),
                     "    <joint name=\"lock{0}\" joint1=\"joint{0}\" polycoef=\"{1} 0 0 0 0\" solref=\"{2} 1\""
                     " solimp=\"{3} {3} 0.001\"/>\n",
                     i + 1, arm.stowed_rad[static_cast<std::size_t>(i)], scene.lock_timeconst_s, scene.lock_impedance);
  }
  if (scene.grasp_weld)  // inactive: engaged with the pose of that moment (plant/multibody/weld.hpp)
    fmt::format_to(std::back_inserter(out),
                   "    <weld name=\"grasp\" body1=\"gripper\" body2=\"target\" active=\"false\" solref=\"{0} 1\""
                   " solimp=\"{1} {1} 0.001\"/>\n",
                   scene.lock_timeconst_s, scene.lock_impedance);
  if (scene.arm_locks || scene.grasp_weld) out += "  </equality>\n";
  out += "</mujoco>\n";
  return out;
}

}  // namespace chaser::plant::multibody
