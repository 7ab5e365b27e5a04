#include "plant/target.hpp"

#include <gtest/gtest.h>

#include "core/rotation.hpp"

namespace chaser::plant {
namespace {

// A constant inertial rate w turns the target by |w| t about w: the attitude change
// q(t) q(0)^-1 is that rotation, and a target at rest keeps its attitude exactly.
TEST(Target, TurnsAtItsConstantInertialRate) {
  model::TargetParams target;
  target.q_inertial_from_target = quat_from_rotation_vector(Vec3(0.2, -0.4, 0.1));
  target.omega_inertial_radps = Vec3(0.0, 0.0, 0.001);
  const Quat q = target_attitude(target, 500.0);
  const Vec3 turned = rotation_vector_from_quat(q * target.q_inertial_from_target.conjugate());
  EXPECT_LT((turned - Vec3(0.0, 0.0, 0.5)).norm(), 1e-14);
  target.omega_inertial_radps.setZero();
  EXPECT_TRUE(target_attitude(target, 1e4).isApprox(target.q_inertial_from_target, 1e-15));
}

// The rate in the target's own axes is what its attitude does: with a constant rate,
// q(t + dt) = q(t) exp(w_body dt), so the rotation vector of q(t)^-1 q(t + dt) over dt is w_body
// exactly (no truncation), at any t and for a rate off every axis; round-off leaves 1e-12 of it.
TEST(Target, BodyRateIsTheAttitudesOwnIncrement) {
  model::TargetParams target;
  target.q_inertial_from_target = quat_from_rotation_vector(Vec3(0.3, 0.1, -0.5));
  target.omega_inertial_radps = Vec3(0.004, -0.002, 0.001);
  for (const double t : {0.0, 250.0, 3000.0}) {
    const TargetRotation now = target_rotation(target, t);
    EXPECT_EQ(now.q_inertial_from_target.coeffs(), target_attitude(target, t).coeffs());
    const Vec3 seen = rotation_vector_from_quat(now.q_inertial_from_target.conjugate() * target_attitude(target, t + 1.0));
    EXPECT_LT((seen - now.omega_body_radps).norm(), 1e-12 * target.omega_inertial_radps.norm()) << t;
    EXPECT_NEAR(now.omega_body_radps.norm(), target.omega_inertial_radps.norm(), 1e-15 * target.omega_inertial_radps.norm());
  }
}

// The body-frame rate of the target is constant in magnitude along the whole tumble: a finite
// difference of the attitude over 1 s recovers |w| at any time (to the difference's O(dt^2)).
TEST(Target, FiniteDifferenceRateMatches) {
  model::TargetParams target;
  target.omega_inertial_radps = Vec3(0.001, -0.002, 0.0005);
  for (const double t : {0.0, 100.0, 1000.0}) {
    const Quat dq = target_attitude(target, t + 1.0) * target_attitude(target, t).conjugate();
    EXPECT_NEAR(rotation_vector_from_quat(dq).norm(), target.omega_inertial_radps.norm(), 1e-12);
  }
}

}  // namespace
}  // namespace chaser::plant
