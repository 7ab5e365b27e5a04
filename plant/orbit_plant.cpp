#include "plant/orbit_plant.hpp"

#include <cmath>

#include <Eigen/LU>

#include "core/constants.hpp"
#include "plant/earth/inertial_orbit.hpp"
#include "plant/earth/magnetic_field.hpp"
#include "plant/earth/moon.hpp"
#include "plant/earth/sun.hpp"
#include "plant/lvlh_eci.hpp"

namespace chaser::plant {

namespace {

constexpr double kSecondsPerDay = 86400.0;

earth::InertialState initial_target_orbit(const model::Scenario& s) {
  const model::EarthOrbitParams& e = *s.orbit.earth;
  return earth::circular_orbit_state(s.orbit.mu_m3ps2, s.orbit.radius_m(), e.inclination_rad, e.raan_rad,
                                     e.argument_of_latitude_rad);
}

OrbitBodyParams body_surface(const model::OrbitBodySurface& b) {
  return {.ballistic_coefficient_kgpm2 = b.ballistic_coefficient_kgpm2,
          .area_to_mass_m2pkg = b.area_to_mass_m2pkg,
          .reflectivity = b.reflectivity};
}

BodyTorqueParams body_torques(const Mat3& inertia, bool gravity_gradient, bool magnetic, const Vec3& dipole_Am2) {
  return {.inertia_kgm2 = inertia,
          .inertia_inv = inertia.inverse(),
          .gravity_gradient = gravity_gradient,
          .magnetic = magnetic && !dipole_Am2.isZero(0.0),
          .residual_dipole_body_Am2 = dipole_Am2};
}

}  // namespace

OrbitPlantParams make_orbit_plant_params(const model::Scenario& s) {
  const model::EarthOrbitParams& e = *s.orbit.earth;
  const model::TargetBodyParams& target = *s.target.body;
  OrbitPlantParams p;
  const model::CalendarTime& t = e.epoch_tt;
  p.epoch_jd_tt = earth::julian_date(t.year, t.month, t.day, t.hour, t.minute, t.second);

  OrbitPerturbationParams& pert = p.dynamics.perturbations;
  pert.gravity = {.mu_m3ps2 = s.orbit.mu_m3ps2, .radius_m = s.orbit.body_radius_m, .j2 = e.j2};
  pert.drag = e.drag;
  pert.solar_pressure = e.solar_pressure;
  pert.eclipses = e.eclipses;
  pert.sun_gravity = e.sun_gravity;
  pert.moon_gravity = e.moon_gravity;
  pert.target = body_surface(e.target);
  pert.chaser = body_surface(e.chaser);

  p.dynamics.epoch_jd_tt = p.epoch_jd_tt;
  const earth::InertialState t0 = initial_target_orbit(s);
  p.dynamics.run_from_eci = lvlh_axes_from_eci(t0.r_eci_m, t0.v_eci_mps);
  p.dynamics.chaser = body_torques(s.chaser.inertia_kgm2, s.environment.gravity_gradient, e.magnetic_torque,
                                   e.chaser.residual_dipole_body_Am2);
  p.dynamics.target = body_torques(target.inertia_kgm2, target.gravity_gradient, e.magnetic_torque,
                                   e.target.residual_dipole_body_Am2);
  if (s.chaser.slosh) p.dynamics.slosh = model::chaser_slosh(s.chaser);
  return p;
}

TargetSpin initial_target_spin(const model::TargetParams& target) {
  const model::SpinCase spin = target.body ? target.body->spin_case : model::SpinCase::given;
  if (spin == model::SpinCase::given)
    return {target.q_inertial_from_target, target.q_inertial_from_target.conjugate() * target.omega_inertial_radps};

  const Vec3 h_bar = -Vec3::UnitZ();                            // ESA H-bar in MSR LVLH
  const Quat s1(Eigen::AngleAxisd(-0.5 * kPi, Vec3::UnitX()));  // target +Y -> H-bar
  Quat q_inertial_from_target;
  Vec3 spin_axis_target;
  switch (spin) {
    case model::SpinCase::s1:
      spin_axis_target = Vec3::UnitY();
      q_inertial_from_target = s1;
      break;
    case model::SpinCase::s2:  // turn the axis onto +Y about target x, then S1's attitude
      spin_axis_target = Vec3(0.0, 1.0, 1.0).normalized();
      q_inertial_from_target = s1 * Quat::FromTwoVectors(spin_axis_target, Vec3::UnitY());
      break;
    default: {  // S3 (given returned above): +Z along (R-bar + H-bar) / sqrt(2), +X along-track
      spin_axis_target = Vec3::UnitZ();
      const Vec3 z_axis = (-Vec3::UnitX() + h_bar).normalized();
      const Vec3 x_axis = Vec3::UnitY();
      Mat3 lvlh_from_target;
      lvlh_from_target << x_axis, z_axis.cross(x_axis), z_axis;
      q_inertial_from_target = Quat(lvlh_from_target);
    }
  }
  return {q_inertial_from_target, target.body->spin_rate_radps * spin_axis_target};
}

OrbitState initial_orbit_state(const model::Scenario& s, const OrbitPlantParams& p, const Vec3& r_lvlh_m,
                               const Vec3& v_lvlh_mps) {
  const earth::InertialState t0 = initial_target_orbit(s);
  const Ephemeris eph = ephemeris_at_run_time(p, 0.0);
  const LvlhOfTarget frame = lvlh_of_target(
      t0.r_eci_m, t0.v_eci_mps, target_acceleration_eci(p.dynamics.perturbations, eph, t0.r_eci_m, t0.v_eci_mps));
  const RelativeEci rel = relative_eci_from_lvlh(frame, {r_lvlh_m, v_lvlh_mps});
  const TargetSpin spin = initial_target_spin(s.target);
  OrbitState o;
  o.r_t_eci_m = t0.r_eci_m;
  o.v_t_eci_mps = t0.v_eci_mps;
  o.dr_eci_m = rel.dr_eci_m;
  o.dv_eci_mps = rel.dv_eci_mps;
  o.q_inertial_from_target = spin.q_inertial_from_target;
  o.omega_target_body_radps = spin.omega_target_body_radps;
  return o;
}

Ephemeris ephemeris_at_run_time(const OrbitPlantParams& p, double t_s) {
  return ephemeris_at(p.epoch_jd_tt + t_s / kSecondsPerDay);
}

Ephemeris ephemeris_at_run_time(const OrbitPlantParams& p, double t_s, EphemerisSamples& samples) {
  const auto index = static_cast<std::int64_t>(std::floor(t_s / kEphemerisSampleS));
  if (index != samples.index) {
    const double t0_s = static_cast<double>(index) * kEphemerisSampleS;
    const double jd0 = p.epoch_jd_tt + t0_s / kSecondsPerDay;
    const double jd1 = p.epoch_jd_tt + (t0_s + kEphemerisSampleS) / kSecondsPerDay;
    samples = {.index = index,
               .sun0_eci_m = earth::sun_position_eci_m(jd0),
               .sun1_eci_m = earth::sun_position_eci_m(jd1),
               .moon0_eci_m = earth::moon_position_eci_m(jd0),
               .moon1_eci_m = earth::moon_position_eci_m(jd1)};
  }
  const double f = (t_s - static_cast<double>(index) * kEphemerisSampleS) / kEphemerisSampleS;
  return {.sun_eci_m = samples.sun0_eci_m + f * (samples.sun1_eci_m - samples.sun0_eci_m),
          .moon_eci_m = samples.moon0_eci_m + f * (samples.moon1_eci_m - samples.moon0_eci_m),
          .ecef_from_eci = earth::ecef_from_eci(p.epoch_jd_tt + t_s / kSecondsPerDay)};
}

}  // namespace chaser::plant
