#include "flight/fdi/design/design_inputs.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "../msr_test_setup.hpp"

namespace chaser::flight::fdi {
namespace {

using Eigen::MatrixXd;

// The position inputs are the HCW model of the scenario's orbit and mass (eqs. 7, 12), with the
// thrusters' LVLH force directions as faults (eq. 11, R = I) and the paper's delay range [0, T].
TEST(DesignInputs, PositionFromScenario) {
  const model::Scenario s = testing::msr_test_scenario();
  const SchemeConfig M = testing::msr_test_configuration(s);
  const DesignInputs in = position_design_inputs(s, M);
  const double n = std::sqrt(4.282837e13 / std::pow(3889.5e3, 3));
  EXPECT_NEAR(in.A(3, 0), 3 * n * n, 1e-20);
  EXPECT_NEAR(in.A(3, 4), 2 * n, 1e-16);
  EXPECT_EQ(in.E_f, in.B * M.topRows(3));
  EXPECT_EQ(in.fault_inputs, MatrixXd(M.topRows(3)));
  EXPECT_EQ(in.period_s, 0.1);
  EXPECT_EQ(in.delta_max_s, 0.1);
  EXPECT_EQ(in.name, "position");
  EXPECT_EQ(in.residual_unit, "m");
}

// The attitude inputs: torques through the inverse inertia (eq. 15), M_C as fault directions.
TEST(DesignInputs, AttitudeFromScenario) {
  const model::Scenario s = testing::msr_test_scenario();
  const SchemeConfig M = testing::msr_test_configuration(s);
  const DesignInputs in = attitude_design_inputs(s, M);
  EXPECT_NEAR(in.B(3, 0), 1.0 / 2000.0, 1e-18);
  EXPECT_EQ(in.E_f, in.B * M.bottomRows(3));
  EXPECT_EQ(in.A.topLeftCorner(3, 3).norm(), 0.0);
  EXPECT_EQ(in.name, "attitude");
  EXPECT_EQ(in.eigenvalues.size(), 6u);
}

}  // namespace
}  // namespace chaser::flight::fdi
