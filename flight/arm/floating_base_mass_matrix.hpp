#pragma once
// The joint-space mass matrix H(q) (13 x 13) of the hub and arm, by the composite-rigid-body
// algorithm (Featherstone, RBDA sec. 6.2, Table 6.2), for v ordered as in
// flight/arm/servicer_arm.hpp: the kinetic energy is T = v' H v / 2.
//
// All spatial quantities are in world axes about the hub's origin (flight/arm/spatial.hpp), so the
// algorithm's transforms X are identities:
//   composite inertias from the tip:   I^c_7 = I_7,  I^c_i = I_i + I^c_{i+1},  I^c_0 = I_0 + I^c_1,
//   for each joint i:                  F = I^c_i S_i,  H_ii = S_i' F + armature_i,
//                                      H_ji = S_j' F for the joints j < i before it, H_base,i = S_base' F,
//   the base block:                    H_base = S_base' I^c_0 S_base,
// with S_i = (a_i; (r_link_i - r_hub) x a_i) the hinge's subspace and S_base the free joint's,
// (0, R; 1, 0) for (omega; v_O) = S_base (v_hub_world; omega_hub_body), R = R_world_from_hub. So
// the base block is (M 1, -[h]x R; R' [h]x, R' I^c_O R) with M the servicer's mass and h = M c its
// first moment about the hub's origin, and H_base,i = (f; R' n) for F = (n; f).
// The armature is the drive's rotor inertia reflected through the gear, as MuJoCo adds it.
// Fixed-size, no allocation.
#include "flight/arm/arm_kinematics.hpp"
#include "flight/arm/servicer_arm.hpp"

namespace chaser::flight::arm {

ServicerMatrix floating_base_mass_matrix(const ServicerArmParams& params, const ArmKinematics& kinematics);

}  // namespace chaser::flight::arm
