// The body-rate model with slosh (flight/fdi/design/rate_model.hpp) against what it must keep: each
// tank's first-mode frequency and damping from the fill formula (model/slosh.hpp) when the body is
// too heavy to move, the one mode COMRADE-like symmetric tanks hide (no torque, driven by none) at
// exactly that frequency, the non-linear coupled equations under a small torque, and the reduced
// model's rates equal to the full model's.
#include "flight/fdi/design/rate_model.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <span>
#include <stdexcept>

#include "model/chaser_slosh.hpp"
#include "model/slosh.hpp"
#include "tests/support/two_tank_chaser.hpp"

namespace chaser::flight::fdi {
namespace {

using chaser::testing::two_tank_chaser;

// The first mode of one tank alone (the formula the plant's analogue comes from).
model::SloshTankFill fill_of(const model::SloshTankSpec& t, double g_eff) {
  const model::CylindricalTank tank{.bottom_centre_body_m = t.bottom_centre_body_m, .axis_body = t.axis_body,
                                    .radius_m = t.radius_m};
  return model::slosh_tank_from_fill(tank, t.liquid_mass_kg, model::fill_height_m(t), g_eff, t.damping_ratio);
}

// A body a million times heavier does not move: every mode is a tank's own, at omega1 with zeta.
TEST(RateModel, OnAnImmovableBodyEachModeIsTheTanksOwn) {
  const model::Scenario s = two_tank_chaser(1.6e9, Vec3::Constant(1.5e9));
  const RateModel m = rate_model(s);
  const model::SloshTankFill fill = fill_of(s.chaser.slosh->tanks[0], 0.005);
  ASSERT_EQ(m.modes.size(), 4u);
  for (const SloshModeFigures& f : m.modes) {
    EXPECT_NEAR(f.frequency_radps / fill.omega_radps, 1.0, 1e-6);
    EXPECT_NEAR(f.damping_ratio, 0.005, 1e-6);
  }
}

// COMRADE's chaser: the tanks' masses swinging against each other along the line joining the tanks
// give no torque and no force, and nothing drives them; that mode keeps the tank's own frequency
// (to round-off) and is dropped. The three others move the body, which stiffens them (the body's
// reaction lowers their effective mass), and are kept: order 3 + 2 x 3 = 9.
TEST(RateModel, SymmetricTanksHideOneModeAndKeepThree) {
  const model::Scenario s = two_tank_chaser();
  const RateModel m = rate_model(s);
  const double omega1 = fill_of(s.chaser.slosh->tanks[0], 0.005).omega_radps;
  ASSERT_EQ(m.A.rows(), 11);
  EXPECT_EQ(m.A_reduced.rows(), 9);
  EXPECT_EQ(m.B.cols(), 24);
  int dropped = 0;
  for (const SloshModeFigures& f : m.modes) {
    if (!f.kept) {
      ++dropped;
      EXPECT_NEAR(f.frequency_radps / omega1, 1.0, 1e-9);
      EXPECT_LT(f.controllability, 1e-10);
      EXPECT_LT(f.observability, 1e-10);
    } else {
      EXPECT_GT(f.frequency_radps, omega1 * (1.0 + 1e-3));
    }
  }
  EXPECT_EQ(dropped, 1);
}

// A small torque about every axis for 30 s: the linear model's rates against the coupled non-linear
// equations integrated from rest (RK4, 0.01 s). Their difference is second order in the motion (the
// products omega x I omega and the Coriolis terms): 1.7e-3 of the rates at 0.05 N m, and it halves
// with the torque (the ratio is checked within 10 %). The reduced model's rates equal the full
// model's to round-off: what it drops is neither driven nor seen.
TEST(RateModel, LinearisationAndReductionKeepTheRates) {
  const model::Scenario s = two_tank_chaser();
  const RateModel m = rate_model(s);
  model::SpacecraftParams chaser = s.chaser;
  chaser.slosh->model = model::SloshModel::spring_mass;
  const model::ChaserSloshParams sl = model::chaser_slosh(chaser);
  const model::RigidBodyMassProps body{.mass_kg = chaser.mass_kg - sl.mass_kg,
                                       .inertia_com_body_kgm2 = sl.body_inertia_kgm2,
                                       .com_body_m = sl.body_com_body_m};
  const double h = 0.01;
  struct State { Vec3 w = Vec3::Zero(); std::array<model::SloshState, 2> s{}; };
  const auto add = [](const State& x, const State& d, double k) {
    State y = x;
    y.w += k * d.w;
    for (std::size_t i = 0; i < 2; ++i) {
      y.s[i].s_body_m += k * d.s[i].s_body_m;
      y.s[i].s_dot_body_mps += k * d.s[i].s_dot_body_mps;
    }
    return y;
  };
  const auto rk4 = [h](const auto& g, auto& y) {
    const auto k1 = g(y), k2 = g(y + 0.5 * h * k1), k3 = g(y + 0.5 * h * k2), k4 = g(y + h * k3);
    y += (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  };
  // The non-linear, full linear and reduced rates after 30 s of `torque` (E: a torque on the body).
  const auto fly = [&](const Vec3& torque) {
    const auto f = [&](const State& x) {
      const model::SloshAccelerations a = model::coupled_accelerations(
          body, sl.body_inertia_inv_kgm2, std::span(sl.tanks.data(), 2),
          std::span<const model::SloshState>(x.s.data(), 2), x.w, Vec3::Zero(), torque);
      State d;
      d.w = a.omega_dot_body_radps2;
      for (std::size_t i = 0; i < 2; ++i) d.s[i] = {a.s_dot_body_mps[i], a.s_ddot_body_mps2[i]};
      return d;
    };
    State x;
    Eigen::VectorXd xf = Eigen::VectorXd::Zero(m.A.rows()), xr = Eigen::VectorXd::Zero(m.A_reduced.rows());
    const Eigen::VectorXd df = m.E * torque, dr = m.E_reduced * torque;
    for (int k = 0; k < 3000; ++k) {
      const State k1 = f(x), k2 = f(add(x, k1, h / 2)), k3 = f(add(x, k2, h / 2)), k4 = f(add(x, k3, h));
      x = add(add(add(add(x, k1, h / 6), k2, h / 3), k3, h / 3), k4, h / 6);
      rk4([&](const Eigen::VectorXd& y) { return Eigen::VectorXd(m.A * y + df); }, xf);
      rk4([&](const Eigen::VectorXd& y) { return Eigen::VectorXd(m.A_reduced * y + dr); }, xr);
    }
    return std::array<Vec3, 3>{x.w, m.C * xf, m.C_reduced * xr};
  };
  const auto relative = [](const std::array<Vec3, 3>& r) { return (r[1] - r[0]).norm() / r[0].norm(); };
  const std::array<Vec3, 3> big = fly(Vec3::Constant(0.05)), small = fly(Vec3::Constant(0.025));
  EXPECT_GT(big[0].norm(), 5e-4);  // [rad/s] it did turn
  EXPECT_LT(relative(big), 3e-3);
  EXPECT_NEAR(relative(big) / relative(small), 2.0, 0.2);
  EXPECT_LT((big[2] - big[1]).norm(), 1e-9 * big[1].norm());
}

TEST(RateModel, NeedsTheTanks) {
  model::Scenario s = two_tank_chaser();
  s.chaser.slosh.reset();
  EXPECT_THROW(rate_model(s), std::invalid_argument);
}

}  // namespace
}  // namespace chaser::flight::fdi
