// The thruster configuration matrix M (Fonod 2015, eq. 2) and the partner property of the MSR
// layout (section II.B, Fig. 3): each active thruster has a partner with the same torque and the
// opposite force.
#include "model/thruster_geometry.hpp"

#include <gtest/gtest.h>

#include "tests/support/msr_branch_a.hpp"

namespace chaser::model {
namespace {

ThrusterSetParams msr_branch_a() { return testing::msr_branch_a_thrusters(); }

// Column i is [F_i; (p_i - c) x F_i] with |F_i| = 22 N.
TEST(ThrusterGeometry, ColumnsAreForceAndMomentAboutTheCentreOfMass) {
  const ThrusterSetParams set = msr_branch_a();
  const Vec3 com(0.03, -0.02, 0.01);
  const ConfigMatrix m = configuration_matrix(set, all_thrusters(set), com);
  for (int i = 0; i < set.count; ++i) {
    const Vec3 force = 22.0 * set.thrusters[i].direction_body;
    EXPECT_LT((m.col(i).head<3>() - force).norm(), 1e-14);
    EXPECT_LT((m.col(i).tail<3>() - (set.thrusters[i].position_body_m - com).cross(force)).norm(), 1e-13);
  }
}

// With the centre of mass at the reference point, partners give the same torque and opposite
// forces exactly (to round-off). Moving the centre of mass by c breaks the torque equality by
// exactly 2 c x F_i: tau_partner - tau_i = (p + c) x F - (p - c) x F.
TEST(ThrusterGeometry, PartnersGiveSameTorqueAndOppositeForce) {
  const ThrusterSetParams set = msr_branch_a();
  const ConfigMatrix m = configuration_matrix(set, all_thrusters(set), Vec3::Zero());
  const Vec3 com(0.03, -0.02, 0.01);
  const ConfigMatrix m_offset = configuration_matrix(set, all_thrusters(set), com);
  for (int i = 0; i < 4; ++i) {
    EXPECT_LT((m.col(i).head<3>() + m.col(i + 4).head<3>()).norm(), 1e-14);
    EXPECT_LT((m.col(i).tail<3>() - m.col(i + 4).tail<3>()).norm(), 1e-13);
    const Vec3 expected = 2.0 * com.cross(Vec3(m.col(i).head<3>()));
    EXPECT_LT((m_offset.col(i + 4).tail<3>() - m_offset.col(i).tail<3>() - expected).norm(), 1e-13);
  }
}

// M has full rank 6: four independent forces and four torques spanning R^3 (section II.B).
TEST(ThrusterGeometry, BranchHasFullRank) {
  const ConfigMatrix m = configuration_matrix(msr_branch_a(), first_thrusters(8), Vec3::Zero());
  EXPECT_EQ(Eigen::FullPivLU<ConfigMatrix>(m).rank(), 6);
}

}  // namespace
}  // namespace chaser::model
