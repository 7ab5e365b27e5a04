#pragma once
// Rotations, quaternions and frame conventions.
//
// Quaternions are Hamilton, scalar first in files, and named q_to_from: q_inertial_from_body maps a
// vector's body-frame components to inertial-frame components, v_inertial = q * v_body.
//
// Two Hill (LVLH) frames appear in the papers:
//  - MSR (Fonod 2015): x radial out (zenith), y along-track, z orbit normal. Used by the MSR scenario.
//  - Manual RVD (Zhou 2018): x along-track, y opposite the orbit normal, z towards the planet (nadir).
// The inertial frame of a run is the MSR LVLH frame at t = 0; where LVLH is at a later time is the
// target orbit's answer (model/target_orbit.hpp), not a formula of this file.
#include "core/types.hpp"

namespace chaser {

// Cross-product matrix: skew(a) * b = a x b.
Mat3 skew(const Vec3& a);

// Unit quaternion of the rotation by |rotation_vector| about its direction (exponential map).
// Exact for all angles; uses a Taylor branch below 1e-8 rad where sin(x)/x loses accuracy.
Quat quat_from_rotation_vector(const Vec3& rotation_vector);

// Inverse of quat_from_rotation_vector, choosing the shorter of q and -q (angle in [0, pi]).
// Below 0.9 deg a series replaces atan2 (equal to it within 2 ulp; tested).
Vec3 rotation_vector_from_quat(const Quat& q);

// The rotation by `fraction` of the angle from u to v (unit vectors) about u x v: the least rotation
// that takes u onto v at fraction 1. When u and v are (anti)parallel, about a fixed perpendicular of
// u (z x u, or x x u when u is along z).
Quat rotation_towards(const Vec3& u, const Vec3& v, double fraction);

// Attitude error as a rotation vector in the body frame: the rotation that takes the desired body
// frame to the actual one, q_desired_from_body = q_inertial_from_desired^-1 * q_inertial_from_body.
Vec3 attitude_error_body(const Quat& q_inertial_from_desired, const Quat& q_inertial_from_body);

// The same error in small-angle coordinates: 2 vec(q_desired_from_body), of the shorter of q and -q.
// Its direction is the rotation vector's and its length 2 sin(angle / 2), the angle less angle^3 / 24
// (3e-7 rad at 1 deg): the rotation vector, Euler angles or any other small-angle coordinates to
// first order, where a linearised attitude model (Fonod 2015, eq. 15) makes no difference between
// them. No division, no series: it runs in the attitude FDI scheme every control period.
Vec3 small_angle_error_body(const Quat& q_inertial_from_desired, const Quat& q_inertial_from_body);


// Converts between the MSR and the manual-RVD Hill frames (a fixed permutation with signs).
Vec3 zhou_from_msr(const Vec3& v_msr);
Vec3 msr_from_zhou(const Vec3& v_zhou);

}  // namespace chaser
