// The target's keep-out volume (model/keep_out.hpp) against closed forms: a point beyond a face
// (its distance along the normal), beyond an edge and a corner (Euclidean to the edge or corner),
// inside (minus the depth to the nearest face), and a union of two boxes. Exact to rounding (1e-15 m).
#include "model/keep_out.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace chaser::model {
namespace {

constexpr double kTol = 1e-12;  // [m]

const KeepOutBox kEnvisatBus{Vec3(-1.1, 0.0, 0.0), Vec3(5.0, 2.0, 2.0)};  // scenarios/comrade_envisat.yaml

TEST(KeepOut, DistancesToOneBoxMatchClosedForms) {
  const std::vector<KeepOutBox> bus{kEnvisatBus};
  // The capture point, 3.5 m beyond the +x face (x = 3.9 m) and 0.6 m off axis in z, within the face.
  EXPECT_NEAR(keep_out_distance_m(bus, Vec3(7.4, 0.0, 0.6)), 3.5, kTol);
  EXPECT_NEAR(keep_out_distance_m(bus, Vec3(-1.1, -32.0, 0.0)), 30.0, kTol);  // beyond the -y face
  EXPECT_NEAR(keep_out_distance_m(bus, Vec3(6.9, 5.0, 0.0)), std::hypot(3.0, 3.0), kTol);  // edge
  EXPECT_NEAR(keep_out_distance_m(bus, Vec3(-8.1, -4.0, 6.0)), std::sqrt(4.0 + 4.0 + 16.0), kTol);  // corner
  EXPECT_NEAR(keep_out_distance_m(bus, Vec3(3.9, 1.0, 0.0)), 0.0, kTol);   // on the face
  EXPECT_NEAR(keep_out_distance_m(bus, Vec3(-1.1, 0.0, 0.0)), -2.0, kTol);  // the centre: 2 m to y and z faces
  EXPECT_NEAR(keep_out_distance_m(bus, Vec3(3.4, 0.0, 0.0)), -0.5, kTol);   // 0.5 m inside the +x face
}

TEST(KeepOut, UnionTakesTheNearestBox) {
  const std::vector<KeepOutBox> two{kEnvisatBus, KeepOutBox{Vec3(-6.6, 9.0, 0.0), Vec3(0.5, 7.0, 2.5)}};
  // Beyond the second box's +y end (y = 16) only that box is near.
  EXPECT_NEAR(keep_out_distance_m(two, Vec3(-6.6, 20.0, 0.0)), 4.0, kTol);
  // Near the bus's +x face the bus decides, as alone.
  EXPECT_NEAR(keep_out_distance_m(two, Vec3(7.4, 0.0, 0.6)), 3.5, kTol);
  EXPECT_EQ(keep_out_distance_m({}, Vec3::Zero()), std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace chaser::model
