// MuJoCo's joint-space mass matrix of a free hub with one child against the closed form: the base
// block is the composite's spatial inertia about the hub's origin, the joint's block the child's
// inertia about (hinge) or mass along (slide) its axis. The hub and child of Basilisk's
// MJSystemMassMatrix test (50 kg, diag(10, 11, 12); 10 kg, diag(5, 6, 7), 0.6 m along x).
// Tolerance 1e-10: the matrix is assembled from these numbers by a few sums and products (CRBA),
// so it is exact to rounding.
#include <string>

#include <fmt/format.h>
#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "core/types.hpp"
#include "plant/multibody/mujoco_model.hpp"

namespace chaser::plant::multibody {
namespace {

std::string hub_with_child(const char* joint_type, const char* axis) {
  return fmt::format(R"(<mujoco>
  <option gravity="0 0 0"/>
  <worldbody>
    <body name="hub">
      <freejoint/>
      <inertial pos="0 0 0" mass="50" diaginertia="10 11 12"/>
      <body name="child" pos="0.6 0 0">
        <joint name="j" type="{}" axis="{}"/>
        <inertial pos="0 0 0" mass="10" diaginertia="5 6 7"/>
      </body>
    </body>
  </worldbody>
</mujoco>)",
                     joint_type, axis);
}

Mat3 cross_matrix(const Vec3& v) {
  Mat3 m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

// The free base's 6 x 6 block: qvel = (v of the hub's origin, world axes; omega, hub axes), here
// aligned. Kinetic energy of body i at c_i: m_i |v + omega x c_i|^2 / 2 + omega' I_i omega / 2.
Mat6 composite_base_block() {
  const double m_hub = 50.0, m_child = 10.0;
  const Vec3 c_child(0.6, 0.0, 0.0);
  const double m = m_hub + m_child;
  const Vec3 c = m_child * c_child / m;
  Mat3 I = Vec3(10, 11, 12).asDiagonal().toDenseMatrix() + Vec3(5, 6, 7).asDiagonal().toDenseMatrix();
  I += m_child * (c_child.squaredNorm() * Mat3::Identity() - c_child * c_child.transpose());  // parallel axes
  Mat6 M;
  M.topLeftCorner<3, 3>() = m * Mat3::Identity();
  M.topRightCorner<3, 3>() = -m * cross_matrix(c);
  M.bottomLeftCorner<3, 3>() = m * cross_matrix(c);
  M.bottomRightCorner<3, 3>() = I;
  return M;
}

TEST(MassMatrix, HingeChildMatchesTheCompositeClosedForm) {
  MujocoModel model(hub_with_child("hinge", "0 0 1"));
  model.forward();
  const Eigen::MatrixXd M = model.mass_matrix();
  ASSERT_EQ(M.rows(), 7);
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(7, 7);
  expected.topLeftCorner<6, 6>() = composite_base_block();
  expected(6, 6) = 7.0;  // the child's I_zz: its CoM is on the hinge
  expected(5, 6) = expected(6, 5) = 7.0;  // the hub's omega_z turns the child as the hinge does
  EXPECT_LT((M - expected).cwiseAbs().maxCoeff(), 1e-10) << M;
  EXPECT_LT((M - M.transpose()).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(M).eigenvalues().minCoeff(), 0.0);
}

TEST(MassMatrix, SlideChildMatchesTheCompositeClosedForm) {
  MujocoModel model(hub_with_child("slide", "1 0 0"));
  model.forward();
  const Eigen::MatrixXd M = model.mass_matrix();
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(7, 7);
  expected.topLeftCorner<6, 6>() = composite_base_block();
  expected(6, 6) = 10.0;  // the child's mass
  expected(0, 6) = expected(6, 0) = 10.0;  // the slide moves it along the hub's x
  EXPECT_LT((M - expected).cwiseAbs().maxCoeff(), 1e-10) << M;
}

}  // namespace
}  // namespace chaser::plant::multibody
