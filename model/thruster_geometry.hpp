#pragma once
// Thruster configuration matrix (Fonod 2015, eq. 2): column i is the force and torque about the
// centre of mass that thruster i produces when open for a whole period, per unit scaled on-time.
#include "core/types.hpp"
#include "model/thrusters.hpp"

namespace chaser::model {

// M for the eight thrusters of `branch` (0 = A, 1 = B): rows 0-2 force [N], rows 3-5 torque [N m],
// body axes, torque about the centre of mass at com_body_m.
ConfigMatrix configuration_matrix(const ThrusterSetParams& set, int branch, const Vec3& com_body_m);

// Force and torque of one thruster at full thrust.
Vec6 thruster_wrench(const ThrusterParams& thruster, const Vec3& com_body_m);

}  // namespace chaser::model
