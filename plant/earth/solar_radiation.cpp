#include "plant/earth/solar_radiation.hpp"

#include "plant/earth/sun.hpp"

namespace chaser::plant::earth {

bool in_earth_shadow(const Vec3& r_eci_m, const Vec3& sun_eci_m, double earth_radius_m) {
  const Vec3 sun_dir = sun_eci_m.normalized();
  const double along = r_eci_m.dot(sun_dir);  // < 0: on the night side of the terminator plane
  return along < 0.0 && (r_eci_m - along * sun_dir).norm() < earth_radius_m;
}

Vec3 solar_pressure_acceleration_eci(const SolarPressureParams& p, const Vec3& r_eci_m, const Vec3& sun_eci_m) {
  if (p.eclipses && in_earth_shadow(r_eci_m, sun_eci_m, p.earth_radius_m)) return Vec3::Zero();
  const Vec3 to_sun = sun_eci_m - r_eci_m;
  const double d = to_sun.norm();
  const double scale = kAstronomicalUnitM / d;
  return -kSolarPressureAt1AuNpm2 * scale * scale * p.reflectivity * p.area_to_mass_m2pkg / d * to_sun;
}

}  // namespace chaser::plant::earth
