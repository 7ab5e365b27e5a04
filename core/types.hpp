#pragma once
// Fixed-size Eigen types used across Chaser. Fixed sizes keep the per-period loop allocation-free.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace chaser {

using Vec3 = Eigen::Vector3d;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat3 = Eigen::Matrix3d;
using Mat6 = Eigen::Matrix<double, 6, 6>;
using Quat = Eigen::Quaterniond;

}  // namespace chaser
