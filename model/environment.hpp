#pragma once
// Disturbances acting on the chaser besides central gravity.
#include "core/types.hpp"

namespace chaser::model {

// Solar-pressure/drag-like bias plus white noise held constant over each control period, and the
// gravity-gradient torque of the central body.
struct EnvironmentParams {
  Vec3 force_bias_lvlh_N = Vec3::Zero();   // [N] constant force, LVLH axes
  double force_noise_sigma_N = 0.0;        // [N] per axis, 1-sigma, redrawn each period
  Vec3 torque_bias_body_Nm = Vec3::Zero(); // [N m] constant torque, body axes
  double torque_noise_sigma_Nm = 0.0;      // [N m] per axis, 1-sigma, redrawn each period
  bool gravity_gradient = true;            // gravity-gradient torque on the chaser
};

}  // namespace chaser::model
