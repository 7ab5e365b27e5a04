#pragma once
// Solar radiation pressure on a body modelled as a cannonball: a sphere of cross-section
// A, reflectivity coefficient C_R (1: absorbs all, 2: mirror), mass m, so that
//   a = -P (AU / d)^2 C_R A / m * u,   u the unit vector from the body to the Sun,
// with P = 4.56e-6 N/m^2 at 1 AU (a solar constant of 1367 W/m^2 over c), d the body's distance from
// the Sun, times the fraction of the Sun it sees: 0 in the Earth's cylindrical shadow, 1 outside
// (Vallado 2013, sec. 5.3: the cylindrical model; the penumbra, ~10 s of a LEO orbit, is neglected).
#include "core/types.hpp"

namespace chaser::plant::earth {

inline constexpr double kSolarPressureAt1AuNpm2 = 4.56e-6;  // [N/m^2]

struct SolarPressureParams {
  double area_to_mass_m2pkg = 0.01;  // [m^2/kg] A / m
  double reflectivity = 1.3;         // [-] C_R
  bool eclipses = true;              // the Earth's shadow switches the pressure off
  double earth_radius_m = 6378137.0;  // [m] the shadow cylinder's radius
};

// True if a point at r (ECI, from the Earth's centre) is in the Earth's cylindrical shadow, the Sun
// at sun_eci_m.
bool in_earth_shadow(const Vec3& r_eci_m, const Vec3& sun_eci_m, double earth_radius_m);

Vec3 solar_pressure_acceleration_eci(const SolarPressureParams& p, const Vec3& r_eci_m, const Vec3& sun_eci_m);

}  // namespace chaser::plant::earth
