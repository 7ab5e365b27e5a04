#include "core/rotation.hpp"

#include <gtest/gtest.h>

#include <cmath>

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

// The small-angle series equals the atan2 formula (2 atan2(|v|, w) / |v|) v within 2 ulp of the
// angle, from 1e-12 rad up to and across the switch at x = |v| / w = 1/128 (0.895 deg), for
// quaternions of either sign; above it the atan2 branch is used unchanged.
TEST(Rotation, SmallAngleSeriesEqualsAtan2) {
  const Vec3 axis = Vec3(0.3, -0.8, 0.52).normalized();
  const double switch_angle = 2.0 * std::atan(1.0 / 128.0);
  for (double angle = 1e-12; angle < 0.1; angle *= 1.05) {
    for (const double a : {angle, switch_angle * (1 - 1e-12), switch_angle * (1 + 1e-12)}) {
      Quat q(Eigen::AngleAxisd(a, axis));
      for (const double sign : {1.0, -1.0}) {
        const Quat qs(sign * q.coeffs());
        const Quat qp = qs.w() < 0.0 ? Quat(-qs.coeffs()) : qs;
        const double n = qp.vec().norm();
        const Vec3 reference = (2.0 * std::atan2(n, qp.w()) / n) * qp.vec();
        EXPECT_LE((rotation_vector_from_quat(qs) - reference).norm(), 4.5e-16 * reference.norm()) << a;
      }
    }
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

// The small-angle error has the rotation vector's direction and length 2 sin(angle / 2), for either
// sign of the quaternion, from 1e-9 rad to 3 rad: 2 sin(a/2) times the axis within 1e-15 (the two
// quaternion products round the unit quaternions' components, a few 1e-16 each, whatever the angle).
// Its departure from the rotation vector itself stays below a^3 / 24, 3e-7 rad at 1 deg.
TEST(Rotation, SmallAngleErrorIsTwiceTheVectorPartOfTheShorterRotation) {
  const Quat q_des = quat_from_rotation_vector(Vec3(0.4, -0.1, 0.2));
  const Vec3 axis = Vec3(-0.6, 0.3, 0.74).normalized();
  for (double a = 1e-9; a < 3.0; a *= 1.3) {
    const Quat q = q_des * quat_from_rotation_vector(a * axis);
    for (const double sign : {1.0, -1.0}) {
      const Vec3 e = small_angle_error_body(q_des, Quat(sign * q.coeffs()));
      EXPECT_LT((e - (2.0 * std::sin(0.5 * a)) * axis).norm(), 1e-15) << a;
      EXPECT_LE((e - attitude_error_body(q_des, q)).norm(), a * a * a / 24.0 + 1e-15) << a;
    }
  }
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

// The least rotation from u to v: at fraction 1 it takes u onto v (1e-15), at 0.5 it turns u by half
// the angle in the plane of u and v, and antiparallel vectors turn by pi about a perpendicular of u.
TEST(Rotation, RotationTowardsTakesUOntoVByTheLeastRotation) {
  const Vec3 u = Vec3(1.0, 2.0, -0.5).normalized(), v = Vec3(-0.3, 0.4, 2.0).normalized();
  EXPECT_LE((rotation_towards(u, v, 1.0) * u - v).norm(), 1e-15);
  const Vec3 half = rotation_towards(u, v, 0.5) * u;
  EXPECT_NEAR(std::acos(half.dot(u)), 0.5 * std::acos(u.dot(v)), 1e-14);
  EXPECT_NEAR(half.dot(u.cross(v)), 0.0, 1e-15);
  EXPECT_LE((rotation_towards(u, -u, 1.0) * u + u).norm(), 1e-15);
  EXPECT_LE((rotation_towards(Vec3::UnitZ(), -Vec3::UnitZ(), 1.0) * Vec3::UnitZ() + Vec3::UnitZ()).norm(), 1e-15);
  EXPECT_EQ(rotation_towards(u, u, 0.7).angularDistance(Quat::Identity()), 0.0);
}

}  // namespace
}  // namespace chaser
