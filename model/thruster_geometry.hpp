#pragma once
// Thruster configuration matrix (Fonod 2015, eq. 2): column k is the force and torque about the
// centre of mass that the k-th thruster of a set produces when open for a whole period, per unit
// scaled on-time.
#include <Eigen/Core>

#include "core/types.hpp"
#include "model/thrusters.hpp"

namespace chaser::model {

// M of a thruster set, at the compile-time capacity: columns [0, count) used, the rest zero.
using ConfigMatrix = Eigen::Matrix<double, 6, kMaxThrusters>;  // [N; N m] per unit on-time

// Force and torque of one thruster at full thrust.
Vec6 thruster_wrench(const ThrusterParams& thruster, const Vec3& com_body_m);

// M for the thrusters of `mask`, in increasing index order (compact numbering): rows 0-2 force
// [N], rows 3-5 torque [N m], body axes, torque about the centre of mass at com_body_m.
ConfigMatrix configuration_matrix(const ThrusterSetParams& set, ThrusterMask mask, const Vec3& com_body_m);

// The same with as many columns as the mask has thrusters (analysis and design, not the hot path).
Eigen::Matrix<double, 6, Eigen::Dynamic> configuration_columns(const ThrusterSetParams& set, ThrusterMask mask,
                                                              const Vec3& com_body_m);

}  // namespace chaser::model
