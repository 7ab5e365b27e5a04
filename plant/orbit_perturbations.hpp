#pragma once
// Translational accelerations of the target and of the chaser relative to it, in an Earth-centred
// inertial frame, for the COMRADE platform (models in plant/earth/, docs/dynamics.md):
// central gravity and J2, drag, solar radiation pressure, the Sun's and the Moon's gravity.
//
// The chaser's state is integrated relative to the target's (dr = r_c - r_t, dv = v_c - v_t), not
// as a second absolute orbit: at metres of separation the two absolute accelerations agree to ten
// digits, and their difference is what moves the chaser. Each term of
//   dv' = [g(r_t + dr) - g(r_t)] + [drag_c - drag_t] + [srp_c - srp_t] + [third_c - third_t] + F / m_c
// is formed without subtracting two nearly equal numbers where that would lose digits: gravity and
// the third bodies by Battin's f(q) (differential_* functions); drag and solar pressure are
// themselves 1e-6 of gravity, so their plain difference keeps every digit that matters (an absolute
// error of ~1e-22 m/s^2). The test relative_motion_test.cpp shows the separation this keeps.
#include "core/types.hpp"
#include "plant/earth/atmosphere.hpp"
#include "plant/earth/gravity.hpp"
#include "plant/earth/solar_radiation.hpp"

namespace chaser::plant {

// What one body's surface does in the environment (a cannonball for both drag and pressure).
struct OrbitBodyParams {
  double ballistic_coefficient_kgpm2 = 100.0;  // [kg/m^2] m / (C_D A)
  double area_to_mass_m2pkg = 0.01;            // [m^2/kg] solar pressure's A / m
  double reflectivity = 1.3;                   // [-] C_R
};

struct OrbitPerturbationParams {
  earth::GravityParams gravity;  // j2 = 0: central gravity only
  bool drag = true;
  bool solar_pressure = true;
  bool eclipses = true;          // the Earth's cylindrical shadow switches solar pressure off
  bool sun_gravity = true;       // third body
  bool moon_gravity = true;      // third body
  OrbitBodyParams target, chaser;
};

// Where the Sun and the Moon are [m], ECI, for one stretch of time short enough to hold them fixed
// (a control period: the Moon moves 100 m of its 384,000 km in 0.1 s).
// The Earth's turn, for its magnetic field, likewise (4e-4 deg in 0.1 s).
struct Ephemeris {
  Vec3 sun_eci_m = Vec3(1.0e11, 0.0, 0.0);
  Vec3 moon_eci_m = Vec3(3.8e8, 0.0, 0.0);
  Mat3 ecef_from_eci = Mat3::Identity();  // the Earth's rotation by the Greenwich mean sidereal time
};
Ephemeris ephemeris_at(double julian_date_tt);

// The target's inertial acceleration [m/s^2], ECI.
Vec3 target_acceleration_eci(const OrbitPerturbationParams& p, const Ephemeris& eph, const Vec3& r_t_eci_m,
                             const Vec3& v_t_eci_mps);

// Both at once, as the propagator asks them (the target's drag and pressure are needed by both and
// computed once): the target's inertial acceleration, and the chaser's relative to it without its
// own forces, the environment's a_c - a_t at r_c = r_t + dr, v_c = v_t + dv.
struct OrbitAccelerations {
  Vec3 target_eci_mps2 = Vec3::Zero();    // [m/s^2]
  Vec3 relative_eci_mps2 = Vec3::Zero();  // [m/s^2]
};
OrbitAccelerations orbit_accelerations(const OrbitPerturbationParams& p, const Ephemeris& eph, const Vec3& r_t_eci_m,
                                       const Vec3& v_t_eci_mps, const Vec3& dr_eci_m, const Vec3& dv_eci_mps);

// The same split in two, which orbit_accelerations sums: the Earth's gravity (central and J2: the
// target's, and the differential one at dr), which changes at the orbit rate times the separation
// and must be evaluated at every RK4 stage; and the slowly varying rest (drag, solar pressure, the
// Sun and the Moon), which the propagator may hold over a control period
// (OrbitDynamicsParams::hold_slow_environment).
OrbitAccelerations gravity_accelerations(const earth::GravityParams& gravity, const Vec3& r_t_eci_m,
                                         const Vec3& dr_eci_m);
OrbitAccelerations slow_accelerations(const OrbitPerturbationParams& p, const Ephemeris& eph, const Vec3& r_t_eci_m,
                                      const Vec3& v_t_eci_mps, const Vec3& dr_eci_m, const Vec3& dv_eci_mps);

}  // namespace chaser::plant
