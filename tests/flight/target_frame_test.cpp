// A point moving in the tumbling target's frame, seen in LVLH (flight/target_frame.hpp), against
// finite differences of r(t) = R_lvlh_from_target(t) p(t) along an independently integrated tumble
// (torque-free Euler, RK4 at 1 ms, ENVISAT's inertia) and LVLH turning at the mean motion about z.
#include "flight/target_frame.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>

#include "core/rotation.hpp"
#include "tests/support/torque_free_body.hpp"

namespace chaser::flight {
namespace {

using testing::TorqueFreeBody;

constexpr double kN = 1.06e-3;  // [rad/s] ENVISAT's mean motion (765 km)

Quat lvlh_at(double t) { return Quat(Eigen::AngleAxisd(kN * t, Vec3::UnitZ())); }

// p(t): the chaser's reference moving from 10 m to 7.4 m along the capture axis (a smooth profile).
Vec3 p_of(double t) { return Vec3(7.4 + 2.6 * std::cos(0.02 * t), 0.0, 0.6); }
Vec3 p_dot_of(double t) { return Vec3(-2.6 * 0.02 * std::sin(0.02 * t), 0.0, 0.0); }
Vec3 p_ddot_of(double t) { return Vec3(-2.6 * 0.0004 * std::cos(0.02 * t), 0.0, 0.0); }

// Central differences with h = 2 ms of positions at 1 ms RK4: truncation h^2 |r'''| / 6 with
// |r'''| ~ w^3 |r| = 6e-4 (4e-10 m/s for the velocity), rounding ~ 1e-15 |r| / h^2 (2e-9 m/s^2 for
// the acceleration): bounds 1e-8 m/s and 1e-7 m/s^2 (an error in a Coriolis term would be ~1e-3).
TEST(TargetFrame, PointVelocityAndAccelerationMatchFiniteDifferences) {
  TorqueFreeBody tumble{.inertia_kgm2 = testing::envisat_inertia_kgm2(),
                        .q_inertial_from_body = quat_from_rotation_vector(Vec3(0.3, -0.2, 0.5)),
                        .omega_body_radps = Vec3(0.2, 1.0, 0.3).normalized() * (2.5 * M_PI / 180.0)};
  tumble.advance(200.0);  // 200 s into the tumble
  const double t0 = 200.0, h = 0.002;
  std::array<Vec3, 3> r;
  // Positions at t0, t0 + h, t0 + 2h (stepping forward), the derivatives compared at t0 + h.
  TorqueFreeBody at = tumble;
  TorqueFreeBody s = tumble;
  for (int i = 0; i < 3; ++i) {
    const double t = t0 + i * h;
    r[static_cast<std::size_t>(i)] = (lvlh_at(t).conjugate() * s.q_inertial_from_body) * p_of(t);
    if (i == 1) at = s;
    for (int j = 0; j < 2; ++j) s.step(1e-3);
  }
  const double t1 = t0 + h;
  const Vec3 omega_l(0.0, 0.0, kN);
  const TargetFrameMotion frame =
      target_frame_motion(lvlh_at(t1), omega_l, Vec3::Zero(), at.q_inertial_from_body,
                                                           at.omega_body_radps, at.omega_dot());
  const LvlhPoint pt = target_point_in_lvlh(frame, p_of(t1), p_dot_of(t1), p_ddot_of(t1));
  const Vec3 v_fd = (r[2] - r[0]) / (2 * h);
  const Vec3 a_fd = (r[2] - 2 * r[1] + r[0]) / (h * h);
  std::printf("|dr| %.2e m, |dv| %.2e m/s, |da| %.2e m/s^2\n", (pt.r_m - r[1]).norm(), (pt.v_mps - v_fd).norm(),
              (pt.a_mps2 - a_fd).norm());
  EXPECT_LE((pt.r_m - r[1]).norm(), 1e-12);
  EXPECT_LE((pt.v_mps - v_fd).norm(), 1e-8);
  EXPECT_LE((pt.a_mps2 - a_fd).norm(), 1e-7);
  // The point is not at rest in LVLH: it turns at ~2.5 deg/s over ~7.4 m (0.3 m/s).
  EXPECT_GT(pt.v_mps.norm(), 0.2);
}

}  // namespace
}  // namespace chaser::flight
