#pragma once
// The two Hill (local orbital) frames of the papers, and the constant rotation between them.
//
//   LVLH, MSR convention (Fonod 2015, eq. 7): x radial out (zenith), y along-track, z orbit normal;
//     the product's truth dynamics (plant/) are written in it.
//   Hill, manual-RVD convention (Zhou 2018, eq. 1, Fig. 2): x along-track, y opposite the orbit
//     normal, z towards the planet (nadir); the inverse simulation (invsim/) is written in it.
//
// Both have their origin at the target's centre of mass and turn together at the orbital rate, so
// one constant rotation maps every vector between them: positions, velocities relative to the
// rotating frame (d/dt of a constant map is the map of d/dt), accelerations and forces.
//   r_lvlh = C_lvlh_from_hill r_hill,  C_lvlh_from_hill = [[0, 0, -1], [1, 0, 0], [0, -1, 0]]
// (a proper rotation, det +1: 120 deg about (-1, -1, 1) / sqrt(3)), the quaternion
//   q_lvlh_from_hill = (w, x, y, z) = (1/2, -1/2, -1/2, 1/2),
// whose components are exact in binary. The orbital rate, the frames' common angular velocity
// relative to inertial, is (0, 0, n) in LVLH components and (0, -n, 0) in Hill components.
//
// The vector maps are the signed permutations zhou_from_msr / msr_from_zhou of core/rotation.hpp
// (exact: no arithmetic); the quaternion is for composing attitudes.
#include "core/types.hpp"

namespace chaser {

// Any vector's components: Hill -> LVLH and back. Exact (a signed permutation).
Vec3 lvlh_from_hill(const Vec3& v_hill);
Vec3 hill_from_lvlh(const Vec3& v_lvlh);

// A relative state [r; v] (position [m], velocity in the rotating frame [m/s]). Exact.
Vec6 lvlh_state_from_hill(const Vec6& x_hill);
Vec6 hill_state_from_lvlh(const Vec6& x_lvlh);

// The constant rotation as a unit quaternion, v_lvlh = q_lvlh_from_hill() * v_hill.
Quat q_lvlh_from_hill();
Quat q_hill_from_lvlh();

// The orbital rate [rad/s], the angular velocity of both frames relative to inertial, in Hill
// components: (0, -n, 0) (the vector of Zhou 2018, eq. 11). In LVLH components it is (0, 0, n), the
// rate model::TargetOrbit gives for a circular orbit; the two are the same vector (tested).
Vec3 omega_hill_in_hill(double mean_motion_radps);

}  // namespace chaser
