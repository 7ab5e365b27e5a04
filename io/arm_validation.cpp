// chaser.arm against itself and the mission it serves: each link's inertia physical and its limits
// ordered, the torque limits consistent with each other and with the drives' friction, the grasping
// fixture on the target's surface, and the fixture within the arm's reach from the capture point.
// No multibody model is built from a scenario that fails here.
#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "io/scenario_sections.hpp"
#include "model/keep_out.hpp"

namespace chaser::io {
namespace {

// A fixture "on" the keep-out volume's surface: within this of it, either way (the volume is the
// target's envelope to a few centimetres).
constexpr double kFixtureSurfaceToleranceM = 0.05;  // [m]
// The arm must reach the fixture with its links no more than this fraction of their length apart:
// a stretched arm is at a singularity, with no motion left along its own line.
constexpr double kUsableReachFraction = 0.95;

// Principal moments of one body: each at most the sum of the other two.
void check_principal_moments(const Vec3& I, const std::string& path, Diagnostics& d) {
  if (!d.clean(path)) return;
  const double largest = I.maxCoeff();
  if (largest > (I.sum() - largest) * (1.0 + 1e-9))
    d.add(path, fmt::format("principal moments [{}, {}, {}] violate the triangle inequality: the largest must be "
                            "<= the sum of the other two",
                            format_number(I.x()), format_number(I.y()), format_number(I.z())));
}

void check_links(const model::ArmParams& arm, Diagnostics& d) {
  for (int i = 0; i < model::kArmJoints; ++i) {
    const model::ArmLinkParams& link = arm.links[static_cast<std::size_t>(i)];
    const std::string base = fmt::format("chaser.arm.links.{}", i);
    check_principal_moments(link.inertia_kgm2, base + ".inertia_kgm2", d);
    if (d.clean(base + ".lower_deg") && d.clean(base + ".upper_deg") && !(link.lower_rad < link.upper_rad))
      d.add(base + ".upper_deg", fmt::format("must be greater than lower_deg {} (got {})",
                                             format_number(link.lower_rad * 180.0 / std::numbers::pi),
                                             format_number(link.upper_rad * 180.0 / std::numbers::pi)));
    const double stowed = arm.stowed_rad[static_cast<std::size_t>(i)];
    if (d.clean(base + ".lower_deg") && d.clean(base + ".upper_deg") && d.clean("chaser.arm.stowed_deg") &&
        link.lower_rad < link.upper_rad && !(stowed >= link.lower_rad && stowed <= link.upper_rad))
      d.add(fmt::format("chaser.arm.stowed_deg.{}", i),
            fmt::format("must be within the joint's limits [{:g}, {:g}] deg (got {:g})",
                        link.lower_rad * 180.0 / std::numbers::pi, link.upper_rad * 180.0 / std::numbers::pi,
                        stowed * 180.0 / std::numbers::pi));
    if (d.clean(base + ".friction_Nm") && d.clean("chaser.arm.torque_repeated_peak_Nm") &&
        !(link.friction_Nm < arm.torque_repeated_peak_Nm))
      d.add(base + ".friction_Nm", fmt::format("must be less than torque_repeated_peak_Nm {}: the drive could not "
                                               "overcome it (got {})",
                                               format_number(arm.torque_repeated_peak_Nm),
                                               format_number(link.friction_Nm)));
  }
  check_principal_moments(arm.gripper.inertia_kgm2, "chaser.arm.gripper.inertia_kgm2", d);
  if (d.clean("chaser.arm.torque_repeated_peak_Nm") && d.clean("chaser.arm.torque_momentary_Nm") &&
      arm.torque_repeated_peak_Nm > arm.torque_momentary_Nm)
    d.add("chaser.arm.torque_repeated_peak_Nm",
          fmt::format("must be at most torque_momentary_Nm {} (got {})", format_number(arm.torque_momentary_Nm),
                      format_number(arm.torque_repeated_peak_Nm)));
}

// The arm's length from joint 1 to the tool point, stretched: the sum of the offsets after joint 1.
double reach_m(const model::ArmParams& arm) {
  double length = arm.gripper.position_link7_m.norm();
  for (int i = 1; i < model::kArmJoints; ++i) length += arm.links[static_cast<std::size_t>(i)].joint_position_parent_m.norm();
  return length;
}

// The arm serves a capture: the fixture (target.body.grasp_point_target_m) on the target's surface,
// and within reach of joint 1 with the chaser at the capture point in its capture attitude.
void check_capture_geometry(const model::Scenario& s, Diagnostics& d) {
  if (!s.target.body || !s.guidance.synchronised) {
    d.add("chaser.arm", "needs target.body (its grasp_point_target_m, the fixture) and guidance.synchronised (the "
                        "capture point and attitude it reaches from)");
    return;
  }
  const model::TargetBodyParams& body = *s.target.body;
  const char* fixture_key = "target.body.grasp_point_target_m";
  if (!d.clean(fixture_key) || !d.clean("target.body.capture_point_target_m") || !d.clean("chaser.com_body_m") ||
      !d.clean("guidance.synchronised"))
    return;
  if (!body.keep_out.empty() && d.clean("target.body.keep_out")) {
    const double distance_m = model::keep_out_distance_m(body.keep_out, body.grasp_point_target_m);
    // A berthing drogue's socket lies its depth inside the surface, at the bottom of the drogue.
    const double recess_m = s.capture && s.capture->berthing ? s.capture->berthing->drogue_depth_m : 0.0;
    if (std::abs(distance_m + recess_m) > kFixtureSurfaceToleranceM) {
      if (recess_m > 0.0)
        d.add(fixture_key, fmt::format("with capture.berthing must lie capture.berthing.drogue_depth_m = {} m inside "
                                       "the target's surface (target.body.keep_out) to within {} m, at the drogue's "
                                       "socket: it is {:.3g} m {} it",
                                       format_number(recess_m), format_number(kFixtureSurfaceToleranceM),
                                       std::abs(distance_m), distance_m > 0 ? "outside" : "inside"));
      else
        d.add(fixture_key, fmt::format("must lie on the target's surface (target.body.keep_out) to within {} m for the "
                                       "arm to grasp it: it is {:.3g} m {} it",
                                       format_number(kFixtureSurfaceToleranceM), std::abs(distance_m),
                                       distance_m > 0 ? "outside" : "inside"));
    }
    if (!d.clean(fixture_key)) return;  // the reach to a misplaced fixture would be a second error for one problem
  }
  const model::ArmParams& arm = *s.chaser.arm;
  const Vec3 joint1_from_com_body_m = arm.mount_body_m + arm.links[0].joint_position_parent_m - s.chaser.com_body_m;
  const Vec3 joint1_target_m =
      body.capture_point_target_m + s.guidance.synchronised->q_target_from_body * joint1_from_com_body_m;
  const double distance_m = (body.grasp_point_target_m - joint1_target_m).norm();
  const double usable_m = kUsableReachFraction * reach_m(arm);
  if (distance_m > usable_m)
    d.add("chaser.arm", fmt::format("cannot reach the fixture from the capture point: joint 1 is {:.3g} m from "
                                    "target.body.grasp_point_target_m, more than {} of the arm's {:.3g} m ({:.3g} m)",
                                    distance_m, format_number(kUsableReachFraction), reach_m(arm), usable_m));
}

}  // namespace

void validate_arm(const model::Scenario& s, Diagnostics& d) {
  if (!s.chaser.arm || !d.clean("chaser.arm")) return;
  check_links(*s.chaser.arm, d);
  check_capture_geometry(s, d);
}

}  // namespace chaser::io
