#include "plant/multibody/mjcf.hpp"

#include <cmath>
#include <iterator>

#include <fmt/format.h>

#include "model/hub_mass_properties.hpp"

namespace chaser::plant::multibody {

namespace {

std::string vec(const Vec3& v) { return fmt::format("{} {} {}", v.x(), v.y(), v.z()); }
std::string quat(const Quat& q) { return fmt::format("{} {} {} {}", q.w(), q.x(), q.y(), q.z()); }

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

// Contact is between the jaws (palm and fingers) and the fixture's lip only, as three predefined
// pairs (<contact><pair>, collision="predefined"): MuJoCo then skips its broad phase over all the
// bodies, which cost ~6 % of a reach run at every RK4 stage with the jaws far from the lip; a pair's
// contact parameters are those MuJoCo would mix from its geoms. No geom (jaws, lip, the target's
// shape) is in the dynamic pass.
constexpr const char* kNoDynamicContact = "contype=\"0\" conaffinity=\"0\"";

// The gripper's body: the gripper less its jaws' fingers with the jaws (palm and the two sliding
// fingers, model/arm.hpp's JawParams), or the whole gripper.
void append_gripper(std::string& out, const model::MultibodySceneParams& scene, const std::string& indent) {
  const model::GripperParams& g = scene.arm.gripper;
  fmt::format_to(std::back_inserter(out), "{}<body name=\"gripper\" pos=\"0 0 0\">\n", indent);
  if (!scene.grasp_contact) {
    fmt::format_to(std::back_inserter(out),
                   "{0}  <inertial pos=\"{1}\" mass=\"{2}\" diaginertia=\"{3}\"/>\n"
                   "{0}  <site name=\"tool\" pos=\"{4}\"/>\n",
                   indent, vec(g.com_link7_m), g.mass_kg, vec(g.inertia_kgm2), vec(g.position_link7_m));
    if (scene.berth_contact)  // the capture probe's tip, centred on the tool point
      fmt::format_to(std::back_inserter(out),
                     "{0}  <geom name=\"probe_tip\" type=\"sphere\" pos=\"{1}\" size=\"{2}\" friction=\"{3} 0.005 0.0001\" {4}/>\n",
                     indent, vec(g.position_link7_m), scene.drogue.tip_radius_m, scene.drogue.friction, kNoDynamicContact);
    fmt::format_to(std::back_inserter(out), "{}</body>\n", indent);
    return;
  }
  const model::JawParams& jaws = g.jaws;
  const model::GripperBodies bodies = model::gripper_bodies(g);
  const Vec3 h = jaws.finger_half_extents_m;
  // The palm: a plate across the jaws' mouth, its face palm_setback_m behind the tool point.
  const double palm_half_thickness_m = 0.005;
  const Vec3 palm_centre = g.position_link7_m - Vec3(jaws.palm_setback_m + palm_half_thickness_m, 0.0, 0.0);
  const Vec3 palm_half = Vec3(palm_half_thickness_m, h.y(), jaws.open_half_gap_m + 2.0 * h.z());
  fmt::format_to(std::back_inserter(out),
                 "{0}  <inertial pos=\"{1}\" mass=\"{2}\" fullinertia=\"{3}\"/>\n"
                 "{0}  <site name=\"tool\" pos=\"{4}\"/>\n"
                 "{0}  <geom name=\"palm\" type=\"box\" pos=\"{5}\" size=\"{6}\" {7}/>\n",
                 indent, vec(bodies.body.com_body_m), bodies.body.mass_kg, full_inertia(bodies.body.inertia_kgm2),
                 vec(g.position_link7_m), vec(palm_centre), vec(palm_half), kNoDynamicContact);
  const char* names[2] = {"finger_a", "finger_b"};
  for (int i = 0; i < 2; ++i) {
    const model::BodyMassProperties& f = bodies.fingers[static_cast<std::size_t>(i)];
    const double side = i == 0 ? 1.0 : -1.0;
    // Each finger's frame at its CoM, open; it slides towards the tool point (along -side z) by up
    // to the open gap, where its inner face reaches the tool's xy plane.
    fmt::format_to(std::back_inserter(out),
                   "{0}  <body name=\"{1}\" pos=\"{2}\">\n"
                   "{0}    <inertial pos=\"0 0 0\" mass=\"{3}\" diaginertia=\"{4}\"/>\n"
                   "{0}    <joint name=\"{1}\" type=\"slide\" axis=\"0 0 {5}\" limited=\"true\" range=\"0 {6}\""
                   " damping=\"{7}\"/>\n"
                   "{0}    <geom name=\"{1}\" type=\"box\" size=\"{8}\" {9}/>\n"
                   "{0}  </body>\n",
                   indent, names[i], vec(f.com_body_m), f.mass_kg, vec(f.inertia_kgm2.diagonal()), -side,
                   jaws.open_half_gap_m, jaws.servo_damping_Nspm, vec(h), kNoDynamicContact);
  }
  fmt::format_to(std::back_inserter(out), "{}</body>\n", indent);
}

// The drogue (scene.berth_contact) on the target's body: each plate's inner face on the cone's
// generator from the throat (x = 0, the socket, radius throat_radius_m) to the mouth (x = -depth_m,
// mouth_radius_m), at its azimuth about the fixture's x; the plates a little wider than the mouth's
// polygon's sides so that no tip passes between them; the floor's face at x = tip_radius_m, where
// the tip's centre is at the socket.
void append_drogue(std::string& out, const model::MultibodySceneParams& scene) {
  const model::DrogueParams& d = scene.drogue;
  constexpr double kHalfThicknessM = 0.005;
  const double pi = 3.14159265358979323846;
  const double dr = d.mouth_radius_m - d.throat_radius_m;
  const double length = std::hypot(d.depth_m, dr);
  const Vec3 along_xr(-d.depth_m / length, dr / length, 0.0);   // the generator, throat to mouth: (x, r)
  const Vec3 outward_xr(dr / length, d.depth_m / length, 0.0);  // its normal away from the cavity
  const double half_width = 1.1 * d.mouth_radius_m * std::tan(pi / d.plates);
  const Quat q_target_from_fixture = scene.q_target_from_fixture.normalized();
  for (int k = 0; k < d.plates; ++k) {
    const double phi = 2.0 * pi * k / d.plates;
    const Vec3 radial(0.0, std::cos(phi), std::sin(phi));
    const Vec3 g = along_xr.x() * Vec3::UnitX() + along_xr.y() * radial;
    const Vec3 n = outward_xr.x() * Vec3::UnitX() + outward_xr.y() * radial;
    const Vec3 t(0.0, -std::sin(phi), std::cos(phi));  // g x t = n
    Mat3 fixture_from_plate;
    fixture_from_plate << g, t, n;
    const Vec3 mid = 0.5 * (-d.depth_m) * Vec3::UnitX() + 0.5 * (d.mouth_radius_m + d.throat_radius_m) * radial;
    const Vec3 centre = mid + kHalfThicknessM * n;
    fmt::format_to(std::back_inserter(out),
                   "      <geom name=\"drogue{}\" type=\"box\" pos=\"{}\" quat=\"{}\" size=\"{} {} {}\" friction=\"{} 0.005 0.0001\" {}/>\n",
                   k, vec(scene.fixture_target_m + q_target_from_fixture * centre),
                   quat((q_target_from_fixture * Quat(fixture_from_plate)).normalized()), 0.5 * length, half_width,
                   kHalfThicknessM, d.friction, kNoDynamicContact);
  }
  const Vec3 floor = (d.tip_radius_m + kHalfThicknessM) * Vec3::UnitX();
  const double floor_half = d.throat_radius_m + 0.02;
  fmt::format_to(std::back_inserter(out),
                 "      <geom name=\"drogue_floor\" type=\"box\" pos=\"{}\" quat=\"{}\" size=\"{} {} {}\" friction=\"{} 0.005 0.0001\" {}/>\n",
                 vec(scene.fixture_target_m + q_target_from_fixture * floor), quat(q_target_from_fixture), kHalfThicknessM,
                 floor_half, floor_half, d.friction, kNoDynamicContact);
}

}  // namespace

std::string mjcf_of(const model::MultibodySceneParams& scene) {
  const model::ArmParams& arm = scene.arm;
  std::string out;
  fmt::format_to(std::back_inserter(out),
                 "<mujoco model=\"chaser_scene\">\n"
                 "  <compiler angle=\"radian\"/>\n"
                 "  <option timestep=\"{}\" integrator=\"{}\" gravity=\"0 0 0\"{}>\n"
                 "{}"
                 "  </option>\n"
                 "  <worldbody>\n"
                 "    <body name=\"hub\" pos=\"0 0 0\">\n"
                 "      <freejoint name=\"hub_free\"/>\n"
                 "      <inertial pos=\"0 0 0\" mass=\"{}\" fullinertia=\"{}\"/>\n",
                 scene.timestep_s, scene.integrator,
                 scene.grasp_contact || scene.berth_contact ? " collision=\"predefined\"" : "",
                 scene.grasp_contact || scene.berth_contact ? "" : "    <flag contact=\"disable\"/>\n",
                 scene.hub_mass_kg, full_inertia(scene.hub_inertia_kgm2));
  for (int i = 0; i < model::kArmJoints; ++i) {
    const model::ArmLinkParams& link = arm.links[static_cast<std::size_t>(i)];
    // The hub's frame is at its CoM: the mount moves by the CoM's offset from the reference point.
    const Vec3 position = i == 0 ? Vec3(arm.mount_body_m - scene.hub_com_body_m + link.joint_position_parent_m)
                                 : link.joint_position_parent_m;
    append_link(out, i, link, position, 3 + i);
  }
  const std::string indent(static_cast<std::size_t>(2 * (3 + model::kArmJoints)), ' ');
  append_gripper(out, scene, indent);
  for (int i = model::kArmJoints - 1; i >= 0; --i)
    fmt::format_to(std::back_inserter(out), "{}</body>\n", std::string(static_cast<std::size_t>(2 * (3 + i)), ' '));
  fmt::format_to(std::back_inserter(out),
                 "    </body>\n"
                 "    <body name=\"target\" pos=\"{}\">\n"
                 "      <freejoint name=\"target_free\"/>\n"
                 "      <inertial pos=\"0 0 0\" mass=\"{}\" fullinertia=\"{}\"/>\n",
                 vec(scene.target_position_m), scene.target_mass_kg, full_inertia(scene.target_inertia_kgm2));
  for (std::size_t i = 0; i < scene.target_shape.size(); ++i)
    fmt::format_to(std::back_inserter(out),
                   "      <geom name=\"shape{}\" type=\"box\" pos=\"{}\" size=\"{}\" {}/>\n", i,
                   vec(scene.target_shape[i].centre_target_m), vec(scene.target_shape[i].half_extents_m), kNoDynamicContact);
  if (scene.grasp_contact)  // the fixture's lip, centred on the grasp point in the grasp pose's axes
    fmt::format_to(std::back_inserter(out),
                   "      <geom name=\"fixture\" type=\"box\" pos=\"{}\" quat=\"{}\" size=\"{}\" {}/>\n",
                   vec(scene.fixture_target_m), quat(scene.q_target_from_fixture.normalized()),
                   vec(scene.fixture.half_extents_m), kNoDynamicContact);
  if (scene.berth_contact) append_drogue(out, scene);
  out +=
      "    </body>\n"
      "  </worldbody>\n"
      "  <actuator>\n";
  // The fingers' position servos first: MuJoCo 2.2 wants the actuators without state before those with.
  if (scene.grasp_contact) {  // ctrl 0 open, open_half_gap_m closed
    const model::JawParams& jaws = arm.gripper.jaws;
    for (const char* finger : {"finger_a", "finger_b"})
      fmt::format_to(std::back_inserter(out),
                     "    <position name=\"{0}\" joint=\"{0}\" kp=\"{1}\" ctrllimited=\"true\" ctrlrange=\"0 {2}\""
                     " forcelimited=\"true\" forcerange=\"{3} {4}\"/>\n",
                     finger, jaws.servo_stiffness_Npm, jaws.open_half_gap_m, -jaws.closing_force_N,
                     jaws.closing_force_N);
  }
  // The inner joint-torque loops: the torque applied follows the demand (ctrl) through
  // 1 / (s / w + 1), MuJoCo's filter dynamics (act' = (ctrl - act) / T, T = 1 / w, integrated with
  // the state), the force the activation (gain 1, no bias).
  for (int i = 1; i <= model::kArmJoints; ++i)
    fmt::format_to(std::back_inserter(out),
                   "    <general name=\"motor{0}\" joint=\"joint{0}\" gear=\"1\" dyntype=\"filter\" dynprm=\"{3}\""
                   " gainprm=\"1\" biastype=\"none\" ctrllimited=\"true\" ctrlrange=\"{1} {2}\"/>\n",
                   i, -arm.torque_momentary_Nm, arm.torque_momentary_Nm, 1.0 / arm.torque_loop_bandwidth_radps);
  out += "  </actuator>\n";
  if (scene.grasp_contact)
    out +=
        "  <contact>\n"
        "    <pair geom1=\"palm\" geom2=\"fixture\"/>\n"
        "    <pair geom1=\"finger_a\" geom2=\"fixture\"/>\n"
        "    <pair geom1=\"finger_b\" geom2=\"fixture\"/>\n"
        "  </contact>\n";
  if (scene.berth_contact) {
    out += "  <contact>\n";
    for (int k = 0; k < scene.drogue.plates; ++k)
      fmt::format_to(std::back_inserter(out), "    <pair geom1=\"probe_tip\" geom2=\"drogue{}\"/>\n", k);
    out += "    <pair geom1=\"probe_tip\" geom2=\"drogue_floor\"/>\n  </contact>\n";
  }
  const bool equality = scene.arm_locks || scene.grasp_weld || scene.berth_contact;
  if (equality) out += "  <equality>\n";
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
  if (scene.berth_contact)  // inactive: engaged by the latches at the pose of that moment, then drawn to the mated one
    fmt::format_to(std::back_inserter(out),
                   "    <weld name=\"berth\" body1=\"gripper\" body2=\"target\" active=\"false\" solref=\"{0} 1\""
                   " solimp=\"{1} {1} 0.001\"/>\n",
                   scene.lock_timeconst_s, scene.lock_impedance);
  if (equality) out += "  </equality>\n";
  out += "</mujoco>\n";
  return out;
}

}  // namespace chaser::plant::multibody
