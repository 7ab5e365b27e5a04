#include "plant/orbit_perturbations.hpp"

#include "plant/earth/sun.hpp"

namespace chaser::plant {

namespace {

earth::DragParams drag_params(const OrbitPerturbationParams& p, const OrbitBodyParams& body) {
  return {.ballistic_coefficient_kgpm2 = body.ballistic_coefficient_kgpm2,
          .equatorial_radius_m = p.gravity.radius_m,
          .corotating_atmosphere = true};
}

earth::SolarPressureParams pressure_params(const OrbitPerturbationParams& p, const OrbitBodyParams& body) {
  return {.area_to_mass_m2pkg = body.area_to_mass_m2pkg,
          .reflectivity = body.reflectivity,
          .eclipses = p.eclipses,
          .earth_radius_m = p.gravity.radius_m};
}

// Drag and solar pressure on one body: the non-gravitational part of its acceleration.
Vec3 surface_acceleration(const OrbitPerturbationParams& p, const OrbitBodyParams& body, const Ephemeris& eph,
                          const Vec3& r_eci_m, const Vec3& v_eci_mps) {
  Vec3 a = Vec3::Zero();
  if (p.drag) a += earth::drag_acceleration_eci(drag_params(p, body), r_eci_m, v_eci_mps);
  if (p.solar_pressure) a += earth::solar_pressure_acceleration_eci(pressure_params(p, body), r_eci_m, eph.sun_eci_m);
  return a;
}

}  // namespace

Ephemeris ephemeris_at(double julian_date_tt) {
  Ephemeris e;
  e.sun_eci_m = earth::sun_position_eci_m(julian_date_tt);
  return e;
}

Vec3 target_acceleration_eci(const OrbitPerturbationParams& p, const Ephemeris& eph, const Vec3& r_t_eci_m,
                             const Vec3& v_t_eci_mps) {
  return earth::gravity_acceleration_eci(p.gravity, r_t_eci_m) +
         surface_acceleration(p, p.target, eph, r_t_eci_m, v_t_eci_mps);
}

Vec3 relative_acceleration_eci(const OrbitPerturbationParams& p, const Ephemeris& eph, const Vec3& r_t_eci_m,
                               const Vec3& v_t_eci_mps, const Vec3& dr_eci_m, const Vec3& dv_eci_mps) {
  Vec3 a = earth::differential_gravity_eci(p.gravity, r_t_eci_m, dr_eci_m);
  if (p.drag || p.solar_pressure) {
    a += surface_acceleration(p, p.chaser, eph, r_t_eci_m + dr_eci_m, v_t_eci_mps + dv_eci_mps) -
         surface_acceleration(p, p.target, eph, r_t_eci_m, v_t_eci_mps);
  }
  return a;
}

}  // namespace chaser::plant
