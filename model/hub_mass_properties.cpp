#include "model/hub_mass_properties.hpp"

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include "core/point_inertia.hpp"

namespace chaser::model {

namespace {

BodyMassProperties in_body_axes(double mass_kg, const Vec3& com_link_m, const Vec3& principal_kgm2,
                                const Vec3& frame_body_m, const Mat3& body_from_link) {
  return {.mass_kg = mass_kg,
          .com_body_m = frame_body_m + body_from_link * com_link_m,
          .inertia_kgm2 = body_from_link * principal_kgm2.asDiagonal() * body_from_link.transpose()};
}

}  // namespace

std::array<BodyMassProperties, kArmJoints + 1> arm_bodies(const ArmParams& arm,
                                                                  const std::array<double, kArmJoints>& q_rad) {
  std::array<BodyMassProperties, kArmJoints + 1> out;
  Vec3 frame_body_m = arm.mount_body_m;  // link 1's parent is the body frame, at the mount
  Mat3 body_from_parent = Mat3::Identity();
  for (int i = 0; i < kArmJoints; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const model::ArmLinkParams& link = arm.links[k];
    frame_body_m += body_from_parent * link.joint_position_parent_m;
    const Mat3 body_from_link = body_from_parent * Eigen::AngleAxisd(q_rad[k], link.joint_axis).toRotationMatrix();
    out[k] = in_body_axes(link.mass_kg, link.com_link_m, link.inertia_kgm2, frame_body_m, body_from_link);
    body_from_parent = body_from_link;
  }
  const model::GripperParams& g = arm.gripper;  // at link 7's origin, its axes
  out[kArmJoints] = in_body_axes(g.mass_kg, g.com_link7_m, g.inertia_kgm2, frame_body_m, body_from_parent);
  return out;
}

GripperBodies gripper_bodies(const GripperParams& g) {
  const JawParams& jaws = g.jaws;
  const Vec3 h = jaws.finger_half_extents_m;
  const double m_f = jaws.finger_mass_kg;
  const Vec3 plate = m_f / 3.0 * Vec3(h.y() * h.y() + h.z() * h.z(), h.x() * h.x() + h.z() * h.z(),
                                      h.x() * h.x() + h.y() * h.y());  // a box of half extents h
  GripperBodies out;
  Mat3 about_com = g.inertia_kgm2.asDiagonal();  // the whole gripper's, about its CoM
  Vec3 moment_kgm = g.mass_kg * g.com_link7_m;
  out.body.mass_kg = g.mass_kg;
  for (int i = 0; i < 2; ++i) {
    const double side = i == 0 ? 1.0 : -1.0;
    BodyMassProperties& f = out.fingers[static_cast<std::size_t>(i)];
    f.mass_kg = m_f;
    f.com_body_m = g.position_link7_m + Vec3(0.0, 0.0, side * (jaws.open_half_gap_m + h.z()));
    f.inertia_kgm2 = plate.asDiagonal();
    out.body.mass_kg -= m_f;
    moment_kgm -= m_f * f.com_body_m;
    about_com -= f.inertia_kgm2 + point_inertia(m_f, f.com_body_m - g.com_link7_m);
  }
  out.body.com_body_m = moment_kgm / out.body.mass_kg;
  out.body.inertia_kgm2 = about_com - point_inertia(out.body.mass_kg, out.body.com_body_m - g.com_link7_m);
  return out;
}

BodyMassProperties hub_mass_properties(const SpacecraftParams& chaser, const ArmParams& arm) {
  const auto links = arm_bodies(arm, arm.stowed_rad);
  BodyMassProperties hub;
  hub.mass_kg = chaser.mass_kg;
  Vec3 moment_kgm = chaser.mass_kg * chaser.com_body_m;
  hub.inertia_kgm2 = chaser.inertia_kgm2;  // about the chaser's CoM until the end
  for (const BodyMassProperties& b : links) {
    hub.mass_kg -= b.mass_kg;
    moment_kgm -= b.mass_kg * b.com_body_m;
    hub.inertia_kgm2 -= b.inertia_kgm2 + point_inertia(b.mass_kg, b.com_body_m - chaser.com_body_m);
  }
  hub.com_body_m = moment_kgm / hub.mass_kg;
  hub.inertia_kgm2 -= point_inertia(hub.mass_kg, hub.com_body_m - chaser.com_body_m);
  return hub;
}

std::optional<std::string> hub_problem(const SpacecraftParams& chaser,
                                       const BodyMassProperties& hub) {
  const double arm_kg = chaser.mass_kg - hub.mass_kg;
  if (!(hub.mass_kg > 0.0))
    return fmt::format("chaser.mass_kg: the chaser ({} kg, arm stowed) must be heavier than its arm (chaser.arm, "
                       "{} kg): the multibody hub would have no mass left",
                       chaser.mass_kg, arm_kg);
  const Mat3 sym = 0.5 * (hub.inertia_kgm2 + hub.inertia_kgm2.transpose());
  const Vec3 moments = Eigen::SelfAdjointEigenSolver<Mat3>(sym, Eigen::EigenvaluesOnly).eigenvalues();
  const double largest = moments.maxCoeff();
  if (!(moments.minCoeff() > 0.0) || largest > (moments.sum() - largest) * (1.0 + 1e-9))
    return fmt::format("chaser.inertia_kgm2: less the stowed arm (chaser.arm at its stowed angles) it leaves the hub "
                       "principal moments [{:.6g}, {:.6g}, {:.6g}] kg m^2, not a body's (each must be positive and at "
                       "most the sum of the other two): the chaser's inertia must include the arm's",
                       moments.x(), moments.y(), moments.z());
  return std::nullopt;
}

BodyMassProperties composite(std::span<const BodyMassProperties> bodies) {
  BodyMassProperties out;
  Vec3 moment_kgm = Vec3::Zero();
  for (const BodyMassProperties& b : bodies) {
    out.mass_kg += b.mass_kg;
    moment_kgm += b.mass_kg * b.com_body_m;
  }
  out.com_body_m = moment_kgm / out.mass_kg;
  for (const BodyMassProperties& b : bodies)
    out.inertia_kgm2 += b.inertia_kgm2 + point_inertia(b.mass_kg, b.com_body_m - out.com_body_m);
  return out;
}

}  // namespace chaser::model
