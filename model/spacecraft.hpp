#pragma once
#include <optional>
#include <vector>

#include "core/constants.hpp"
#include "core/types.hpp"
#include "model/arm.hpp"
#include "model/keep_out.hpp"

namespace chaser::model {

// A propellant tank whose first lateral slosh mode the Earth-orbit plant models (
// model/slosh.hpp): an upright flat-bottomed cylinder fixed in the chaser, the liquid's fill height
// from its mass and density. Its liquid is part of the chaser's mass_kg, com_body_m and inertia_kgm2
// (the whole spacecraft at rest); the plant takes the slosh mass back out of them.
struct SloshTankSpec {
  Vec3 bottom_centre_body_m = Vec3::Zero();  // [m] centre of the tank's bottom, from the reference point
  Vec3 axis_body = Vec3::UnitZ();            // unit, bottom to top: the way the settling acceleration points
  double radius_m = 0.4;                     // [m] R
  double height_m = 1.0;                     // [m] the cylinder's height: the liquid must fit
  double liquid_mass_kg = 100.0;             // [kg]
  double density_kgpm3 = 1004.0;             // [kg/m^3] hydrazine at 25 C
  double damping_ratio = 0.005;              // [-] zeta of the first mode (a bare tank: 0.001-0.01)
  double surface_tension_Npm = 0.066;        // [N/m] sigma, the pendulum's hold at zero thrust (hydrazine, 25 C)
};
// The liquid's height in its tank, h = m / (rho pi R^2) [m].
inline double fill_height_m(const SloshTankSpec& t) {
  return t.liquid_mass_kg / (t.density_kgpm3 * kPi * t.radius_m * t.radius_m);
}
// Surface tension's hold on the liquid, sigma / (rho R^2): the acceleration at Bond number 1 [m/s^2].
inline double capillary_accel_mps2(const SloshTankSpec& t) {
  return t.surface_tension_Npm / (t.density_kgpm3 * t.radius_m * t.radius_m);
}

// The mechanical analogue of each tank's first mode (model/slosh.hpp): the spring-mass, whose
// stiffness is fixed by g_eff_mps2, or the pendulum, driven by the specific force the tank actually
// feels and bounded by the tank's wall (valid in turning flight).
enum class SloshModel { spring_mass, pendulum };

struct SloshParams {
  SloshModel model = SloshModel::spring_mass;
  double g_eff_mps2 = 0.01;  // [m/s^2] the axial acceleration that settles the liquid (sets omega1)
  std::vector<SloshTankSpec> tanks;  // 1 to model::kMaxSloshTanks (4)
};

// Rigid chaser body. Positions in the body frame are measured from the geometric reference point
// (the origin of the thruster layout); the centre of mass sits at com_body_m from it.
struct SpacecraftParams {
  double mass_kg = 2500.0;                   // [kg] wet mass at the start of the run
  Mat3 inertia_kgm2 = Mat3::Identity();      // [kg m^2] about the centre of mass, body axes
  Vec3 com_body_m = Vec3::Zero();            // [m] centre of mass from the reference point
  double isp_s = 220.0;                      // [s] specific impulse of the thrusters
  std::optional<SloshParams> slosh;          // propellant slosh (with orbit.earth only)
  double keep_out_radius_m = 0.0;            // [m] a sphere about the CoM enclosing the chaser, for the
                                             // target's keep-out clearance (model/keep_out.hpp)
  std::optional<ArmParams> arm;              // the servicer's 7-DOF arm (model/arm.hpp); absent: none
};

// COMRADE 2018, sec. 7.1: the ENVISAT-like target's spin cases at 2.5 deg/s (docs/scenario.md
// gives the axes; LVLH here is MSR's, x zenith, z along the orbital angular momentum, and the
// ESA H-bar is -z). Given: the scenario's q_inertial_from_target and omega_inertial_radps.
enum class SpinCase { given, s1, s2, s3 };

// The target as a rigid body tumbling by Euler's equations, instead of a constant rate.
struct TargetBodyParams {
  double mass_kg = 7828.0;                   // [kg]
  Mat3 inertia_kgm2 = Mat3::Identity();      // [kg m^2] about its centre of mass, target axes
  bool gravity_gradient = true;              // gravity-gradient torque on the target
  SpinCase spin_case = SpinCase::given;
  double spin_rate_radps = 0.0;              // [rad/s] inertial, for spin cases S1-S3
  Vec3 grasp_point_target_m = Vec3::Zero();  // [m] where the gripper takes hold (target axes, from its CoM)
  Vec3 capture_point_target_m = Vec3::Zero();  // [m] where the chaser's CoM holds for capture
  FixtureParams fixture;                      // the grasping fixture's lip at grasp_point_target_m (model/arm.hpp)
  std::vector<KeepOutBox> keep_out;           // the target's keep-out volume; empty: not checked
};

// Passive target: its attitude turns at a constant inertial rate (a slow tumble, or zero), or,
// with `body`, tumbles as a rigid body from this initial attitude and rate.
struct TargetParams {
  Quat q_inertial_from_target = Quat::Identity();
  Vec3 omega_inertial_radps = Vec3::Zero();  // [rad/s] constant tumble rate, inertial components
  std::optional<TargetBodyParams> body;
};

}  // namespace chaser::model
