// The exponential atmosphere against its table, and the drag decay of a circular orbit against
// the closed form da/dt = -rho sqrt(mu a) / B.
#include "plant/earth/atmosphere.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "plant/earth/gravity.hpp"
#include "plant/earth/inertial_orbit.hpp"

namespace chaser::plant::earth {
namespace {

// Vallado 2013, Table 8-4, at band bases; the density falls with altitude everywhere, and is
// continuous across bands to the table's own rounding (within 10 %: the bands were fitted apart).
TEST(Atmosphere, DensityFollowsVallado84) {
  EXPECT_DOUBLE_EQ(exponential_density_kgpm3(0.0), 1.225);
  EXPECT_DOUBLE_EQ(exponential_density_kgpm3(400e3), 3.725e-12);
  EXPECT_DOUBLE_EQ(exponential_density_kgpm3(1000e3), 3.019e-15);
  EXPECT_NEAR(exponential_density_kgpm3(450e3 - 1e-3) / 1.585e-12, 1.0, 0.1);
  for (double h = 0; h < 1200e3; h += 1e3)
    EXPECT_LT(exponential_density_kgpm3(h + 1e3), exponential_density_kgpm3(h)) << h;
}

// Drag opposes the velocity relative to the air; with a turning atmosphere an eastward equatorial
// orbit meets slower air (v - omega_E r): less drag than in still air, by (1 - omega_E r / v)^2.
TEST(Atmosphere, DragOpposesTheAirSpeed) {
  const double mu = GravityParams{}.mu_m3ps2, a = 6378137.0 + 400e3;
  const InertialState s = circular_orbit_state(mu, a, 0.0, 0.0, 0.3);
  const DragParams still{.ballistic_coefficient_kgpm2 = 50.0, .corotating_atmosphere = false};
  DragParams turning = still;
  turning.corotating_atmosphere = true;
  const Vec3 d_still = drag_acceleration_eci(still, s.r_eci_m, s.v_eci_mps);
  const Vec3 d_turning = drag_acceleration_eci(turning, s.r_eci_m, s.v_eci_mps);
  EXPECT_NEAR(d_still.normalized().dot(s.v_eci_mps.normalized()), -1.0, 1e-15);
  const double v = s.v_eci_mps.norm();
  EXPECT_NEAR(d_turning.norm() / d_still.norm(), std::pow(1 - kEarthRotationRadps * a / v, 2), 1e-12);
  const double rho = exponential_density_kgpm3(s.r_eci_m.norm() - 6378137.0);
  EXPECT_NEAR(rho / 3.725e-12, 1.0, 1e-3);  // 400 km, the 350 km band's end or the 400 km band's base
  EXPECT_NEAR(d_still.norm() / (rho * v * v / (2 * 50.0)), 1.0, 1e-14);
}

// A day at 400 km in still air (B = 100 kg/m^2, central gravity only): the semi-major axis (from
// the energy) falls as the closed form integrated along the way, to 2 %. The orbit stays circular to
// ~1e-5, so the density met around it is the circular orbit's.
TEST(Atmosphere, CircularOrbitDecaysAsTheClosedForm) {
  const GravityParams central{.j2 = 0.0};
  const DragParams drag{.ballistic_coefficient_kgpm2 = 100.0, .corotating_atmosphere = false};
  const double a0 = central.radius_m + 400e3;
  InertialState s = circular_orbit_state(central.mu_m3ps2, a0, 51.6 * kDegToRad, 0.0, 0.0);
  const auto accel = [&](double, const Vec3& r, const Vec3& v) {
    return Vec3(gravity_acceleration_eci(central, r) + drag_acceleration_eci(drag, r, v));
  };
  const double h = 10.0, day = 86400.0;
  double a_closed = a0;  // the closed form's rate integrated with the same steps
  for (double t = 0; t < day; t += h) {
    s = rk4_step(s, t, h, accel);
    a_closed += h * circular_decay_rate_mps(central.mu_m3ps2, a_closed,
                                            exponential_density_kgpm3(a_closed - drag.equatorial_radius_m), 100.0);
  }
  const double decay = a0 - semi_major_axis_m(central.mu_m3ps2, s);
  const double decay_closed = a0 - a_closed;
  EXPECT_GT(decay_closed, 100.0);  // ~170 m a day: a clear signal
  EXPECT_NEAR(decay / decay_closed, 1.0, 0.02);
}

}  // namespace
}  // namespace chaser::plant::earth
