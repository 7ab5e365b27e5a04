#include "core/linear_models.hpp"

#include <gtest/gtest.h>

#include "core/constants.hpp"

namespace chaser {
namespace linear_models_test {

constexpr double kN = 8.53e-4;  // [rad/s]

// hcw_acceleration is the acceleration half of A [r; v] (used by the control feed-forward, so a
// mismatch would leave a steady tracking error).
TEST(LinearModels, HcwAccelerationIsLowerHalfOfStateMatrix) {
  const Vec3 r(1.5, -20.0, 0.3), v(0.01, -0.02, 0.003);
  Vec6 x;
  x << r, v;
  const Vec6 xdot = hcw_state_matrix(kN) * x;
  EXPECT_LT((xdot.tail<3>() - hcw_acceleration(kN, r, v)).norm(), 1e-20);
  EXPECT_EQ(xdot.head<3>(), v);
}

// HCW closed orbits: a point on the along-track axis is an equilibrium, and the 2:1 relative
// ellipse (vy0 = -2 n x0, centred, plus an out-of-plane oscillation) returns to its start after
// one orbit. 1e-9 relative: the one-orbit transition is computed by one exponential of norm ~30.
TEST(LinearModels, HcwEquilibriumAndClosedEllipse) {
  const DiscreteLinear6 step = discrete_hcw(kN, 0.1);
  Vec6 vbar;
  vbar << 0.0, -20.0, 0.0, 0.0, 0.0, 0.0;
  EXPECT_LT((step.Ad * vbar - vbar).norm(), 1e-14);
  const DiscreteLinear6 orbit = discrete_hcw(kN, 2.0 * kPi / kN);
  Vec6 ellipse;
  ellipse << 2.0, 0.0, 1.0, 0.0, -2.0 * kN * 2.0, 0.5 * kN;
  EXPECT_LT((orbit.Ad * ellipse - ellipse).norm(), 1e-9 * ellipse.norm());
}

// With a diagonal inertia the linearised attitude is three double integrators:
// Ad = [[I, T I], [0, I]], Bd = [T^2/2 I^-1; T I^-1].
TEST(LinearModels, AttitudeIsDoubleIntegratorThroughInertia) {
  const Mat3 inertia = Vec3(2000.0, 2500.0, 3000.0).asDiagonal();
  const double T = 0.1;
  const DiscreteLinear6 d = discrete_attitude(inertia, T);
  Mat6 ad = Mat6::Identity();
  ad.topRightCorner<3, 3>() = T * Mat3::Identity();
  Mat63 bd;
  bd << 0.5 * T * T * inertia.inverse(), T * inertia.inverse();
  EXPECT_LT((d.Ad - ad).norm(), 1e-15);
  EXPECT_LT((d.Bd - bd).norm(), 1e-18);
}

}  // namespace linear_models_test
}  // namespace chaser
