#pragma once
// The coupled body-and-slosh system of model/slosh.hpp integrated on its own (RK4, the pendulums put
// back on their spheres after each step, as the plant does), and its invariants: the tests' harness.
#include <cstddef>
#include <vector>

#include "core/rotation.hpp"
#include "plant/rigid_body.hpp"
#include "model/slosh.hpp"

namespace chaser::model::slosh_harness {

// The whole coupled system: the body's CoM in inertial axes, attitude, rate, and each slosh state.
struct System {
  RigidBodyMassProps body;
  std::vector<SloshTankParams> tanks;
  Vec3 force_body_N = Vec3::Zero();
  Vec3 torque_body_Nm = Vec3::Zero();
};

struct FullState {
  Vec3 r_inertial_m = Vec3::Zero();
  Vec3 v_inertial_mps = Vec3::Zero();
  Quat q_inertial_from_body = Quat::Identity();
  Vec3 omega_body_radps = Vec3::Zero();
  std::vector<SloshState> slosh;
};

struct Derivative {
  Vec3 r_dot, v_dot;
  Eigen::Vector4d q_dot;
  Vec3 omega_dot;
  std::vector<SloshState> slosh_dot;  // (s', s'')
};

inline Derivative derivative(const System& sys, const FullState& x) {
  const SloshAccelerations acc = coupled_accelerations(sys.body, sys.tanks, x.slosh, x.omega_body_radps,
                                                       sys.force_body_N, sys.torque_body_Nm);
  Derivative d;
  d.r_dot = x.v_inertial_mps;
  d.v_dot = x.q_inertial_from_body * acc.a_com_body_mps2;
  d.q_dot = plant::quat_derivative(x.q_inertial_from_body, x.omega_body_radps);
  d.omega_dot = acc.omega_dot_body_radps2;
  for (std::size_t i = 0; i < x.slosh.size(); ++i)
    d.slosh_dot.push_back({acc.s_dot_body_mps[i], acc.s_ddot_body_mps2[i]});
  return d;
}

inline FullState advanced(const FullState& x, const Derivative& d, double h) {
  FullState y = x;
  y.r_inertial_m += h * d.r_dot;
  y.v_inertial_mps += h * d.v_dot;
  y.q_inertial_from_body.coeffs() += h * d.q_dot;
  y.omega_body_radps += h * d.omega_dot;
  for (std::size_t i = 0; i < x.slosh.size(); ++i) {
    y.slosh[i].s_body_m += h * d.slosh_dot[i].s_body_m;
    y.slosh[i].s_dot_body_mps += h * d.slosh_dot[i].s_dot_body_mps;
  }
  return y;
}

// Classical RK4; the quaternion is re-normalised after the step and the pendulums put back on their
// spheres (as the propagator does).
inline void rk4_step(const System& sys, FullState& x, double h) {
  const Derivative k1 = derivative(sys, x);
  const Derivative k2 = derivative(sys, advanced(x, k1, 0.5 * h));
  const Derivative k3 = derivative(sys, advanced(x, k2, 0.5 * h));
  const Derivative k4 = derivative(sys, advanced(x, k3, h));
  x = advanced(x, k1, h / 6.0);
  x = advanced(x, k2, h / 3.0);
  x = advanced(x, k3, h / 3.0);
  x = advanced(x, k4, h / 6.0);
  x.q_inertial_from_body.normalize();
  for (std::size_t i = 0; i < x.slosh.size(); ++i) x.slosh[i] = on_constraint(sys.tanks[i], x.slosh[i]);
}

inline Vec3 linear_momentum(const System& sys, const FullState& x) {
  return total_linear_momentum_inertial(sys.body, sys.tanks, x.slosh, x.q_inertial_from_body, x.v_inertial_mps,
                                        x.omega_body_radps);
}
inline Vec3 angular_momentum(const System& sys, const FullState& x) {
  return total_angular_momentum_inertial(sys.body, sys.tanks, x.slosh, x.q_inertial_from_body, x.v_inertial_mps,
                                         x.omega_body_radps);
}
inline double energy(const System& sys, const FullState& x) {
  return total_kinetic_energy(sys.body, sys.tanks, x.slosh, x.q_inertial_from_body, x.v_inertial_mps,
                              x.omega_body_radps) +
         slosh_spring_energy(sys.tanks, x.slosh);
}

// Period of s_i . e from its zero crossings (linear interpolation; at a crossing s'' = -omega^2 s is
// zero, so the chord's error is O(h^3)), averaged over the whole run.
inline double measured_period(const System& sys, FullState x, std::size_t i, const Vec3& e, double h, int steps) {
  double first = -1.0, last = -1.0;
  int crossings = 0;
  for (int k = 0; k < steps; ++k) {
    const double before = x.slosh[i].s_body_m.dot(e);
    rk4_step(sys, x, h);
    const double after = x.slosh[i].s_body_m.dot(e);
    if ((before < 0.0) != (after < 0.0)) {
      const double t = h * (k + before / (before - after));
      if (first < 0.0) first = t;
      last = t;
      ++crossings;
    }
  }
  return 2.0 * (last - first) / (crossings - 1);
}

// A chaser-like body: 1500 kg, non-diagonal inertia (principal axes turned), CoM off the origin.
inline RigidBodyMassProps chaser_body() {
  const Mat3 rot = quat_from_rotation_vector(Vec3(0.2, -0.4, 0.3)).toRotationMatrix();
  RigidBodyMassProps body;
  body.mass_kg = 1500.0;
  body.inertia_com_body_kgm2 = rot * Vec3(900.0, 1200.0, 1500.0).asDiagonal() * rot.transpose();
  body.com_body_m = Vec3(0.05, -0.03, 0.8);
  return body;
}

}  // namespace chaser::model::slosh_harness
