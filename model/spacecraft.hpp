#pragma once
#include "core/types.hpp"

namespace chaser::model {

// Rigid chaser body. Positions in the body frame are measured from the geometric reference point
// (the origin of the thruster layout); the centre of mass sits at com_body_m from it.
struct SpacecraftParams {
  double mass_kg = 2500.0;                   // [kg] wet mass at the start of the run
  Mat3 inertia_kgm2 = Mat3::Identity();      // [kg m^2] about the centre of mass, body axes
  Vec3 com_body_m = Vec3::Zero();            // [m] centre of mass from the reference point
  double isp_s = 220.0;                      // [s] specific impulse of the thrusters
};

// Passive target: its attitude turns at a constant inertial rate (a slow tumble, or zero).
struct TargetParams {
  Quat q_inertial_from_target = Quat::Identity();
  Vec3 omega_inertial_radps = Vec3::Zero();  // [rad/s] constant tumble rate, inertial components
};

}  // namespace chaser::model
