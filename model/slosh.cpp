#include "model/slosh.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "core/constants.hpp"

namespace chaser::model {

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

SloshTankParams pendulum_analogue(const SloshTankFill& fill, const CylindricalTank& tank, double g_eff_mps2,
                                  double capillary_accel_mps2) {
  SloshTankParams p = fill.slosh;
  const double omega = fill.omega_radps, length = g_eff_mps2 / (omega * omega);  // (R / xi1) coth(xi1 h / R)
  p.stiffness_Npm = 0.0;
  p.pendulum_length_m = length;
  p.wall_angle_rad = length > tank.radius_m ? std::asin(tank.radius_m / length) : 0.5 * kPi;
  const double wall_omega = std::min(10.0 * omega, kMaxWallOmegaRadps);
  p.wall_stiffness_Npm = p.mass_kg * wall_omega * wall_omega;
  p.wall_damping_Nspm = 2.0 * p.mass_kg * wall_omega;  // critical
  p.capillary_accel_mps2 = capillary_accel_mps2;
  return p;
}

namespace {

using Mat4 = Eigen::Matrix4d;
using Vec4 = Eigen::Vector4d;

std::size_t tank_count(std::span<const SloshTankParams> tanks, std::span<const SloshState> states) {
  return std::min({tanks.size(), states.size(), static_cast<std::size_t>(kMaxSloshTanks)});
}

// The lateral part of v: P v = v - n (n . v). Forced inline, like mass_terms: GCC kept both as
// calls, a tenth of the kernel's time.
[[gnu::always_inline]] inline Vec3 lateral(const Vec3& n, const Vec3& v) { return v - n * n.dot(v); }

bool is_pendulum(const SloshTankParams& tank) { return tank.pendulum_length_m > 0.0; }

// The pendulum's rod direction u, from the mass to the hinge (n when the mass sits at the hinge).
Vec3 rod_direction(const SloshTankParams& tank, const Vec3& s) {
  const Vec3 from_hinge = s - tank.pendulum_length_m * tank.axis_body;
  const double norm = from_hinge.norm();
  return norm > 0.0 ? Vec3(-from_hinge / norm) : tank.axis_body;
}

// How far the pendulum's mass is pressed into the wall along its arc [m] (0 inside the bound), and
// the arc's outward unit tangent there, d(mass)/d(theta) / L = sin(theta) n + cos(theta) rho.
struct WallContact {
  double depth_m = 0.0;
  Vec3 outward = Vec3::Zero();
};
WallContact wall_contact(const SloshTankParams& tank, const Vec3& u, const Vec3& s) {
  const double cos_theta = std::clamp(u.dot(tank.axis_body), -1.0, 1.0);
  const double theta = std::acos(cos_theta);
  if (!(tank.wall_stiffness_Npm > 0.0) || theta <= tank.wall_angle_rad) return {};
  const Vec3 radial = lateral(tank.axis_body, s);
  const double radial_norm = radial.norm();
  if (!(radial_norm > 0.0)) return {};  // straight above the hinge, through the wall: no way to push
  return {tank.pendulum_length_m * (theta - tank.wall_angle_rad),
          std::sin(theta) * tank.axis_body + cos_theta * (radial / radial_norm)};
}

// One mass's kinematics and forces, with s and s' on the constraint.
struct MassTerms {
  Vec3 s, s_dot;  // displacement [m] and rate [m/s] from the anchor, body frame
  Vec3 r;         // [m] p_i - c: from the body's CoM to the mass
  Vec3 f;         // [N] spring-damper (and wall) force on the mass
  Vec3 u;         // the constraint force's direction: n, or the pendulum's rod (mass to hinge)
  double rod_centripetal = 0.0;  // [m/s^2] |s'|^2 / L, the pendulum's; 0 for the spring-mass
};

[[gnu::always_inline]] inline MassTerms mass_terms(const RigidBodyMassProps& body, const SloshTankParams& tank,
                                                  const SloshState& state) {
  MassTerms t;
  if (!is_pendulum(tank)) {
    t.u = tank.axis_body;
    t.s = lateral(tank.axis_body, state.s_body_m);
    t.s_dot = lateral(tank.axis_body, state.s_dot_body_mps);
    t.r = tank.anchor_body_m + t.s - body.com_body_m;
    t.f = -tank.stiffness_Npm * t.s - tank.damping_Nspm * t.s_dot;
    return t;
  }
  const double length = tank.pendulum_length_m;
  t.u = rod_direction(tank, state.s_body_m);
  t.s = length * (tank.axis_body - t.u);
  t.s_dot = lateral(t.u, state.s_dot_body_mps);
  t.r = tank.anchor_body_m + t.s - body.com_body_m;
  t.f = -tank.damping_Nspm * t.s_dot - (tank.mass_kg * tank.capillary_accel_mps2) * tank.axis_body;
  t.rod_centripetal = t.s_dot.squaredNorm() / length;
  const WallContact wall = wall_contact(tank, t.u, t.s);
  if (wall.depth_m > 0.0) {
    const double push = tank.wall_stiffness_Npm * wall.depth_m + tank.wall_damping_Nspm * wall.outward.dot(t.s_dot);
    if (push > 0.0) t.f -= push * wall.outward;
  }
  return t;
}

// lambda from (diag(1/m) + G) lambda = c, symmetric positive definite: Cramer's rule for one or
// two tanks (the common case), Cholesky for more (unused rows are identity and zero).
Vec4 solve_axial_forces(const Mat4& g, const Vec4& c, std::size_t count) {
  if (count == 1) return Vec4(c[0] / g(0, 0), 0.0, 0.0, 0.0);
  if (count == 2) {
    const double det = g(0, 0) * g(1, 1) - g(0, 1) * g(0, 1);  // > 0: positive definite
    return Vec4((g(1, 1) * c[0] - g(0, 1) * c[1]) / det, (g(0, 0) * c[1] - g(0, 1) * c[0]) / det, 0.0, 0.0);
  }
  return Eigen::LLT<Mat4>(g).solve(c);
}

// The mass's inertial velocity less the body CoM's, body axes: omega x r + s'.
Vec3 velocity_from_com(const MassTerms& t, const Vec3& omega) { return omega.cross(t.r) + t.s_dot; }

}  // namespace

SloshAccelerations coupled_accelerations(const RigidBodyMassProps& body, std::span<const SloshTankParams> tanks,
                                         std::span<const SloshState> states, const Vec3& omega,
                                         const Vec3& force, const Vec3& torque) {
  return coupled_accelerations(body, body.inertia_com_body_kgm2.inverse(), tanks, states, omega, force, torque);
}

SloshAccelerations coupled_accelerations(const RigidBodyMassProps& body, const Mat3& inertia_inv,
                                         std::span<const SloshTankParams> tanks, std::span<const SloshState> states,
                                         const Vec3& omega, const Vec3& force, const Vec3& torque) {
  // The header's 6x6 system A (a_c, omega') = rhs, A = diag(M, I) + sum m_i J_i J_i^T, solved through
  // the axial forces instead (the Woodbury identity, read physically): with lambda known, the body's
  // accelerations are explicit, and lambda solves a k x k system (k tanks): one or two tanks in
  // closed form, more by a 4x4 Cholesky, instead of a 6x6 one; tests/plant/slosh_test.cpp holds it
  // to the 6x6 form to round-off.
  const std::size_t count = tank_count(tanks, states);
  std::array<MassTerms, kMaxSloshTanks> terms;
  std::array<Vec3, kMaxSloshTanks> centripetal_coriolis;  // w x (w x r_i) + 2 w x s_i'
  std::array<Vec3, kMaxSloshTanks> turn;                  // I^-1 (r_i x n_i): omega' per unit lambda_i

  // The springs alone (lambda = 0): a0 = (F - sum f_i) / M, w0' = I^-1 (T - w x I w - sum r_i x f_i).
  Vec3 net_force = force;
  Vec3 net_torque = torque - omega.cross(body.inertia_com_body_kgm2 * omega);
  for (std::size_t i = 0; i < count; ++i) {
    const MassTerms& t = terms[i] = mass_terms(body, tanks[i], states[i]);
    centripetal_coriolis[i] = omega.cross(omega.cross(t.r) + 2.0 * t.s_dot);  // one cross product fewer
    turn[i] = inertia_inv * t.r.cross(t.u);
    net_force -= t.f;
    net_torque -= t.r.cross(t.f);
  }
  const double inv_mass = 1.0 / body.mass_kg;
  const Vec3 a0 = inv_mass * net_force;
  const Vec3 w0 = inertia_inv * net_torque;

  // lambda_i / m_i = n_i . a_c + (r_i x n_i) . omega' + n_i . cc_i, with a_c = a0 - sum lambda_j n_j / M
  // and omega' = w0' - sum lambda_j I^-1 (r_j x n_j):  (diag(1/m) + G) lambda = c, G symmetric positive
  // semi-definite (G_ij = n_i . n_j / M + (r_i x n_i) . I^-1 (r_j x n_j)). Unused rows stay identity.
  Mat4 g = Mat4::Identity();
  Vec4 c = Vec4::Zero();
  std::array<double, kMaxSloshTanks> inv_m{};  // 1 / m_i: one division per tank, not four
  // The pendulum's row adds its centripetal term and its own force's share along the rod, which the
  // spring-mass's lateral force does not have (n_i . f_i = 0).
  for (std::size_t i = 0; i < count; ++i) {
    inv_m[i] = 1.0 / tanks[i].mass_kg;
    const Vec3& n_i = terms[i].u;
    const Vec3 u_i = terms[i].r.cross(n_i);
    const auto ii = static_cast<Eigen::Index>(i);
    c[ii] = n_i.dot(a0 + centripetal_coriolis[i]) + u_i.dot(w0);
    if (is_pendulum(tanks[i])) c[ii] += terms[i].rod_centripetal - inv_m[i] * n_i.dot(terms[i].f);
    g(ii, ii) = inv_m[i] + inv_mass + u_i.dot(turn[i]);
    for (std::size_t j = 0; j < i; ++j) {
      const auto jj = static_cast<Eigen::Index>(j);
      g(ii, jj) = g(jj, ii) = inv_mass * n_i.dot(terms[j].u) + u_i.dot(turn[j]);
    }
  }
  const Vec4 lambda = solve_axial_forces(g, c, count);

  SloshAccelerations out;
  out.a_com_body_mps2 = a0;
  out.omega_dot_body_radps2 = w0;
  for (std::size_t i = 0; i < count; ++i) {
    const double l = lambda[static_cast<Eigen::Index>(i)];
    out.a_com_body_mps2 -= (l * inv_mass) * terms[i].u;
    out.omega_dot_body_radps2 -= l * turn[i];
  }
  for (std::size_t i = 0; i < count; ++i) {
    const SloshTankParams& tank = tanks[i];
    // The tank point under the mass, inertial acceleration: a_ref + w' x p + w x (w x p) + 2 w x s'
    // = a_c + w' x r + w x (w x r) + 2 w x s' (a_ref = a_c - w' x c - w x (w x c)).
    const Vec3 frame = out.a_com_body_mps2 + out.omega_dot_body_radps2.cross(terms[i].r) + centripetal_coriolis[i];
    if (!is_pendulum(tank)) {
      out.s_ddot_body_mps2[i] = lateral(tank.axis_body, inv_m[i] * terms[i].f - frame);
    } else {
      out.s_ddot_body_mps2[i] = lateral(terms[i].u, inv_m[i] * terms[i].f - frame) + terms[i].rod_centripetal * terms[i].u;
    }
    out.axial_force_N[i] = lambda[static_cast<Eigen::Index>(i)];  // = m_i n_i . frame (spring-mass)
    out.s_dot_body_mps[i] = terms[i].s_dot;
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
  for (std::size_t i = 0; i < tank_count(tanks, states); ++i) {
    const SloshTankParams& tank = tanks[i];
    if (!is_pendulum(tank)) {
      twice += tank.stiffness_Npm * lateral(tank.axis_body, states[i].s_body_m).squaredNorm();
      continue;
    }
    const Vec3 u = rod_direction(tank, states[i].s_body_m);
    const Vec3 s = tank.pendulum_length_m * (tank.axis_body - u);  // on the sphere
    const double depth = wall_contact(tank, u, s).depth_m;
    twice += tank.wall_stiffness_Npm * depth * depth + 2.0 * tank.mass_kg * tank.capillary_accel_mps2 * tank.axis_body.dot(s);
  }
  return 0.5 * twice;
}

SloshState on_constraint(const SloshTankParams& tank, const SloshState& state) {
  if (!is_pendulum(tank)) return state;
  const Vec3 u = rod_direction(tank, state.s_body_m);
  return {tank.pendulum_length_m * (tank.axis_body - u), lateral(u, state.s_dot_body_mps)};
}

}  // namespace chaser::model
