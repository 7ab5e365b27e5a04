#include "flight/guidance.hpp"

#include <algorithm>
#include <cmath>

#include "core/constants.hpp"
#include "core/rotation.hpp"

namespace chaser::flight {
namespace {

// Progress sigma in [0, 1] and its derivatives for the blended-cruise profile of guidance.hpp.
struct Progress {
  double sigma = 0.0, rate = 0.0, accel = 0.0, jerk = 0.0;  // [-], [1/s], [1/s^2], [1/s^3]
};

// The start blend, s in [0, tb]: speed w(s) / span with w = (1 - cos(pi s / tb)) / 2.
Progress start_blend(double s, double tb, double span) {
  const double omega = kPi / tb;  // [rad/s] blend frequency
  const double phase = omega * s;
  return Progress{0.5 * (s - std::sin(phase) / omega) / span, 0.5 * (1.0 - std::cos(phase)) / span,
                  0.5 * omega * std::sin(phase) / span, 0.5 * omega * omega * std::cos(phase) / span};
}

Progress progress(double t, double duration, double blend) {
  if (duration <= 0.0 || t >= duration) return Progress{1.0, 0.0, 0.0, 0.0};
  if (t <= 0.0) return Progress{};
  const double tb = std::min(blend, 0.5 * duration);
  const double span = duration - tb;  // sigma' = 1 / span in the cruise
  if (t < tb) return start_blend(t, tb, span);
  if (t > duration - tb) {  // mirror image of the start blend, counted back from the end
    const Progress back = start_blend(duration - t, tb, span);
    return Progress{1.0 - back.sigma, back.rate, -back.accel, back.jerk};
  }
  return Progress{(t - 0.5 * tb) / span, 1.0 / span, 0.0, 0.0};
}

}  // namespace

ApproachProfile approach_profile(const model::GuidanceParams& params, double t_s) {
  const Progress p = progress(t_s, params.approach_duration_s, std::max(params.blend_time_s, 0.0));
  const double travel = params.capture_distance_m - params.start_distance_m;
  return ApproachProfile{params.start_distance_m + travel * p.sigma, travel * p.rate, travel * p.accel,
                         travel * p.jerk};
}

Quat target_pointing_q_lvlh_from_body(const Vec3& approach_axis_lvlh) {
  const Vec3 x_body = -approach_axis_lvlh.normalized();
  constexpr double kNearNormalCos = 0.9;  // ~25 deg: switch the roll reference before it degenerates
  const Vec3 roll_ref = std::abs(x_body.z()) > kNearNormalCos ? Vec3::UnitX() : Vec3::UnitZ();
  const Vec3 z_body = (roll_ref - roll_ref.dot(x_body) * x_body).normalized();
  Mat3 lvlh_from_body;
  lvlh_from_body << x_body, z_body.cross(x_body), z_body;
  return Quat(lvlh_from_body).normalized();
}

GuidanceRef guidance_reference(const model::GuidanceParams& params, double t_s, const model::LvlhFrame& lvlh) {
  const Vec3 axis = params.approach_axis_lvlh.normalized();
  const ApproachProfile p = approach_profile(params, t_s);
  const Quat q_lvlh_from_body = target_pointing_q_lvlh_from_body(axis);
  GuidanceRef ref;
  ref.r_lvlh_m = p.distance_m * axis;
  ref.v_lvlh_mps = p.rate_mps * axis;
  ref.a_lvlh_mps2 = p.accel_mps2 * axis;
  ref.j_lvlh_mps3 = p.jerk_mps3 * axis;
  ref.q_inertial_from_body = lvlh.q_inertial_from_lvlh * q_lvlh_from_body;
  ref.omega_body_radps = q_lvlh_from_body.conjugate() * lvlh.omega_lvlh_radps;
  return ref;
}

}  // namespace chaser::flight
