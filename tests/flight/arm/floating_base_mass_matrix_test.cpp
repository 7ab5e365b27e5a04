// The mass matrix H(q) (CRBA) against closed forms and against MuJoCo's mj_fullM of the same scene.
//
// Tolerances: the closed forms 1e-12 relative to H's largest entry (a few sums and products of the
// parameters, exact to rounding); MuJoCo 1e-9 relative to H's largest entry, as asked of the
// flight model: both are the CRBA on the same numbers, MuJoCo's about the subtree's CoM with its
// inertias diagonalised at compile time (an eigen-decomposition of the hub's tensor), so they agree
// to rounding (measured: 2.0e-15), far inside what a controller can notice. MuJoCo's hub inertia is
// the one it compiled (testing::servicer_arm_as_compiled: its diagonalisation of a full tensor is
// off by 4e-8 of it, which alone would exceed 1e-9).
#include <algorithm>

#include <gtest/gtest.h>
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "flight/arm/floating_base_mass_matrix.hpp"
#include "plant/multibody/mjcf.hpp"
#include "plant/multibody/mujoco_model.hpp"
#include "tests/flight/arm/arm_test_support.hpp"

namespace chaser::flight::arm {
namespace {

using plant::multibody::MujocoModel;
using plant::multibody::mjcf_of;

Mat3 cross(const Vec3& v) { return cross_matrix(v); }

// A 50 kg hub (diag(10, 11, 12) kg m^2) with one 10 kg link (diag(5, 6, 7)) whose CoM is on its
// hinge, about z, 0.6 m along the hub's x (the case of tests/plant/multibody/mass_matrix_test.cpp);
// links 2..7 massless and without armature.
ServicerArmParams one_link_arm(double armature_kgm2) {
  ServicerArmParams params;
  params.hub_mass_kg = 50.0;
  params.hub_inertia_kgm2 = Vec3(10.0, 11.0, 12.0).asDiagonal();
  ServicerLinkParams& link = params.links[0];
  link.joint_position_parent_m = Vec3(0.6, 0.0, 0.0);
  link.joint_axis = Vec3::UnitZ();
  link.mass_kg = 10.0;
  link.inertia_com_link_kgm2 = Vec3(5.0, 6.0, 7.0).asDiagonal();
  link.armature_kgm2 = armature_kgm2;
  return params;
}

// Kinetic energy m_i |v + omega x c_i|^2 / 2 + omega' I_i omega / 2 per body, in hub axes: the
// composite's mass, first moment m c and inertia about the hub's origin (parallel axes); the
// hinge's block the link's I_zz plus the armature, coupled to the hub's omega_z by I_zz.
ServicerMatrix one_link_closed_form_hub_axes(double armature_kgm2) {
  const double m = 60.0;
  const Vec3 h_kgm = 10.0 * Vec3(0.6, 0.0, 0.0);
  Mat3 inertia_kgm2 = Vec3(15.0, 17.0, 19.0).asDiagonal();
  inertia_kgm2 += 10.0 * Vec3(0.0, 0.36, 0.36).asDiagonal().toDenseMatrix();
  ServicerMatrix H = ServicerMatrix::Zero();
  H.topLeftCorner<3, 3>() = m * Mat3::Identity();
  H.block<3, 3>(0, 3) = -cross(h_kgm);
  H.block<3, 3>(3, 0) = cross(h_kgm);
  H.block<3, 3>(3, 3) = inertia_kgm2;
  H(6, 6) = 7.0 + armature_kgm2;
  H(5, 6) = H(6, 5) = 7.0;
  return H;
}

TEST(FloatingBaseMassMatrix, OneLinkArmIsTheCompositeClosedForm) {
  const double armature_kgm2 = 0.5;
  const ServicerArmParams params = one_link_arm(armature_kgm2);
  const ServicerMatrix expected_hub_axes = one_link_closed_form_hub_axes(armature_kgm2);
  const ServicerMatrix H = floating_base_mass_matrix(
      params, arm_kinematics(params, Vec3(3.0, -1.0, 2.0), Quat::Identity(), JointVector::Zero()));
  EXPECT_LT((H - expected_hub_axes).cwiseAbs().maxCoeff(), 1e-12 * 60.0) << H;
  // The hub turned: the linear dofs are in world axes, the rest in hub axes, so the linear rows
  // turn by R: H_lin = R H_lin(hub axes), and nothing else changes.
  const Quat q_world_from_hub = Quat(0.3, -0.5, 0.7, 0.2).normalized();
  const Mat3 world_from_hub = q_world_from_hub.toRotationMatrix();
  ServicerMatrix expected = expected_hub_axes;
  expected.topRows<3>() = world_from_hub * expected_hub_axes.topRows<3>();
  expected.leftCols<3>() = expected_hub_axes.leftCols<3>() * world_from_hub.transpose();
  expected.topLeftCorner<3, 3>() = 60.0 * Mat3::Identity();
  const ServicerMatrix turned =
      floating_base_mass_matrix(params, arm_kinematics(params, Vec3::Zero(), q_world_from_hub, JointVector::Zero()));
  EXPECT_LT((turned - expected).cwiseAbs().maxCoeff(), 1e-12 * 60.0) << turned;
}

// The stretched default arm along the hub's x: the base block is the servicer's total mass, its
// first moment sum m_i x_i along x, and the hub's inertia plus each body's inertia about the hub's
// origin (parallel axes: + m_i x_i^2 about y and z), from the table of docs/dynamics.md.
TEST(FloatingBaseMassMatrix, TheStretchedArmsBaseBlockIsTheServicersMassMomentAndInertia) {
  const model::MultibodySceneParams scene = testing::default_scene();
  const ServicerArmParams params = servicer_arm_of(scene);
  const ServicerMatrix H =
      floating_base_mass_matrix(params, arm_kinematics(params, Vec3::Zero(), Quat::Identity(), JointVector::Zero()));
  struct Body {
    double mass_kg, com_x_m;
    Vec3 inertia_kgm2;
  };
  const Body bodies[] = {{8.0, 1.15, model::tube_inertia_kgm2(8.0, 0.2, 0.10)},
                         {8.0, 1.35, model::tube_inertia_kgm2(8.0, 0.2, 0.10)},
                         {18.0, 2.0, model::tube_inertia_kgm2(18.0, 1.1, 0.08)},
                         {8.0, 2.65, model::tube_inertia_kgm2(8.0, 0.2, 0.10)},
                         {16.0, 3.25, model::tube_inertia_kgm2(16.0, 1.0, 0.08)},
                         {6.0, 3.8, model::tube_inertia_kgm2(6.0, 0.1, 0.08)},
                         {6.0, 3.9, model::tube_inertia_kgm2(6.0, 0.1, 0.08)},
                         {10.0, 4.0, model::tube_inertia_kgm2(10.0, 0.3, 0.10)}};  // the gripper
  double mass_kg = scene.hub_mass_kg, moment_x_kgm = 0.0;
  Mat3 inertia_kgm2 = scene.hub_inertia_kgm2;
  for (const Body& b : bodies) {
    mass_kg += b.mass_kg;
    moment_x_kgm += b.mass_kg * b.com_x_m;
    inertia_kgm2 += (b.inertia_kgm2 + b.mass_kg * b.com_x_m * b.com_x_m * Vec3(0.0, 1.0, 1.0)).asDiagonal();
  }
  EXPECT_NEAR(mass_kg, 1680.0, 1e-12);
  const double scale = H.cwiseAbs().maxCoeff();
  EXPECT_LT((H.topLeftCorner<3, 3>() - mass_kg * Mat3::Identity()).cwiseAbs().maxCoeff(), 1e-12 * scale);
  EXPECT_LT((H.block<3, 3>(0, 3) + cross(Vec3(moment_x_kgm, 0.0, 0.0))).cwiseAbs().maxCoeff(), 1e-12 * scale);
  EXPECT_LT((H.block<3, 3>(3, 3) - inertia_kgm2).cwiseAbs().maxCoeff(), 1e-12 * scale) << H.block<3, 3>(3, 3);
}

TEST(FloatingBaseMassMatrix, MatchesMujocosFullMAndIsSymmetricPositiveDefinite) {
  for (const model::MultibodySceneParams& scene : testing::scenes()) {
    MujocoModel mujoco(mjcf_of(scene));
    const ServicerArmParams params = testing::servicer_arm_as_compiled(scene, mujoco);
    RandomStream random(20180601, "flight/arm/mass_matrix");
    double worst_relative = 0.0;
    for (int n = 0; n < 20; ++n) {
      const testing::Configuration c = testing::random_configuration(random, scene.arm);
      testing::set_state(mujoco, c);
      const Eigen::MatrixXd full = mujoco.mass_matrix();  // 19 x 19: hub, arm, then the target
      const ServicerMatrix H = floating_base_mass_matrix(
          params, arm_kinematics(params, c.r_hub_world_m, c.q_world_from_hub, c.joint_angles_rad));
      const double scale = H.cwiseAbs().maxCoeff();
      const double error = (H - full.topLeftCorner<kServicerDofs, kServicerDofs>()).cwiseAbs().maxCoeff();
      worst_relative = std::max(worst_relative, error / scale);
      EXPECT_EQ(full.topRightCorner(kServicerDofs, full.cols() - kServicerDofs).cwiseAbs().maxCoeff(), 0.0);
      EXPECT_EQ((H - H.transpose()).cwiseAbs().maxCoeff(), 0.0);
      EXPECT_EQ(Eigen::LLT<ServicerMatrix>(H).info(), Eigen::Success);
      EXPECT_GT(Eigen::SelfAdjointEigenSolver<ServicerMatrix>(H).eigenvalues().minCoeff(), 0.0);
    }
    EXPECT_LT(worst_relative, 1e-9);  // measured: 2.0e-15
  }
}

}  // namespace
}  // namespace chaser::flight::arm
