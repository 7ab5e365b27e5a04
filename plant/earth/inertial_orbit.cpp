#include "plant/earth/inertial_orbit.hpp"

#include <cmath>

#include "core/constants.hpp"

namespace chaser::plant::earth {

InertialState circular_orbit_state(double mu_m3ps2, double radius_m, double inclination_rad, double raan_rad,
                                   double argument_of_latitude_rad) {
  // Perifocal-like frame of the node line: x to the ascending node, y 90 deg ahead in the plane.
  const Quat to_eci = Eigen::AngleAxisd(raan_rad, Vec3::UnitZ()) *
                                   Eigen::AngleAxisd(inclination_rad, Vec3::UnitX());
  const double u = argument_of_latitude_rad;
  const double speed = std::sqrt(mu_m3ps2 / radius_m);
  return {to_eci * Vec3(radius_m * std::cos(u), radius_m * std::sin(u), 0.0),
          to_eci * Vec3(-speed * std::sin(u), speed * std::cos(u), 0.0)};
}

double semi_major_axis_m(double mu_m3ps2, const InertialState& s) {
  const double energy = 0.5 * s.v_eci_mps.squaredNorm() - mu_m3ps2 / s.r_eci_m.norm();
  return -mu_m3ps2 / (2.0 * energy);
}

double inclination_rad(const InertialState& s) {
  const Vec3 h = s.r_eci_m.cross(s.v_eci_mps);
  return std::acos(h.z() / h.norm());
}

double raan_rad(const InertialState& s) {
  const Vec3 h = s.r_eci_m.cross(s.v_eci_mps);  // node line along z x h = (-h_y, h_x, 0)
  const double raan = std::atan2(h.x(), -h.y());
  return raan < 0.0 ? raan + 2.0 * kPi : raan;
}

}  // namespace chaser::plant::earth
