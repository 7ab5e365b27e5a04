// chaser.arm: the servicer's 7-DOF arm and gripper (model/arm.hpp). Optional; the checks that need
// other keys (a physical inertia per link, ordered limits, the torque limits against each other and
// the friction, the fixture on the target, the reach from the capture point) are in
// io/arm_validation.cpp.
#include <fmt/format.h>

#include "io/scenario_sections.hpp"

namespace chaser::io {
namespace {

constexpr double kMaxArmOffsetM = 20.0;     // [m] a link's offset or CoM: no space arm is longer
constexpr double kMaxLinkMassKg = 1e4;      // [kg]
constexpr double kMaxJointAngleDeg = 360.0; // [deg] a joint's limit, either way
constexpr double kMaxTorqueNm = 1e5;        // [N m]
// [rad/s] The scene's RK4 at 1 ms follows a first-order lag's step response to 3e-5 of the step
// at 300 rad/s and to 0.7 % at 1,000 rad/s (its stability ends at 2,785 rad/s).
constexpr double kMaxTorqueLoopBandwidthRadps = 1000.0;

void read_link(const YAML::Node& node, const std::string& path, model::ArmLinkParams& out, Diagnostics& diag) {
  MapReader m(node, path, diag);
  const Range offset = Range::closed(-kMaxArmOffsetM, kMaxArmOffsetM);
  m.vec3("joint_position_m", offset, out.joint_position_parent_m);
  m.direction("joint_axis", out.joint_axis);
  m.number("mass_kg", Range::left_open(0.0, kMaxLinkMassKg), out.mass_kg);
  m.vec3("com_m", offset, out.com_link_m);
  m.vec3("inertia_kgm2", Range::left_open(0.0, 1e6), out.inertia_kgm2);
  m.angle_deg("lower_deg", Range::closed(-kMaxJointAngleDeg, kMaxJointAngleDeg), out.lower_rad);
  m.angle_deg("upper_deg", Range::closed(-kMaxJointAngleDeg, kMaxJointAngleDeg), out.upper_rad);
  m.number("friction_Nm", Range::closed(0.0, kMaxTorqueNm), out.friction_Nm);
  m.number("damping_Nms", Range::closed(0.0, kMaxTorqueNm), out.damping_Nms);
  m.number("armature_kgm2", Range::closed(0.0, 1e4), out.armature_kgm2);
  m.finish();
}

void read_gripper(MapReader& m, model::GripperParams& out) {
  const Range offset = Range::closed(-kMaxArmOffsetM, kMaxArmOffsetM);
  m.vec3("tool_position_m", offset, out.position_link7_m);
  m.number("mass_kg", Range::left_open(0.0, kMaxLinkMassKg), out.mass_kg);
  m.vec3("com_m", offset, out.com_link7_m);
  m.vec3("inertia_kgm2", Range::left_open(0.0, 1e6), out.inertia_kgm2);
  if (m.has("jaws")) read_section(m, "jaws", [&](MapReader& j) {  // optional: model/arm.hpp's default
    model::JawParams& jaws = out.jaws;
    j.number("open_half_gap_m", Range::left_open(0.0, 0.5), jaws.open_half_gap_m);
    j.vec3("finger_half_extents_m", Range::left_open(0.0, 0.5), jaws.finger_half_extents_m);
    j.number("finger_mass_kg", Range::left_open(0.0, kMaxLinkMassKg), jaws.finger_mass_kg);
    j.number("closing_force_N", Range::left_open(0.0, 1e4), jaws.closing_force_N);
    j.number("servo_stiffness_Npm", Range::left_open(0.0, 1e7), jaws.servo_stiffness_Npm);
    j.number("servo_damping_Nspm", Range::left_open(0.0, 1e5), jaws.servo_damping_Nspm);
    j.number("palm_setback_m", Range::left_open(0.0, 0.5), jaws.palm_setback_m);
  });
}

void read_arm(MapReader& r, model::ArmParams& out) {
  r.vec3("mount_body_m", Range::closed(-kMaxLayoutExtentM, kMaxLayoutExtentM), out.mount_body_m);
  r.number("torque_repeated_peak_Nm", Range::left_open(0.0, kMaxTorqueNm), out.torque_repeated_peak_Nm);
  r.number("torque_momentary_Nm", Range::left_open(0.0, kMaxTorqueNm), out.torque_momentary_Nm);
  // Optional (model/arm.hpp's default).
  if (r.has("brake_holding_torque_Nm"))
    r.number("brake_holding_torque_Nm", Range::left_open(0.0, kMaxTorqueNm), out.brake_holding_torque_Nm);
  if (r.has("torque_loop_bandwidth_radps"))
    r.number("torque_loop_bandwidth_radps", Range::closed(1.0, kMaxTorqueLoopBandwidthRadps),
             out.torque_loop_bandwidth_radps);
  const auto list = r.child("links", fmt::format("a list of {} links, base to tip", model::kArmJoints));
  if (list) {
    if (!list->IsSequence() || list->size() != static_cast<std::size_t>(model::kArmJoints)) {
      r.diagnostics().add(r.path_of("links"), fmt::format("must be a list of {} links, base to tip (got {})",
                                                          model::kArmJoints, describe_node(*list)));
    } else {
      for (std::size_t i = 0; i < list->size(); ++i)
        read_link((*list)[i], join_path(r.path_of("links"), std::to_string(i)), out.links[i], r.diagnostics());
    }
  }
  read_section(r, "gripper", [&](MapReader& m) { read_gripper(m, out.gripper); });
  // The stowed angles (optional: model/arm.hpp's default fold), in degrees, base to tip.
  if (r.has("stowed_deg")) {
    const auto list = r.child("stowed_deg", fmt::format("a list of {} angles [deg], base to tip", model::kArmJoints));
    const std::string path = r.path_of("stowed_deg");
    if (list && (!list->IsSequence() || list->size() != static_cast<std::size_t>(model::kArmJoints))) {
      r.diagnostics().add(path, fmt::format("must be a list of {} angles [deg], base to tip (got {})", model::kArmJoints,
                                            describe_node(*list)));
    } else if (list) {
      for (std::size_t i = 0; i < list->size(); ++i) {
        double deg = 0.0;
        if (read_number((*list)[i], join_path(path, std::to_string(i)),
                        Range::closed(-kMaxJointAngleDeg, kMaxJointAngleDeg), r.diagnostics(), deg))
          out.stowed_rad[i] = deg * model::kArmDegToRad;
      }
    }
  }
}

}  // namespace

void read_optional_arm(MapReader& r, std::optional<model::ArmParams>& out) {
  if (!r.has("arm")) return;
  out.emplace();
  read_section(r, "arm", [&](MapReader& m) { read_arm(m, *out); });
}

}  // namespace chaser::io
