#include "plant/slosh.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <cstddef>

namespace chaser::plant {

SloshTankFill slosh_tank_from_fill(const CylindricalTank& tank, double liquid_mass_kg, double fill_height_m,
                                   double g_eff_mps2, double damping_ratio) {
  const double xi = kSloshXi1, r = tank.radius_m, h = fill_height_m;
  const double depth_factor = std::tanh(xi * h / r);
  SloshTankFill fill;
  // Dodge 2000, ch. 3 (Abramson 1966, Table 6.1): omega1, m1, and L1 above the liquid's centre.
  fill.omega_radps = std::sqrt(g_eff_mps2 * xi / r * depth_factor);
  const double m1 = liquid_mass_kg * 2.0 * r * depth_factor / (xi * (xi * xi - 1.0) * h);
  fill.slosh_height_m = h - 2.0 * r / xi * std::tanh(xi * h / (2.0 * r));  // h/2 + L1
  fill.fixed_mass_kg = liquid_mass_kg - m1;
  fill.fixed_height_m = (liquid_mass_kg * 0.5 * h - m1 * fill.slosh_height_m) / fill.fixed_mass_kg;
  fill.fixed_mass_body_m = tank.bottom_centre_body_m + fill.fixed_height_m * tank.axis_body;

  fill.slosh.anchor_body_m = tank.bottom_centre_body_m + fill.slosh_height_m * tank.axis_body;
  fill.slosh.axis_body = tank.axis_body;
  fill.slosh.mass_kg = m1;
  fill.slosh.stiffness_Npm = m1 * fill.omega_radps * fill.omega_radps;
  fill.slosh.damping_Nspm = 2.0 * damping_ratio * m1 * fill.omega_radps;
  return fill;
}

namespace {

std::size_t tank_count(std::span<const SloshTankParams> tanks, std::span<const SloshState> states) {
  return std::min({tanks.size(), states.size(), static_cast<std::size_t>(kMaxSloshTanks)});
}

// The lateral part of v: P v = v - n (n . v).
Vec3 lateral(const Vec3& n, const Vec3& v) { return v - n * n.dot(v); }

// One mass's kinematics and spring-damper force, with s and s' on the constraint.
struct MassTerms {
  Vec3 s, s_dot;  // lateral displacement [m] and rate [m/s], body frame
  Vec3 r;         // [m] p_i - c: from the body's CoM to the mass
  Vec3 f;         // [N] spring-damper force on the mass
};

MassTerms mass_terms(const RigidBodyMassProps& body, const SloshTankParams& tank, const SloshState& state) {
  MassTerms t;
  t.s = lateral(tank.axis_body, state.s_body_m);
  t.s_dot = lateral(tank.axis_body, state.s_dot_body_mps);
  t.r = tank.anchor_body_m + t.s - body.com_body_m;
  t.f = -tank.stiffness_Npm * t.s - tank.damping_Nspm * t.s_dot;
  return t;
}

// The mass's inertial velocity less the body CoM's, body axes: omega x r + s'.
Vec3 velocity_from_com(const MassTerms& t, const Vec3& omega) { return omega.cross(t.r) + t.s_dot; }

}  // namespace

SloshAccelerations coupled_accelerations(const RigidBodyMassProps& body, std::span<const SloshTankParams> tanks,
                                         std::span<const SloshState> states, const Vec3& omega,
                                         const Vec3& force, const Vec3& torque) {
  const std::size_t count = tank_count(tanks, states);
  std::array<MassTerms, kMaxSloshTanks> terms;
  std::array<Vec3, kMaxSloshTanks> centripetal_coriolis;  // w x (w x r_i) + 2 w x s_i'

  // Body Newton-Euler with each mass's lambda_i eliminated (header): A (a_c, omega') = rhs, with
  // A = diag(M, I) + sum m_i J_i J_i^T, J_i = (n_i, r_i x n_i), symmetric positive definite.
  Mat6 a = Mat6::Zero();
  a.topLeftCorner<3, 3>() = body.mass_kg * Mat3::Identity();
  a.bottomRightCorner<3, 3>() = body.inertia_com_body_kgm2;
  Vec6 rhs;
  rhs.head<3>() = force;
  rhs.tail<3>() = torque - omega.cross(body.inertia_com_body_kgm2 * omega);
  for (std::size_t i = 0; i < count; ++i) {
    const SloshTankParams& tank = tanks[i];
    const MassTerms& t = terms[i] = mass_terms(body, tank, states[i]);
    centripetal_coriolis[i] = omega.cross(omega.cross(t.r)) + 2.0 * omega.cross(t.s_dot);
    Vec6 j;
    j.head<3>() = tank.axis_body;
    j.tail<3>() = t.r.cross(tank.axis_body);
    const double b = tank.axis_body.dot(centripetal_coriolis[i]);
    a.noalias() += tank.mass_kg * j * j.transpose();
    rhs.head<3>() -= t.f + tank.mass_kg * b * tank.axis_body;
    rhs.tail<3>() -= t.r.cross(t.f) + tank.mass_kg * b * j.tail<3>();
  }
  const Vec6 x = Eigen::LLT<Mat6>(a).solve(rhs);

  SloshAccelerations out;
  out.a_com_body_mps2 = x.head<3>();
  out.omega_dot_body_radps2 = x.tail<3>();
  for (std::size_t i = 0; i < count; ++i) {
    const SloshTankParams& tank = tanks[i];
    // The tank point under the mass, inertial acceleration: a_ref + w' x p + w x (w x p) + 2 w x s'
    // = a_c + w' x r + w x (w x r) + 2 w x s' (a_ref = a_c - w' x c - w x (w x c)).
    const Vec3 frame = out.a_com_body_mps2 + out.omega_dot_body_radps2.cross(terms[i].r) + centripetal_coriolis[i];
    out.s_ddot_body_mps2[i] = lateral(tank.axis_body, terms[i].f / tank.mass_kg - frame);
    out.axial_force_N[i] = tank.mass_kg * tank.axis_body.dot(frame);
  }
  return out;
}

Vec3 total_linear_momentum_inertial(const RigidBodyMassProps& body, std::span<const SloshTankParams> tanks,
                                    std::span<const SloshState> states, const Quat& q, const Vec3& v_com,
                                    const Vec3& omega) {
  Vec3 relative_body = Vec3::Zero();  // sum m_i (v_i - v_c), body axes
  double total_mass = body.mass_kg;
  for (std::size_t i = 0; i < tank_count(tanks, states); ++i) {
    relative_body += tanks[i].mass_kg * velocity_from_com(mass_terms(body, tanks[i], states[i]), omega);
    total_mass += tanks[i].mass_kg;
  }
  return total_mass * v_com + q * relative_body;
}

Vec3 total_angular_momentum_inertial(const RigidBodyMassProps& body, std::span<const SloshTankParams> tanks,
                                     std::span<const SloshState> states, const Quat& q, const Vec3& v_com,
                                     const Vec3& omega) {
  // In body axes, about the body's CoM first: positions r_i, velocities v_c + omega x r_i + s_i'.
  const std::size_t count = tank_count(tanks, states);
  const Vec3 v_com_body = q.conjugate() * v_com;
  double total_mass = body.mass_kg;
  Vec3 first_moment = Vec3::Zero();  // sum m_i r_i
  Vec3 h_body = body.inertia_com_body_kgm2 * omega;
  for (std::size_t i = 0; i < count; ++i) {
    const MassTerms t = mass_terms(body, tanks[i], states[i]);
    h_body += tanks[i].mass_kg * t.r.cross(v_com_body + velocity_from_com(t, omega));
    first_moment += tanks[i].mass_kg * t.r;
    total_mass += tanks[i].mass_kg;
  }
  // Moved to the system's CoM g = first_moment / total_mass: H_g = H_c - g x P.
  const Vec3 momentum_body = q.conjugate() * total_linear_momentum_inertial(body, tanks, states, q, v_com, omega);
  return q * (h_body - (first_moment / total_mass).cross(momentum_body));
}

double total_kinetic_energy(const RigidBodyMassProps& body, std::span<const SloshTankParams> tanks,
                            std::span<const SloshState> states, const Quat& q, const Vec3& v_com,
                            const Vec3& omega) {
  const Vec3 v_com_body = q.conjugate() * v_com;
  double twice = body.mass_kg * v_com.squaredNorm() + omega.dot(body.inertia_com_body_kgm2 * omega);
  for (std::size_t i = 0; i < tank_count(tanks, states); ++i) {
    const Vec3 v = v_com_body + velocity_from_com(mass_terms(body, tanks[i], states[i]), omega);
    twice += tanks[i].mass_kg * v.squaredNorm();
  }
  return 0.5 * twice;
}

double slosh_spring_energy(std::span<const SloshTankParams> tanks, std::span<const SloshState> states) {
  double twice = 0.0;
  for (std::size_t i = 0; i < tank_count(tanks, states); ++i)
    twice += tanks[i].stiffness_Npm * lateral(tanks[i].axis_body, states[i].s_body_m).squaredNorm();
  return 0.5 * twice;
}

}  // namespace chaser::plant
