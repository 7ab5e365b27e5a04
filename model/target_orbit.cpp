#include "model/target_orbit.hpp"

#include <cmath>

namespace chaser::model {

TargetOrbit::TargetOrbit(const OrbitParams& params) : TargetOrbit(params.mu_m3ps2, params.radius_m()) {}

TargetOrbit::TargetOrbit(double mu_m3ps2, double radius_m)
    : mu_m3ps2_(mu_m3ps2), radius_m_(radius_m), mean_motion_radps_(OrbitParams::mean_motion_radps(mu_m3ps2, radius_m)) {}

Quat TargetOrbit::q_inertial_from_lvlh(double t_s) const {
  const double half = 0.5 * argument_of_latitude_rad(t_s);  // a turn by u about z
  return Quat(std::cos(half), 0.0, 0.0, std::sin(half));
}

LvlhFrame TargetOrbit::lvlh_at(double t_s) const {
  return LvlhFrame{
      .q_inertial_from_lvlh = q_inertial_from_lvlh(t_s),
      .omega_lvlh_radps = Vec3(0.0, 0.0, mean_motion_radps_),
      .omega_dot_lvlh_radps2 = Vec3::Zero(),  // a circle turns at a constant rate
      .target_radius_m = radius_m_,
  };
}

}  // namespace chaser::model
