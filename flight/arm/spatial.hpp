#pragma once
// Spatial vectors in Pluecker coordinates (Featherstone, "Rigid Body Dynamics Algorithms", 2008,
// ch. 2), all in WORLD axes about one point O fixed in the world: the point where the hub's origin
// is at this instant (so that the numbers stay of the arm's size wherever the servicer flies).
// A motion vector is (omega; v_O), the angular velocity and the velocity of the body point passing
// through O; a force vector is (n_O; f), the moment about O and the force. With every body in
// the one frame, no coordinate transform X appears: a composite inertia is a plain sum.
#include "core/types.hpp"

namespace chaser::flight::arm {

// Angular rows first, as Featherstone writes them.
inline Vec3 angular(const Vec6& s) { return s.head<3>(); }
inline Vec3 linear(const Vec6& s) { return s.tail<3>(); }
inline Vec6 spatial(const Vec3& angular_part, const Vec3& linear_part) {
  Vec6 s;
  s << angular_part, linear_part;
  return s;
}

// A rigid body's spatial inertia about O (RBDA sec. 2.13), kept as its three parts: the mass m,
// h = m c (c the CoM from O) and the rotational inertia about O, I_c - m [c]x [c]x.
struct SpatialInertia {
  double mass_kg = 0.0;
  Vec3 h_kgm = Vec3::Zero();              // [kg m] first mass moment about O, world axes
  Mat3 inertia_o_kgm2 = Mat3::Zero();     // [kg m^2] about O, world axes
};

inline Mat3 cross_matrix(const Vec3& v) {
  Mat3 m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

// A body of mass m whose CoM is at c_o_m from O, with inertia about its CoM in world axes.
inline SpatialInertia spatial_inertia(double mass_kg, const Vec3& c_o_m, const Mat3& inertia_com_world_kgm2) {
  const Mat3 c_cross = cross_matrix(c_o_m);
  return {mass_kg, mass_kg * c_o_m, inertia_com_world_kgm2 - mass_kg * c_cross * c_cross};
}

// Bodies joined rigidly: the composite's inertia, a sum when both are about one point in one frame.
inline SpatialInertia operator+(const SpatialInertia& a, const SpatialInertia& b) {
  return {a.mass_kg + b.mass_kg, a.h_kgm + b.h_kgm, a.inertia_o_kgm2 + b.inertia_o_kgm2};
}

// The momentum I m of a body moving with m = (omega; v_O): (I_O omega + h x v_O; m v_O - h x omega).
inline Vec6 operator*(const SpatialInertia& inertia, const Vec6& motion) {
  const Vec3 omega = angular(motion), v_o = linear(motion);
  return spatial(inertia.inertia_o_kgm2 * omega + inertia.h_kgm.cross(v_o),
                 inertia.mass_kg * v_o - inertia.h_kgm.cross(omega));
}

// The motion subspace S of a hinge about the unit axis a through the point r from O (RBDA ch. 4,
// in one frame): (a; r x a), since the body point at O moves at a x (O - r) per unit rate.
inline Vec6 hinge_subspace(const Vec3& axis_world, const Vec3& r_o_m) {
  return spatial(axis_world, r_o_m.cross(axis_world));
}

// The spatial cross products (RBDA ch. 2): v x m on a motion, v x* f on a force.
inline Vec6 cross_motion(const Vec6& v, const Vec6& m) {
  return spatial(angular(v).cross(angular(m)), angular(v).cross(linear(m)) + linear(v).cross(angular(m)));
}
inline Vec6 cross_force(const Vec6& v, const Vec6& f) {
  return spatial(angular(v).cross(angular(f)) + linear(v).cross(linear(f)), angular(v).cross(linear(f)));
}

}  // namespace chaser::flight::arm
