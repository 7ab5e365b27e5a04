#include "plant/propagator.hpp"

#include <algorithm>
#include <cmath>

#include "plant/gravity_gradient.hpp"
#include "plant/relative_orbit.hpp"

namespace chaser::plant {

DynamicsParams make_dynamics_params(const model::Scenario& s) {
  return DynamicsParams{
      .orbit = model::TargetOrbit(s.orbit),
      .inertia_kgm2 = s.chaser.inertia_kgm2,
      .inertia_inv = s.chaser.inertia_kgm2.inverse(),
      .gravity_gradient = s.environment.gravity_gradient,
      .max_substep_s = kDefaultMaxSubstepS,
  };
}

int substep_count(double dt_s, double max_substep_s) {
  constexpr double kSlack = 1e-9;  // a ns-rounded piece a hair over the bound stays one substep
  const double steps = std::ceil(dt_s / max_substep_s * (1.0 - kSlack));
  return std::max(1, static_cast<int>(steps));
}

namespace {

// The integrated state packed in one fixed-size vector so the RK4 combinations are plain vector
// arithmetic: r (0..2), v (3..5), q coeffs x, y, z, w (6..9), omega (10..12), m (13).
using RigidStateVec = Eigen::Matrix<double, 14, 1>;
constexpr int kR = 0, kV = 3, kQ = 6, kW = 10, kMass = 13;

RigidStateVec pack(const RigidState& x) {
  RigidStateVec y;
  y << x.r_lvlh_m, x.v_lvlh_mps, x.q_inertial_from_body.coeffs(), x.omega_body_radps, x.mass_kg;
  return y;
}

void unpack(const RigidStateVec& y, RigidState& x) {
  x.r_lvlh_m = y.segment<3>(kR);
  x.v_lvlh_mps = y.segment<3>(kV);
  x.q_inertial_from_body = Quat(Eigen::Vector4d(y.segment<4>(kQ))).normalized();
  x.omega_body_radps = y.segment<3>(kW);
  x.mass_kg = y[kMass];
}

// Orientation of LVLH in inertial at a stage time: a turn about z by the argument of latitude u
// travelled since t = 0, kept as (cos u, sin u).
struct LvlhAngle {
  double c, s;
  LvlhAngle turned(const LvlhAngle& d) const { return {c * d.c - s * d.s, s * d.c + c * d.s}; }
};

// The turn over half a substep, n h / 2 ~ 4e-5 rad at the default bound: the Taylor series to the
// x^4 / x^5 terms is exact to round-off below 1e-3 rad (next terms x^6 / 720 < 2e-21) and saves a
// sincos per piece; larger angles take the library call.
LvlhAngle small_turn(double angle) {
  constexpr double kSeriesLimit = 1e-3;  // [rad]
  if (std::abs(angle) >= kSeriesLimit) return {std::cos(angle), std::sin(angle)};
  const double a2 = angle * angle;
  return {1.0 - 0.5 * a2 * (1.0 - a2 / 12.0), angle * (1.0 - a2 / 6.0 * (1.0 - a2 / 20.0))};
}

Vec3 lvlh_from_inertial(const LvlhAngle& a, const Vec3& v) {
  return Vec3(a.c * v.x() + a.s * v.y(), -a.s * v.x() + a.c * v.y(), v.z());
}
Vec3 inertial_from_lvlh(const LvlhAngle& a, const Vec3& v) {
  return Vec3(a.c * v.x() - a.s * v.y(), a.s * v.x() + a.c * v.y(), v.z());
}

// Right-hand side of the coupled equations of propagator.hpp at one RK stage. q may be slightly
// off the unit sphere inside a step; the rotations below are then smooth extensions, which keeps
// RK4 fourth order (the exact flow preserves |q|).
RigidStateVec derivative(const DynamicsParams& p, const PieceInput& u, const RigidStateVec& y, const LvlhAngle& lvlh) {
  const Vec3 r = y.segment<3>(kR);
  const Vec3 v = y.segment<3>(kV);
  const Quat q(Eigen::Vector4d(y.segment<4>(kQ)));
  const Vec3 omega = y.segment<3>(kW);
  const double m = y[kMass];

  const Vec3 thrust_lvlh_N = lvlh_from_inertial(lvlh, q * u.force_body_N);
  const Vec3 accel = relative_orbit_acceleration_lvlh(p.orbit.radius_m(), p.orbit.mean_motion_radps(), r, v) +
                     (thrust_lvlh_N + u.force_lvlh_N) * (1.0 / m);

  Vec3 torque = u.torque_body_Nm;
  if (p.gravity_gradient) {
    const Vec3 r_planet_lvlh_m(p.orbit.radius_m() + r.x(), r.y(), r.z());
    const Vec3 r_planet_body_m = q.conjugate() * inertial_from_lvlh(lvlh, r_planet_lvlh_m);
    const double gain = gravity_gradient_gain(p.orbit.mu_m3ps2(), r_planet_lvlh_m.squaredNorm());
    torque += gravity_gradient_torque_body(gain, r_planet_body_m, p.inertia_kgm2);
  }

  RigidStateVec dy;
  dy.segment<3>(kR) = v;
  dy.segment<3>(kV) = accel;
  dy.segment<4>(kQ) = quat_derivative(q, omega);
  dy.segment<3>(kW) = euler_angular_acceleration_body(p.inertia_kgm2, p.inertia_inv, omega, torque);
  dy[kMass] = -u.mass_flow_kgps;
  return dy;
}

}  // namespace

void propagate_piece(const DynamicsParams& p, RigidState& x, double t0_s, double dt_s, const PieceInput& u) {
  if (!(dt_s > 0.0)) return;
  const int steps = substep_count(dt_s, p.max_substep_s);
  const double h = dt_s / steps;
  // LVLH angle at the substep start, and its turn over half a substep (the circle's u' = n): stage
  // times t, t + h/2, t + h.
  const double u0 = p.orbit.argument_of_latitude_rad(t0_s);
  LvlhAngle start{std::cos(u0), std::sin(u0)};
  const LvlhAngle half_turn = small_turn(0.5 * p.orbit.mean_motion_radps() * h);

  RigidStateVec y = pack(x);
  for (int i = 0; i < steps; ++i) {  // classical RK4
    const LvlhAngle mid = start.turned(half_turn);
    const LvlhAngle end = mid.turned(half_turn);
    const RigidStateVec k1 = derivative(p, u, y, start);
    const RigidStateVec k2 = derivative(p, u, y + (0.5 * h) * k1, mid);
    const RigidStateVec k3 = derivative(p, u, y + (0.5 * h) * k2, mid);
    const RigidStateVec k4 = derivative(p, u, y + h * k3, end);
    y += (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    start = end;
  }
  unpack(y, x);
}

}  // namespace chaser::plant
