#pragma once
// A perturbed Earth orbit for the target and the chaser (the COMRADE platform): the
// scenario's `orbit.earth` section. Absent, a run flies Fonod 2015's circular Keplerian orbit
// (model/orbit.hpp); present, the plant propagates both bodies in an Earth-centred inertial frame
// with the perturbations switched on here (plant/orbit_propagator.hpp, docs/dynamics.md). The
// central body's mu and radius stay in OrbitParams (J2's reference radius is body_radius_m), and
// the target starts on the circular orbit of OrbitParams' altitude in the plane given here.
#include <optional>

#include "core/types.hpp"

namespace chaser::model {

// What one body's surface and magnetism do in the environment.
struct OrbitBodySurface {
  double ballistic_coefficient_kgpm2 = 100.0;  // [kg/m^2] m / (C_D A), drag
  double area_to_mass_m2pkg = 0.01;            // [m^2/kg] cannonball solar pressure's A / m
  double reflectivity = 1.3;                   // [-] C_R in [1, 2]
  Vec3 residual_dipole_body_Am2 = Vec3::Zero();  // [A m^2] body axes, magnetic torque m x B
};

// A calendar date and time of day (Gregorian, 1900-2100), on the TT scale.
struct CalendarTime {
  int year = 2027, month = 3, day = 20, hour = 12, minute = 0;
  double second = 0.0;
};

struct EarthOrbitParams {
  CalendarTime epoch_tt;                   // t = 0 of the run
  double inclination_rad = 0.0;
  double raan_rad = 0.0;                   // right ascension of the ascending node
  double argument_of_latitude_rad = 0.0;   // of the target at t = 0
  double j2 = 1.08262668e-3;               // [-] 0: central gravity alone
  bool drag = true;
  bool solar_pressure = true;
  bool eclipses = true;
  bool sun_gravity = true;
  bool moon_gravity = true;
  bool magnetic_torque = true;
  OrbitBodySurface target, chaser;
};

}  // namespace chaser::model
