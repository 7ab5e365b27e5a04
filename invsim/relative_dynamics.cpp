#include "invsim/relative_dynamics.hpp"

#include <cmath>

#include "core/hill_frames.hpp"
#include "core/rotation.hpp"
#include "plant/relative_orbit.hpp"

namespace chaser::invsim {

RvdConstants make_rvd_constants(double mu, double radius, double mass, const Mat3& inertia,
                                double max_substep_s) {
  plant::DynamicsParams d;
  d.orbit = model::TargetOrbit(mu, radius);
  d.inertia_kgm2 = inertia;
  d.inertia_inv = inertia.inverse();
  d.gravity_gradient = false;
  d.max_substep_s = max_substep_s;
  return {d, mass};
}

Vec3 relative_gravity_accel(const RvdConstants& c, const Vec3& r, const Vec3& v) {
  return hill_from_lvlh(plant::relative_orbit_acceleration_lvlh(
      c.dynamics.orbit.radius_m(), c.dynamics.orbit.mean_motion_radps(), lvlh_from_hill(r), lvlh_from_hill(v)));
}

Vec3 relative_rate_body(const RvdConstants& c, const RvdState& s) {
  return s.omega_body_radps -
         s.q_hill_from_body.toRotationMatrix().transpose() * omega_hill_in_hill(c.dynamics.orbit.mean_motion_radps());
}

plant::RigidState plant_state(const RvdConstants& c, const RvdState& s) {
  plant::RigidState x;
  x.r_lvlh_m = lvlh_from_hill(s.r_hill_m);
  x.v_lvlh_mps = lvlh_from_hill(s.v_hill_mps);
  x.q_inertial_from_body = q_lvlh_from_hill() * s.q_hill_from_body;
  x.omega_body_radps = s.omega_body_radps;
  x.mass_kg = c.mass_kg;
  return x;
}

void propagate_piece(const RvdConstants& c, const Vec3& force, const Vec3& torque, double dt,
                     RvdState& s) {
  if (!(dt > 0.0)) return;
  // The piece's inertial frame is LVLH at the piece's start (t0 = 0 below): the equations do not
  // depend on which inertial frame is chosen, so re-basing it at every piece is exact and spares
  // invsim a run clock. At the end LVLH has turned by n dt about its z axis in that frame.
  plant::RigidState x = plant_state(c, s);
  plant::propagate_piece(c.dynamics, x, 0.0, dt,
                         plant::PieceInput{.force_body_N = force, .torque_body_Nm = torque});
  s.r_hill_m = hill_from_lvlh(x.r_lvlh_m);
  s.v_hill_mps = hill_from_lvlh(x.v_lvlh_mps);
  const Quat q_lvlh_from_inertial = c.dynamics.orbit.q_inertial_from_lvlh(dt).conjugate();
  s.q_hill_from_body = (q_hill_from_lvlh() * q_lvlh_from_inertial * x.q_inertial_from_body).normalized();
  s.omega_body_radps = x.omega_body_radps;
}

}  // namespace chaser::invsim
