#pragma once
// The servicer's hub: the rigid chaser less its stowed arm (the multibody plant's body, and the
// flight software's model of it). The scenario's chaser.mass_kg, inertia_kgm2 and com_body_m are
// the whole spacecraft's with the arm stowed (the rigid plants fly it so); the multibody plant flies the arm's links as bodies of their own, so the hub is what is
// left when they are taken out: their masses, first moments and inertias about the chaser's CoM
// (parallel axes, I_P = I_C + m (|d|^2 1 - d d^T), d from the body's CoM C to P).
//   m_hub = M - sum m_i,   c_hub = (M c - sum m_i c_i) / m_hub
//   I_hub = I - sum [I_i + m_i P(c_i - c)] - m_hub P(c_hub - c)       (all about their own CoM)
// The links' CoMs and inertias in body axes come from the arm's forward kinematics at its stowed
// angles (stowed_arm_bodies), the same chain plant/multibody/mjcf.cpp writes: each link frame
// parallel to its parent's at q = 0, joint i turning link i about its axis.
#include <array>
#include <optional>
#include <span>
#include <string>

#include "core/types.hpp"
#include "model/arm.hpp"
#include "model/spacecraft.hpp"

namespace chaser::model {

struct BodyMassProperties {
  double mass_kg = 0.0;
  Vec3 com_body_m = Vec3::Zero();                   // [m] from the chaser's body reference point, body axes
  Mat3 inertia_kgm2 = Mat3::Zero();                 // [kg m^2] about com_body_m, body axes
};

// The seven links and the gripper (index 7) at joint angles q_rad, in the chaser's body frame.
std::array<BodyMassProperties, kArmJoints + 1> arm_bodies(const ArmParams& arm,
                                                                  const std::array<double, kArmJoints>& q_rad);

// The gripper as the multibody plant has it (link 7's frame, com_body_m read as from link 7's
// origin): the two fingers of its jaws, open (uniform plates, model/arm.hpp's JawParams), and the
// gripper's own body, which is the gripper (mass_kg, com_link7_m, inertia_kgm2, jaws open) less
// them, by the parallel axes as the hub is the chaser less its arm. finger[0] is on the tool's +z.
struct GripperBodies {
  BodyMassProperties body;
  std::array<BodyMassProperties, 2> fingers;
};
GripperBodies gripper_bodies(const GripperParams& gripper);

// The hub: the chaser (mass_kg, com_body_m, inertia_kgm2) less the arm at arm.stowed_rad.
BodyMassProperties hub_mass_properties(const SpacecraftParams& chaser, const ArmParams& arm);

// Why the hub is not a body (naming the keys): the arm as heavy as the chaser or heavier, or an
// inertia left that is not positive definite or breaks the triangle inequality of its principal
// moments; nothing when it is one.
std::optional<std::string> hub_problem(const SpacecraftParams& chaser,
                                       const BodyMassProperties& hub);

// Composite of bodies about their common CoM (the check that puts the hub and arm back together).
BodyMassProperties composite(std::span<const BodyMassProperties> bodies);

}  // namespace chaser::model
