#include "flight/fdi/design/fdi_models.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <unsupported/Eigen/MatrixFunctions>

#include "core/rotation.hpp"
#include "test_matrices.hpp"

namespace chaser::flight::fdi {
namespace {

using Eigen::MatrixXd;
using testing::relative_error;

// Clohessy-Wiltshire state transition matrix in MSR LVLH (x radial, y along-track, z normal).
MatrixXd cw_transition(double n, double t) {
  const double c = std::cos(n * t);
  const double s = std::sin(n * t);
  MatrixXd phi(6, 6);
  phi << 4 - 3 * c, 0, 0, s / n, 2 * (1 - c) / n, 0,
         6 * (s - n * t), 1, 0, -2 * (1 - c) / n, (4 * s - 3 * n * t) / n, 0,
         0, 0, c, 0, 0, s / n,
         3 * n * s, 0, 0, c, 2 * s, 0,
         -6 * n * (1 - c), 0, 0, -2 * s, 4 * c - 3, 0,
         0, 0, -n * s, 0, 0, c;
  return phi;
}

// The HCW model is right if its flow e^{At} is the closed-form CW transition matrix, over a short
// span and over half an orbit. 1e-11: e^{At} by Pade is accurate to ~1e-15 relative; the CW
// formulas lose a few digits to cancellation (s - n t) at small n t.
TEST(FdiModels, HcwFlowIsTheClohessyWiltshireTransition) {
  const double n = 8.5e-4;
  const LinearModel model = hcw_position_model(n, 2500.0);
  for (const double t : {0.1, 100.0, 3000.0})
    EXPECT_LT(relative_error((model.A * t).exp(), cw_transition(n, t)), 1e-11) << "t = " << t;
  EXPECT_EQ(model.B.topRows(3).norm(), 0.0);
  EXPECT_DOUBLE_EQ(model.B(3, 0), 1.0 / 2500.0);
  EXPECT_EQ(model.C, (MatrixXd(3, 6) << MatrixXd::Identity(3, 3), MatrixXd::Zero(3, 3)).finished());
}

// Linearised about rest (the paper), the attitude model is the double integrator theta'' = I^-1 tau.
TEST(FdiModels, AttitudeAtRestIsADoubleIntegrator) {
  const Mat3 inertia = Vec3(2000.0, 2500.0, 3000.0).asDiagonal();
  const LinearModel model = linear_attitude_model(inertia);
  MatrixXd expected = MatrixXd::Zero(6, 6);
  expected.topRightCorner(3, 3).setIdentity();
  EXPECT_EQ(model.A, expected);
  EXPECT_LT(relative_error(model.B.bottomRows(3), inertia.inverse()), 1e-15);
}

// About a reference turning at omega_ref, the linear model must be the Jacobian of the nonlinear
// kinematics and Euler's equations. Kinematics: the body quaternion is q_ref(t) * q(theta), so
// theta(h) = rotvec(exp(omega_ref h)^-1 * q(theta0) * exp(omega h)); central differences in h.
// Dynamics: -I^-1 (omega x I omega) differentiated in omega. Perturbations of 1e-6 make the
// neglected quadratic terms 1e-6 relative; tolerance 1e-4.
TEST(FdiModels, AttitudeAboutTurningReferenceIsTheJacobian) {
  const Mat3 inertia = (Mat3() << 2000, 30, -20, 30, 2500, 10, -20, 10, 3000).finished();
  const Vec3 w0(1e-3, -2e-3, 3e-3);
  const LinearModel model = linear_attitude_model(inertia, w0);
  const Vec3 theta0(1e-6, -2e-6, 1.5e-6);
  const Vec3 dw(-2e-6, 1e-6, 3e-6);
  const double h = 1e-3;
  const auto theta_at = [&](double t) {
    const Quat q = quat_from_rotation_vector(-w0 * t) * quat_from_rotation_vector(theta0) *
                   quat_from_rotation_vector((w0 + dw) * t);
    return rotation_vector_from_quat(q);
  };
  const Vec3 theta_dot = (theta_at(h) - theta_at(-h)) / (2 * h);
  const Vec3 predicted = model.A.topLeftCorner(3, 3) * theta0 + dw;
  EXPECT_LT((theta_dot - predicted).norm(), 1e-4 * predicted.norm());

  const auto euler = [&](const Vec3& w) -> Vec3 { return -inertia.inverse() * w.cross(inertia * w); };
  Mat3 jacobian;
  for (int k = 0; k < 3; ++k) {
    const Vec3 e = 1e-6 * Vec3::Unit(k);
    jacobian.col(k) = (euler(w0 + e) - euler(w0 - e)) / 2e-6;
  }
  EXPECT_LT(relative_error(model.A.bottomRightCorner(3, 3), jacobian), 1e-4);
}

}  // namespace
}  // namespace chaser::flight::fdi
