#include "control/state_space.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "control/frequency_response.hpp"

namespace chaser::control {
namespace {

using Eigen::MatrixXd;

// P of the SISO loop y = G u, e = r - y with z = e: F_l(P, k) = S = 1 / (1 + G k). G = 1/(s + 1)
// and a static k give S = (s + 1) / (s + 1 + k): a pole at -(1 + k) and S(0) = 1 / (1 + k).
// Exact to rounding (1e-14).
TEST(StateSpace, LowerLftOfAStaticGainIsTheSensitivity) {
  StateSpace p;
  p.a = MatrixXd::Constant(1, 1, -1.0);
  p.b = (MatrixXd(1, 2) << 0.0, 1.0).finished();
  p.c = (MatrixXd(2, 1) << -1.0, -1.0).finished();
  p.d = (MatrixXd(2, 2) << 1.0, 0.0, 1.0, 0.0).finished();
  const double k = 4.0;
  const StateSpace s = lower_lft(p, 1, 1, static_gain(MatrixXd::Constant(1, 1, k)));
  EXPECT_NEAR(max_real_pole(s), -(1.0 + k), 1e-14);
  EXPECT_NEAR(sigma_max(s, 0.0), 1.0 / (1.0 + k), 1e-14);
}

TEST(StateSpace, SizeProblemsAreNamedNotCrashed) {
  StateSpace p{MatrixXd::Zero(2, 2), MatrixXd::Zero(2, 3), MatrixXd::Zero(3, 2), MatrixXd::Zero(3, 3)};
  StateSpace k = static_gain(MatrixXd::Zero(2, 2));  // 2 outputs, but n_ctrl = 1
  try {
    lower_lft(p, 1, 1, k);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("controller K must have n_meas = 1 inputs and n_ctrl = 1 outputs"),
              std::string::npos)
        << e.what();
  }
  p.b.resize(2, 2);  // b disagrees with d
  EXPECT_FALSE(validate(p, "P").empty());
  EXPECT_THROW(lower_lft(p, 1, 1, static_gain(MatrixXd::Zero(1, 1))), std::invalid_argument);
}

// D22 Dk = 1 makes I - D22 Dk singular: no well-posed loop.
TEST(StateSpace, IllPosedLoopIsRefused) {
  StateSpace p{MatrixXd::Zero(0, 0), MatrixXd::Zero(0, 2), MatrixXd::Zero(2, 0), MatrixXd::Identity(2, 2)};
  EXPECT_THROW(lower_lft(p, 1, 1, static_gain(MatrixXd::Ones(1, 1))), std::invalid_argument);
}

}  // namespace
}  // namespace chaser::control
