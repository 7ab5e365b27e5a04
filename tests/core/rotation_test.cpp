#include "core/rotation.hpp"

#include <gtest/gtest.h>

#include "core/constants.hpp"

namespace chaser {
namespace {

// The exponential map and its inverse are exact inverses for angles in [0, pi).
TEST(Rotation, RotationVectorRoundTrip) {
  for (const Vec3& v : {Vec3(0.3, -0.2, 0.9), Vec3(1e-10, 0.0, -2e-10), Vec3(0.0, 3.0, 0.0)}) {
    const Quat q = quat_from_rotation_vector(v);
    EXPECT_NEAR(q.norm(), 1.0, 1e-15);
    EXPECT_LT((rotation_vector_from_quat(q) - v).norm(), 1e-14 * (1.0 + v.norm()));
  }
}

// A rotation vector about z by angle a must agree with Eigen's AngleAxis.
TEST(Rotation, MatchesAngleAxis) {
  const Vec3 axis = Vec3(1.0, 2.0, -0.5).normalized();
  const double angle = 1.234;
  const Quat expected(Eigen::AngleAxisd(angle, axis));
  EXPECT_TRUE(quat_from_rotation_vector(angle * axis).isApprox(expected, 1e-15));
}

// The error of an attitude against itself is zero; a small body-frame perturbation is recovered.
TEST(Rotation, AttitudeErrorIsBodyFramePerturbation) {
  const Quat q_des = quat_from_rotation_vector(Vec3(0.4, -0.1, 0.2));
  const Vec3 delta(1e-3, -2e-3, 5e-4);
  const Quat q = q_des * quat_from_rotation_vector(delta);
  EXPECT_LT(attitude_error_body(q_des, q_des).norm(), 1e-15);
  EXPECT_LT((attitude_error_body(q_des, q) - delta).norm(), 1e-15);
}

// After a quarter orbit the LVLH x axis (radial) points along the initial y axis (along-track).
TEST(Rotation, LvlhTurnsAboutOrbitNormal) {
  const double n = 1e-3;
  const Quat q = q_inertial_from_lvlh(n, 0.5 * kPi / n);
  EXPECT_LT((q * Vec3::UnitX() - Vec3::UnitY()).norm(), 1e-12);
}

// The two Hill conventions: MSR radial-out is Zhou's -z (z points to the planet), and the maps
// are mutual inverses.
TEST(Rotation, HillFrameConversions) {
  EXPECT_EQ(zhou_from_msr(Vec3::UnitX()), Vec3(0, 0, -1));
  EXPECT_EQ(zhou_from_msr(Vec3::UnitY()), Vec3(1, 0, 0));
  EXPECT_EQ(zhou_from_msr(Vec3::UnitZ()), Vec3(0, -1, 0));
  const Vec3 v(0.3, -1.2, 2.5);
  EXPECT_EQ(msr_from_zhou(zhou_from_msr(v)), v);
}

}  // namespace
}  // namespace chaser
