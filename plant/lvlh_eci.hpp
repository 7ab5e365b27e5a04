#pragma once
// The target's LVLH frame from its inertial state, and the chaser's relative state between ECI and
// LVLH, for runs whose target flies a perturbed Earth orbit.
//
// LVLH here is the MSR convention the whole core uses (docs/dynamics.md, "Frames"): centred on the
// target, x radial out (zenith), z along the orbital angular momentum h = r x v, y = z x x (along
// the velocity for a circular orbit). In the ESA convention (R-bar down, V-bar ahead, H-bar
// opposite to h) H-bar is -z here.
//
// The frame turns at omega = (r / |h|) (a . z) x + (|h| / r^2) z (Vallado 2013, sec. 6.7; Casotto 2016):
// the z part is the orbit's angular rate; the x part turns the orbit plane about the radius and is
// the out-of-plane acceleration a . z over the along-track speed, e.g. 1.7e-6 rad/s from J2 in a
// polar LEO (1.7e-4 m/s of apparent velocity at 100 m: not negligible for navigation).
#include "core/types.hpp"

namespace chaser::plant {

struct LvlhOfTarget {
  Mat3 lvlh_from_eci = Mat3::Identity();  // rows: x, y, z of LVLH in ECI components
  Vec3 omega_lvlh_radps = Vec3::Zero();   // [rad/s] LVLH's angular velocity w.r.t. ECI, LVLH axes
};

// The axes alone (rows x, y, z of LVLH in ECI components): from the position and velocity.
Mat3 lvlh_axes_from_eci(const Vec3& r_eci_m, const Vec3& v_eci_mps);

// LVLH of a target at r_eci_m [m], v_eci_mps [m/s], with inertial acceleration a_eci_mps2 [m/s^2]
// (its gravity and perturbations: only the component along h matters, for the rate).
LvlhOfTarget lvlh_of_target(const Vec3& r_eci_m, const Vec3& v_eci_mps, const Vec3& a_eci_mps2);

// The chaser's relative position and velocity as seen in the rotating LVLH frame
// (r_lvlh = C dr, v_lvlh = C dv - omega x r_lvlh) and back.
struct RelativeLvlh {
  Vec3 r_lvlh_m = Vec3::Zero();
  Vec3 v_lvlh_mps = Vec3::Zero();  // time derivative of r_lvlh_m in the rotating frame
};
struct RelativeEci {
  Vec3 dr_eci_m = Vec3::Zero();    // chaser CoM minus target CoM
  Vec3 dv_eci_mps = Vec3::Zero();  // inertial velocity difference
};
RelativeLvlh relative_lvlh_from_eci(const LvlhOfTarget& frame, const RelativeEci& rel);
RelativeEci relative_eci_from_lvlh(const LvlhOfTarget& frame, const RelativeLvlh& rel);

}  // namespace chaser::plant
