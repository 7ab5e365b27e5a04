#pragma once
#include <optional>

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

// COMRADE 2018, sec. 7.1: the ENVISAT-like target's spin cases at 2.5 deg/s (docs/scenario.md
// gives the axes; LVLH here is MSR's, x zenith, z along the orbital angular momentum, and the
// ESA H-bar is -z). Given: the scenario's q_inertial_from_target and omega_inertial_radps.
enum class SpinCase { given, s1, s2, s3 };

// The target as a rigid body tumbling by Euler's equations (issue 17), instead of a constant rate.
struct TargetBodyParams {
  double mass_kg = 7828.0;                   // [kg]
  Mat3 inertia_kgm2 = Mat3::Identity();      // [kg m^2] about its centre of mass, target axes
  bool gravity_gradient = true;              // gravity-gradient torque on the target
  SpinCase spin_case = SpinCase::given;
  double spin_rate_radps = 0.0;              // [rad/s] inertial, for spin cases S1-S3
  Vec3 grasp_point_target_m = Vec3::Zero();  // [m] where the gripper takes hold (target axes, from its CoM)
  Vec3 capture_point_target_m = Vec3::Zero();  // [m] where the chaser's CoM holds for capture
};

// Passive target: its attitude turns at a constant inertial rate (a slow tumble, or zero), or,
// with `body`, tumbles as a rigid body from this initial attitude and rate.
struct TargetParams {
  Quat q_inertial_from_target = Quat::Identity();
  Vec3 omega_inertial_radps = Vec3::Zero();  // [rad/s] constant tumble rate, inertial components
  std::optional<TargetBodyParams> body;
};

}  // namespace chaser::model
