#pragma once
// Guidance for the last 20 m (Fonod 2015, section II.D and Fig. 5): a forced straight-line approach
// along the corridor axis, then a hold at the capture point, with target-pointing attitude.
//
// Distance from the target along the unit axis u (guidance.approach_axis_lvlh, target -> chaser):
//   d(t) = d0 + (d1 - d0) sigma(t),   r_ref = d u,  v_ref = d' u,  a_ref = d'' u,  j_ref = d''' u,
// where sigma goes 0 -> 1 over [0, D] with a cosine speed blend of length tb at each end:
//   sigma'(t) = w(t) / (D - tb),  w = (1 - cos(pi t / tb)) / 2 on [0, tb], 1 in the cruise, and the
//   mirror image on [D - tb, D]. Position, speed and acceleration are continuous (no jerk impulses
// for the controller), and sigma(D) = 1 exactly. The jerk is given so that the controller can
// feed forward the acceleration averaged over the coming period (it jumps at phase boundaries).
// Before t = 0 the reference holds at d0, after D at d1.
// If D < 2 tb the blend is shortened to D / 2 (a pure cosine profile); D <= 0 means "hold at d1".
//
// Attitude: body +x points at the target (along -u). Roll: body +z is the LVLH +z (orbit normal)
// made orthogonal to body x; if the axis is within ~25 deg of the orbit normal, LVLH +x (radial)
// is used instead. For the default V-bar approach (u = -y) this is a +90 deg turn about LVLH z:
// body x = LVLH +y, body y = LVLH -x (nadir), body z = LVLH +z. The line is fixed in LVLH, so the
// attitude is constant in LVLH and turns with it at the orbit rate n about LVLH z.
#include "core/types.hpp"
#include "model/gnc.hpp"
#include "model/target_orbit.hpp"

namespace chaser::flight {

struct GuidanceRef {
  Vec3 r_lvlh_m = Vec3::Zero();        // [m] reference position
  Vec3 v_lvlh_mps = Vec3::Zero();      // [m/s] d/dt r_lvlh_m (LVLH-frame derivative)
  Vec3 a_lvlh_mps2 = Vec3::Zero();     // [m/s^2] d/dt v_lvlh_mps
  Vec3 j_lvlh_mps3 = Vec3::Zero();     // [m/s^3] d/dt a_lvlh_mps2 (jerk)
  Quat q_inertial_from_body = Quat::Identity();  // reference attitude
  Vec3 omega_body_radps = Vec3::Zero();          // [rad/s] reference inertial rate, body axes
};

// Distance from the target along the axis and its first two time derivatives.
struct ApproachProfile {
  double distance_m = 0.0;     // [m]
  double rate_mps = 0.0;       // [m/s]  (negative while closing)
  double accel_mps2 = 0.0;     // [m/s^2]
  double jerk_mps3 = 0.0;      // [m/s^3]
};
ApproachProfile approach_profile(const model::GuidanceParams& params, double t_s);

// Constant target-pointing attitude of the body relative to LVLH for an approach axis.
Quat target_pointing_q_lvlh_from_body(const Vec3& approach_axis_lvlh);

// The full reference at time t (a pure function of time; allocation-free), in the target's LVLH
// frame at t as the orbit model gives it.
GuidanceRef guidance_reference(const model::GuidanceParams& params, double t_s, const model::LvlhFrame& lvlh);
inline GuidanceRef guidance_reference(const model::GuidanceParams& params, const model::TargetOrbit& orbit, double t_s) {
  return guidance_reference(params, t_s, orbit.lvlh_at(t_s));
}

}  // namespace chaser::flight
