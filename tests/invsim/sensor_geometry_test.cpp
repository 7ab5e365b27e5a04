#include "invsim/sensor_geometry.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "core/constants.hpp"

namespace chaser::invsim {
namespace {

// On the docking axis with zero attitude the target is dead ahead: azimuth and elevation 0, and
// the range is the centre-of-mass distance less the sensor's forward offset (eq. 14, x = rho - x_s).
TEST(SensorGeometry, OnAxisTargetIsDeadAhead) {
  const LineOfSight los = line_of_sight(Vec3(50.0, 0.0, 0.0), Mat3::Identity(), Vec3(-3.0, 0.0, 0.0));
  EXPECT_DOUBLE_EQ(los.range_m, 47.0);
  EXPECT_DOUBLE_EQ(los.azimuth_rad, 0.0);
  EXPECT_DOUBLE_EQ(los.elevation_rad, 0.0);
}

// Eq. 15 to first order: azimuth = psi - atan((y + y_s)/rho), elevation = theta + atan((z + z_s)/rho)
// (our right-handed measurement frame; see the header). Eq. 15 neglects the attitude's turn of the
// sensor lever (angle * |p_s| / rho) and second-order terms; with a lateral lever of 0.2 m, 0.5 deg
// and 1 m in 42 m these are ~5e-5 rad: 1e-4 is the tolerance.
TEST(SensorGeometry, SmallAnglesFollowEq15) {
  const Vec3 sensor(0.0, 0.2, -0.1);
  const Vec3 r(42.0, 0.8, -0.6);
  const double psi = 0.5 * kDegToRad, theta = -0.4 * kDegToRad;
  const LineOfSight los = line_of_sight(r, matrix_from_euler321(Vec3(0.0, theta, psi)), sensor);
  const double rho = los.range_m;
  EXPECT_NEAR(los.azimuth_rad, psi - std::atan((r.y() + sensor.y()) / rho), 1e-4);
  EXPECT_NEAR(los.elevation_rad, theta + std::atan((r.z() + sensor.z()) / rho), 1e-4);
  EXPECT_NEAR(rho, r.x() + sensor.x(), 0.05);
}

// The field-of-view check is inclusive of its limits and symmetric.
TEST(SensorGeometry, FieldOfViewLimits) {
  const double lim = 10.0 * kDegToRad;
  EXPECT_TRUE(target_in_view({10.0, lim, -lim}, lim, lim));
  EXPECT_FALSE(target_in_view({10.0, -1.0001 * lim, 0.0}, lim, lim));
  EXPECT_FALSE(target_in_view({10.0, 0.0, 1.0001 * lim}, lim, lim));
}

// A lateral offset of rho tan(10 deg) puts the target on the azimuth limit, so eq. 16's largest
// offset at zero attitude error is rho * 10 deg to first order.
TEST(SensorGeometry, LateralOffsetAtTheViewLimit) {
  const double rho = 60.0, lim = 10.0 * kDegToRad;
  const LineOfSight los = line_of_sight(Vec3(rho, -rho * std::tan(lim), 0.0), Mat3::Identity(), Vec3::Zero());
  EXPECT_NEAR(std::abs(los.azimuth_rad), lim, 1e-12);
  EXPECT_NEAR(max_lateral_offset_m(rho, lim, 1.0 * kDegToRad, 0.5), rho * 9.0 * kDegToRad - 0.5, 1e-12);
}

// Euler 3-2-1 angles round-trip through the rotation matrix (away from pitch +-90 deg).
TEST(SensorGeometry, Euler321RoundTrip) {
  const Vec3 e(0.3, -0.2, 1.1);
  EXPECT_LT((euler321_from_matrix(matrix_from_euler321(e)) - e).norm(), 1e-14);
}

}  // namespace
}  // namespace chaser::invsim
