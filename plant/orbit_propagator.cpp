#include "plant/orbit_propagator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "plant/earth/magnetic_field.hpp"
#include "plant/gravity_gradient.hpp"
#include "plant/lvlh_eci.hpp"

namespace chaser::plant {

namespace {

// The integrated state in one fixed-size vector, so the RK4 combinations are plain vector
// arithmetic: target r, v (0..5); relative dr, dv (6..11); chaser q (x, y, z, w), omega, m
// (12..19); target q, omega (20..26); slosh s, s_dot per tank (27.., Tanks of them: the tanks
// flown rounded up to 0, 2 or 4, a padding tank zero). Sized by the tanks so that a rigid chaser
// does not carry 24 zeros through every RK4 combination.
constexpr int kBase = 27;
template <int Tanks>
using StateVec = Eigen::Matrix<double, kBase + 6 * Tanks, 1>;
constexpr int kRt = 0, kVt = 3, kDr = 6, kDv = 9, kQc = 12, kWc = 16, kM = 19, kQt = 20, kWt = 24;
constexpr int slosh_s(int i) { return kBase + 6 * i; }
constexpr int slosh_s_dot(int i) { return kBase + 6 * i + 3; }

template <int Tanks>
StateVec<Tanks> pack(const OrbitState& o, const RigidState& c) {
  StateVec<Tanks> y;
  y.template head<kBase>() << o.r_t_eci_m, o.v_t_eci_mps, o.dr_eci_m, o.dv_eci_mps, c.q_inertial_from_body.coeffs(),
      c.omega_body_radps, c.mass_kg, o.q_inertial_from_target.coeffs(), o.omega_target_body_radps;
  for (int i = 0; i < Tanks; ++i) {
    y.template segment<3>(slosh_s(i)) = o.slosh[static_cast<std::size_t>(i)].s_body_m;
    y.template segment<3>(slosh_s_dot(i)) = o.slosh[static_cast<std::size_t>(i)].s_dot_body_mps;
  }
  return y;
}

template <int Tanks>
void unpack(const StateVec<Tanks>& y, OrbitState& o, RigidState& c) {
  o.r_t_eci_m = y.template segment<3>(kRt);
  o.v_t_eci_mps = y.template segment<3>(kVt);
  o.dr_eci_m = y.template segment<3>(kDr);
  o.dv_eci_mps = y.template segment<3>(kDv);
  c.q_inertial_from_body = Quat(Eigen::Vector4d(y.template segment<4>(kQc))).normalized();
  c.omega_body_radps = y.template segment<3>(kWc);
  c.mass_kg = y[kM];
  o.q_inertial_from_target = Quat(Eigen::Vector4d(y.template segment<4>(kQt))).normalized();
  o.omega_target_body_radps = y.template segment<3>(kWt);
  for (int i = 0; i < Tanks; ++i) {
    o.slosh[static_cast<std::size_t>(i)].s_body_m = y.template segment<3>(slosh_s(i));
    o.slosh[static_cast<std::size_t>(i)].s_dot_body_mps = y.template segment<3>(slosh_s_dot(i));
  }
}

// The Earth's magnetic field at r_eci_m, ECI.
Vec3 field_eci_T(const Ephemeris& eph, const Vec3& r_eci_m) {
  return eph.ecef_from_eci.transpose() * earth::magnetic_field_ecef_T(eph.ecef_from_eci * r_eci_m);
}

// The torques of the Earth's field on one body at r_eci_m (from the Earth's centre), body axes;
// q_inertial_from_body in the run's inertial axes; field_eci: the magnetic field there, evaluated
// only when the body's magnetic torque is on. Zero, and no rotation formed, when both are off.
template <class Field>
Vec3 environment_torque_body(const BodyTorqueParams& b, double mu_m3ps2, const Mat3& run_from_eci,
                             const Quat& q_inertial_from_body, const Vec3& r_eci_m, const Field& field_eci) {
  Vec3 torque = Vec3::Zero();
  if (!b.gravity_gradient && !b.magnetic) return torque;
  // ECI -> run axes -> body axes. q may be slightly off the unit sphere inside a step; the rotation
  // is then a smooth extension of it, which keeps RK4 fourth order (propagator.cpp does the same).
  const Quat q_body_from_inertial = q_inertial_from_body.conjugate();
  if (b.gravity_gradient) {
    // mu of the central field only: J2's share of the gradient is 1e-3 of it.
    const double gain = gravity_gradient_gain(mu_m3ps2, r_eci_m.squaredNorm());
    torque += gravity_gradient_torque_body(gain, q_body_from_inertial * (run_from_eci * r_eci_m), b.inertia_kgm2);
  }
  if (b.magnetic)
    torque += earth::magnetic_torque_body_Nm(b.residual_dipole_body_Am2, q_body_from_inertial * (run_from_eci * field_eci()));
  return torque;
}

// Inputs of one piece resolved once: the thrust's force in the run's inertial axes comes from the
// attitude at each stage; the LVLH disturbance force is rotated to ECI at the piece start.
struct PieceContext {
  const OrbitDynamicsParams& p;
  const PeriodEnvironment& env;
  const PieceInput& u;
  Mat3 eci_from_run;
  Vec3 force_dist_eci_N;
  Vec3 force_dist_run_N;  // the same in the run's inertial axes (the slosh kernel's body force)
};

OrbitAccelerations accelerations(const OrbitDynamicsParams& p, const PeriodEnvironment& env, const Vec3& r_t,
                                 const Vec3& v_t, const Vec3& dr, const Vec3& dv) {
  if (!env.held) return orbit_accelerations(p.perturbations, env.eph, r_t, v_t, dr, dv);
  const OrbitAccelerations g = gravity_accelerations(p.perturbations.gravity, r_t, dr);
  return {.target_eci_mps2 = g.target_eci_mps2 + env.slow.target_eci_mps2,
          .relative_eci_mps2 = g.relative_eci_mps2 + env.slow.relative_eci_mps2};
}

// The chaser's rotation and its slosh masses, coupled (model/slosh.hpp): the thrust and the disturbance
// force act on the body (the chaser less its slosh masses), the torques, given about the whole
// chaser's CoM at rest, are moved to the body's own.
template <int Tanks>
void slosh_derivative(const PieceContext& c, const StateVec<Tanks>& y, const Quat& q_c, const Vec3& w_c,
                      double mass_kg, const Vec3& torque_c_Nm, StateVec<Tanks>& dy) {
  const model::ChaserSloshParams& slosh = c.p.slosh;
  std::array<model::SloshState, Tanks> states;  // count <= Tanks
  for (int i = 0; i < slosh.count; ++i)
    states[static_cast<std::size_t>(i)] = {y.template segment<3>(slosh_s(i)), y.template segment<3>(slosh_s_dot(i))};
  const model::RigidBodyMassProps body{.mass_kg = mass_kg - slosh.mass_kg,
                                .inertia_com_body_kgm2 = slosh.body_inertia_kgm2,
                                .com_body_m = slosh.body_com_body_m};
  const Vec3 force_body_N = c.u.force_body_N + q_c.conjugate() * c.force_dist_run_N;
  const Vec3 torque_body_Nm = torque_c_Nm + (slosh.com_body_m - slosh.body_com_body_m).cross(force_body_N);
  const auto n = static_cast<std::size_t>(slosh.count);
  const model::SloshAccelerations a =
      model::coupled_accelerations(body, slosh.body_inertia_inv_kgm2, std::span(slosh.tanks.data(), n),
                                   std::span<const model::SloshState>(states.data(), n), w_c, force_body_N,
                                   torque_body_Nm);
  dy.template segment<3>(kWc) = a.omega_dot_body_radps2;
  for (int i = 0; i < slosh.count; ++i) {
    dy.template segment<3>(slosh_s(i)) = a.s_dot_body_mps[static_cast<std::size_t>(i)];  // on the constraint
    dy.template segment<3>(slosh_s_dot(i)) = a.s_ddot_body_mps2[static_cast<std::size_t>(i)];
  }
}

template <int Tanks>
StateVec<Tanks> derivative(const PieceContext& c, const StateVec<Tanks>& y) {
  const OrbitDynamicsParams& p = c.p;
  const PeriodEnvironment& env = c.env;
  const Vec3 r_t = y.template segment<3>(kRt), v_t = y.template segment<3>(kVt);
  const Vec3 dr = y.template segment<3>(kDr), dv = y.template segment<3>(kDv);
  const Quat q_c(Eigen::Vector4d(y.template segment<4>(kQc)));
  const Vec3 w_c = y.template segment<3>(kWc);
  const double m = y[kM];
  const Quat q_t(Eigen::Vector4d(y.template segment<4>(kQt)));
  const Vec3 w_t = y.template segment<3>(kWt);

  const Vec3 thrust_eci_N = c.eci_from_run * (q_c * c.u.force_body_N);
  const OrbitAccelerations a = accelerations(p, env, r_t, v_t, dr, dv);
  StateVec<Tanks> dy;
  dy.template segment<3>(kRt) = v_t;
  dy.template segment<3>(kVt) = a.target_eci_mps2;
  dy.template segment<3>(kDr) = dv;
  dy.template segment<3>(kDv) = a.relative_eci_mps2 + (thrust_eci_N + c.force_dist_eci_N) * (1.0 / m);

  const double mu = p.perturbations.gravity.mu_m3ps2;
  const Vec3 torque_c =
      c.u.torque_body_Nm +
      (env.held ? env.torque_chaser_body_Nm : environment_torque_body(p.chaser, mu, p.run_from_eci, q_c, r_t + dr, [&] {
        return field_eci_T(env.eph, r_t + dr);
      }));
  dy.template segment<4>(kQc) = quat_derivative(q_c, w_c);
  dy[kM] = -c.u.mass_flow_kgps;
  if constexpr (Tanks > 0) dy.template tail<6 * Tanks>().setZero();
  if constexpr (Tanks == 0) {  // a rigid chaser (propagate_orbit_piece sizes the state by the tanks)
    dy.template segment<3>(kWc) = euler_angular_acceleration_body(p.chaser.inertia_kgm2, p.chaser.inertia_inv, w_c, torque_c);
  } else {
    slosh_derivative<Tanks>(c, y, q_c, w_c, m, torque_c, dy);
  }

  const Vec3 torque_t = env.held ? env.torque_target_body_Nm : environment_torque_body(p.target, mu, p.run_from_eci, q_t, r_t, [&] {
    return field_eci_T(env.eph, r_t);
  });
  dy.template segment<4>(kQt) = quat_derivative(q_t, w_t);
  dy.template segment<3>(kWt) = euler_angular_acceleration_body(p.target.inertia_kgm2, p.target.inertia_inv, w_t, torque_t);
  return dy;
}

// steps classical RK4 steps of h [s] each; or, for one short step (third_order), Kutta's
// third-order method: k2 at h/2, k3 at h from y - h k1 + 2 h k2, weights 1/6, 4/6, 1/6.
template <int Tanks>
void integrate_piece(const PieceContext& ctx, OrbitState& orbit, RigidState& chaser, int steps, double h,
                     bool third_order) {
  using State = StateVec<Tanks>;
  State y = pack<Tanks>(orbit, chaser);
  if (third_order) {
    const State k1 = derivative<Tanks>(ctx, y);
    const State k2 = derivative<Tanks>(ctx, y + (0.5 * h) * k1);
    const State k3 = derivative<Tanks>(ctx, y + h * (2.0 * k2 - k1));
    y += (h / 6.0) * (k1 + 4.0 * k2 + k3);
  } else {
    for (int i = 0; i < steps; ++i) {
      const State k1 = derivative<Tanks>(ctx, y);
      const State k2 = derivative<Tanks>(ctx, y + (0.5 * h) * k1);
      const State k3 = derivative<Tanks>(ctx, y + (0.5 * h) * k2);
      const State k4 = derivative<Tanks>(ctx, y + h * k3);
      y += (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    }
  }
  unpack<Tanks>(y, orbit, chaser);
}

LvlhOfTarget target_lvlh(const OrbitDynamicsParams& p, const PeriodEnvironment& env, const OrbitState& o) {
  const Vec3 a_t = env.held ? earth::gravity_acceleration_eci(p.perturbations.gravity, o.r_t_eci_m) +
                                  env.slow.target_eci_mps2
                            : target_acceleration_eci(p.perturbations, env.eph, o.r_t_eci_m, o.v_t_eci_mps);
  return lvlh_of_target(o.r_t_eci_m, o.v_t_eci_mps, a_t);
}

}  // namespace

SlowEnvironment slow_environment(const OrbitDynamicsParams& p, const Ephemeris& eph_mid, const OrbitState& orbit,
                                 double lead_s) {
  SlowEnvironment out;
  out.eph = eph_mid;
  // Central gravity and J2 over the lead (up to half a window, 0.5 s): without the a t^2 / 2 term
  // the target's position would be g t^2 / 2 = 1 m off; with it, ~ n^3 r t^3 / 6 = 4e-7 m. The
  // relative state's own drift over it is the relative velocity's (its change, ~1e-5 m/s, is left
  // out: drag sees 7.5 km/s).
  const Vec3 g_t = earth::gravity_acceleration_eci(p.perturbations.gravity, orbit.r_t_eci_m);
  const Vec3 r_t = orbit.r_t_eci_m + lead_s * orbit.v_t_eci_mps + (0.5 * lead_s * lead_s) * g_t;
  const Vec3 v_t = orbit.v_t_eci_mps + lead_s * g_t;
  const Vec3 dr = orbit.dr_eci_m + lead_s * orbit.dv_eci_mps;
  out.slow = slow_accelerations(p.perturbations, eph_mid, r_t, v_t, dr, orbit.dv_eci_mps);
  if (p.target.magnetic) out.field_target_eci_T = field_eci_T(eph_mid, r_t);
  if (p.chaser.magnetic) out.field_chaser_eci_T = field_eci_T(eph_mid, r_t + dr);
  return out;
}

std::int64_t environment_periods(const OrbitDynamicsParams& p, double period_s) {
  return std::max<std::int64_t>(1, std::llround(p.environment_step_s / period_s));
}

PeriodEnvironment period_environment(const OrbitDynamicsParams& p, const SlowEnvironment& slow,
                                     const OrbitState& orbit, const RigidState& chaser, double period_s) {
  PeriodEnvironment env;
  env.eph = slow.eph;
  env.held = true;
  env.slow = slow.slow;
  // The midpoint rule for the torques: positions half a period on (the gradient's direction turns
  // at n, 5e-5 rad in half a period: its drift alone is enough), and each body's attitude there to
  // first order (its error, (w dt)^2 / 8, is the held torque's own order).
  const double half_s = 0.5 * period_s;
  const Vec3 r_t = orbit.r_t_eci_m + half_s * orbit.v_t_eci_mps;
  const Vec3 r_c = r_t + orbit.dr_eci_m + half_s * orbit.dv_eci_mps;
  const auto attitude_at_midpoint = [half_s](const Quat& q, const Vec3& omega_body_radps) {
    Quat mid;
    mid.coeffs() = q.coeffs() + half_s * quat_derivative(q, omega_body_radps);
    return mid.normalized();
  };
  const double mu = p.perturbations.gravity.mu_m3ps2;
  env.torque_target_body_Nm =
      environment_torque_body(p.target, mu, p.run_from_eci,
                              attitude_at_midpoint(orbit.q_inertial_from_target, orbit.omega_target_body_radps), r_t,
                              [&] { return slow.field_target_eci_T; });
  env.torque_chaser_body_Nm =
      environment_torque_body(p.chaser, mu, p.run_from_eci,
                              attitude_at_midpoint(chaser.q_inertial_from_body, chaser.omega_body_radps), r_c,
                              [&] { return slow.field_chaser_eci_T; });
  return env;
}

PeriodEnvironment period_environment(const OrbitDynamicsParams& p, const Ephemeris& eph_mid, const OrbitState& orbit,
                                     const RigidState& chaser, double period_s) {
  if (!p.hold_slow_environment) {
    PeriodEnvironment env;
    env.eph = eph_mid;
    return env;
  }
  return period_environment(p, slow_environment(p, eph_mid, orbit, 0.5 * period_s), orbit, chaser, period_s);
}

void propagate_orbit_piece(const OrbitDynamicsParams& p, const PeriodEnvironment& env, OrbitState& orbit,
                           RigidState& chaser, double dt_s, const PieceInput& u) {
  if (!(dt_s > 0.0)) return;
  const int steps = substep_count(dt_s, p.max_substep_s);
  const double h = dt_s / steps;
  const Mat3 eci_from_run = p.run_from_eci.transpose();
  Vec3 force_dist_eci_N = Vec3::Zero();
  if (!u.force_lvlh_N.isZero(0.0)) {
    force_dist_eci_N = target_lvlh(p, env, orbit).lvlh_from_eci.transpose() * u.force_lvlh_N;
  }
  const PieceContext ctx{p, env, u, eci_from_run, force_dist_eci_N, p.run_from_eci * force_dist_eci_N};
  // The state's size: the tanks flown rounded up to 0, 2 or 4 (model::kMaxSloshTanks).
  static_assert(model::kMaxSloshTanks == 4);
  const bool third_order = steps == 1 && dt_s <= p.third_order_max_piece_s;
  if (p.slosh.count == 0) {
    integrate_piece<0>(ctx, orbit, chaser, steps, h, third_order);
  } else if (p.slosh.count <= 2) {
    integrate_piece<2>(ctx, orbit, chaser, steps, h, third_order);
  } else {
    integrate_piece<4>(ctx, orbit, chaser, steps, h, third_order);
  }
  for (int i = 0; i < p.slosh.count; ++i) {  // the pendulums back onto their spheres (RK4 drifts off)
    const auto k = static_cast<std::size_t>(i);
    orbit.slosh[k] = model::on_constraint(p.slosh.tanks[k], orbit.slosh[k]);
  }
}

void update_lvlh_view(const OrbitDynamicsParams& p, const PeriodEnvironment& env, const OrbitState& orbit,
                      RigidState& chaser) {
  const RelativeLvlh rel = relative_lvlh_from_eci(target_lvlh(p, env, orbit), {orbit.dr_eci_m, orbit.dv_eci_mps});
  chaser.r_lvlh_m = rel.r_lvlh_m;
  chaser.v_lvlh_mps = rel.v_lvlh_mps;
}

Quat q_inertial_from_lvlh(const OrbitDynamicsParams& p, const OrbitState& orbit) {
  const Mat3 run_from_lvlh = p.run_from_eci * lvlh_axes_from_eci(orbit.r_t_eci_m, orbit.v_t_eci_mps).transpose();
  return Quat(run_from_lvlh).normalized();
}

}  // namespace chaser::plant
