#include "plant/orbit_perturbations.hpp"

#include "plant/earth/magnetic_field.hpp"
#include "plant/earth/moon.hpp"
#include "plant/earth/sun.hpp"
#include "plant/earth/third_body.hpp"

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
  // UT1 taken as TT, as magnetic_field.hpp does (0.3 deg of the Earth's turn in 2024).
  return {.sun_eci_m = earth::sun_position_eci_m(julian_date_tt),
          .moon_eci_m = earth::moon_position_eci_m(julian_date_tt),
          .ecef_from_eci = earth::ecef_from_eci(julian_date_tt)};
}

namespace {

// The third bodies' pull on the target, added to a.
void add_third_bodies(const OrbitPerturbationParams& p, const Ephemeris& eph, const Vec3& r_t_eci_m, Vec3& a) {
  if (p.sun_gravity)
    a += earth::third_body_acceleration_eci(earth::kSunGravitationalParameterM3ps2, r_t_eci_m, eph.sun_eci_m);
  if (p.moon_gravity)
    a += earth::third_body_acceleration_eci(earth::kMoonGravitationalParameterM3ps2, r_t_eci_m, eph.moon_eci_m);
}

// Its difference between the chaser and the target, without cancellation, added to a.
void add_differential_third_bodies(const OrbitPerturbationParams& p, const Ephemeris& eph, const Vec3& r_t_eci_m,
                                   const Vec3& dr_eci_m, Vec3& a) {
  if (p.sun_gravity)
    a += earth::differential_third_body_eci(earth::kSunGravitationalParameterM3ps2, r_t_eci_m, dr_eci_m,
                                            eph.sun_eci_m);
  if (p.moon_gravity)
    a += earth::differential_third_body_eci(earth::kMoonGravitationalParameterM3ps2, r_t_eci_m, dr_eci_m,
                                            eph.moon_eci_m);
}

}  // namespace

Vec3 target_acceleration_eci(const OrbitPerturbationParams& p, const Ephemeris& eph, const Vec3& r_t_eci_m,
                             const Vec3& v_t_eci_mps) {
  Vec3 a = earth::gravity_acceleration_eci(p.gravity, r_t_eci_m) +
           surface_acceleration(p, p.target, eph, r_t_eci_m, v_t_eci_mps);
  add_third_bodies(p, eph, r_t_eci_m, a);
  return a;
}

OrbitAccelerations gravity_accelerations(const earth::GravityParams& gravity, const Vec3& r_t_eci_m,
                                         const Vec3& dr_eci_m) {
  const earth::GravityPair g = earth::gravity_pair_eci(gravity, r_t_eci_m, dr_eci_m);
  return {.target_eci_mps2 = g.target_eci_mps2, .relative_eci_mps2 = g.relative_eci_mps2};
}

OrbitAccelerations slow_accelerations(const OrbitPerturbationParams& p, const Ephemeris& eph, const Vec3& r_t_eci_m,
                                      const Vec3& v_t_eci_mps, const Vec3& dr_eci_m, const Vec3& dv_eci_mps) {
  const Vec3 surface_t = surface_acceleration(p, p.target, eph, r_t_eci_m, v_t_eci_mps);
  OrbitAccelerations out;
  out.target_eci_mps2 = surface_t;
  add_third_bodies(p, eph, r_t_eci_m, out.target_eci_mps2);
  if (p.drag || p.solar_pressure)
    out.relative_eci_mps2 = surface_acceleration(p, p.chaser, eph, r_t_eci_m + dr_eci_m, v_t_eci_mps + dv_eci_mps) - surface_t;
  add_differential_third_bodies(p, eph, r_t_eci_m, dr_eci_m, out.relative_eci_mps2);
  return out;
}

OrbitAccelerations orbit_accelerations(const OrbitPerturbationParams& p, const Ephemeris& eph, const Vec3& r_t_eci_m,
                                       const Vec3& v_t_eci_mps, const Vec3& dr_eci_m, const Vec3& dv_eci_mps) {
  const OrbitAccelerations g = gravity_accelerations(p.gravity, r_t_eci_m, dr_eci_m);
  const OrbitAccelerations s = slow_accelerations(p, eph, r_t_eci_m, v_t_eci_mps, dr_eci_m, dv_eci_mps);
  return {.target_eci_mps2 = g.target_eci_mps2 + s.target_eci_mps2,
          .relative_eci_mps2 = g.relative_eci_mps2 + s.relative_eci_mps2};
}

}  // namespace chaser::plant
