#include "model/arm.hpp"

#include <numbers>

namespace chaser::model {

Vec3 tube_inertia_kgm2(double mass_kg, double length_m, double radius_m) {
  const double transverse = mass_kg * (radius_m * radius_m / 2.0 + length_m * length_m / 12.0);
  return Vec3(mass_kg * radius_m * radius_m, transverse, transverse);
}

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// A link that is a tube of `length_m` from its joint along +x, its joint turning about `axis`.
ArmLinkParams tube_link(const Vec3& joint_position_parent_m, const Vec3& axis, double mass_kg, double length_m,
                        double radius_m, double limit_deg) {
  ArmLinkParams link;
  link.joint_position_parent_m = joint_position_parent_m;
  link.joint_axis = axis;
  link.mass_kg = mass_kg;
  link.com_link_m = Vec3(length_m / 2.0, 0.0, 0.0);
  link.inertia_kgm2 = tube_inertia_kgm2(mass_kg, length_m, radius_m);
  link.lower_rad = -limit_deg * kDeg;
  link.upper_rad = limit_deg * kDeg;
  // A harmonic drive's friction is of the order of 1 % of its rated torque (176 N m): 2 N m. Its
  // rotor, ~1e-4 kg m^2 behind a 1:70 gear, adds ~0.5 kg m^2 about the joint axis.
  link.friction_Nm = 2.0;
  link.armature_kgm2 = 0.5;
  return link;
}

}  // namespace

ArmParams default_arm() {
  // Rolls turn +/-170 deg and pitches +/-120 deg, the ranges of the light-weight S-R-S arms; the
  // drives' housings are 0.2 m tubes of 8 kg, the upper arm and forearm carbon tubes of 1.1 m and
  // 1.0 m (18 and 16 kg with their harness), the wrist 0.1 m housings of 6 kg.
  const Vec3 roll = Vec3::UnitX(), pitch = Vec3::UnitZ();
  ArmParams arm;
  arm.links[0] = tube_link(Vec3::Zero(), roll, 8.0, 0.2, 0.10, 170.0);            // shoulder roll
  arm.links[1] = tube_link(Vec3(0.2, 0.0, 0.0), pitch, 8.0, 0.2, 0.10, 120.0);    // shoulder pitch
  arm.links[2] = tube_link(Vec3(0.2, 0.0, 0.0), roll, 18.0, 1.1, 0.08, 170.0);    // upper arm roll
  arm.links[3] = tube_link(Vec3(1.1, 0.0, 0.0), pitch, 8.0, 0.2, 0.10, 120.0);    // elbow pitch
  arm.links[4] = tube_link(Vec3(0.2, 0.0, 0.0), roll, 16.0, 1.0, 0.08, 170.0);    // forearm roll
  arm.links[5] = tube_link(Vec3(1.0, 0.0, 0.0), pitch, 6.0, 0.1, 0.08, 120.0);    // wrist pitch
  arm.links[6] = tube_link(Vec3(0.1, 0.0, 0.0), roll, 6.0, 0.1, 0.08, 170.0);     // wrist roll
  arm.gripper.position_link7_m = Vec3(0.3, 0.0, 0.0);  // 3.1 m from the shoulder when stretched
  arm.gripper.mass_kg = 10.0;
  arm.gripper.com_link7_m = Vec3(0.15, 0.0, 0.0);
  arm.gripper.inertia_kgm2 = tube_inertia_kgm2(10.0, 0.3, 0.1);
  return arm;
}

}  // namespace chaser::model
