// The multi-estimator supervisor (flight/fdi/mode_supervisor.hpp) on the discrete rate model its
// estimators come from (COMRADE's two tanks, the tests' box of 24 thrusters), flown open loop with
// random commands and gyro noise:
// - its corrected estimators are the mode-matched estimators run plainly (the reference beside the
//   kernel), to rounding;
// - fault-free, it never leaves the nominal mode;
// - a stuck-open thruster switches it to that mode once, within seconds, and a fault that clears
//   switches it back, no sooner than the dwell time;
// - a stuck-closed thruster switches it to that mode once the thruster is fired, and not before
//   (the hysteresis keeps the nominal mode while the data cannot tell the two apart);
// - a thruster outside the model's columns, or twice, is refused.
#include "flight/fdi/mode_supervisor.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <random>
#include <stdexcept>

#include "flight/fdi/design/uio_bank.hpp"
#include "tests/support/two_tank_chaser.hpp"

namespace chaser::flight::fdi {
namespace {

using chaser::testing::two_tank_chaser;

constexpr double kT = 0.1;  // [s]
constexpr int kT1 = 0, kT5 = 4, kT13 = 12;  // thruster indices

struct Supervised {
  model::Scenario scenario = two_tank_chaser();
  UioBank design;
  SupervisorParams params;
};

// T1, T5 and T13 monitored (their torques are not parallel on the box: checked below), modes
// 0 nominal, 1/2 T1 open/closed, 3/4 T5, 5/6 T13.
Supervised make_setup(const SupervisorKeys& keys = {.period_s = kT, .forgetting_s = 2.0, .bias_s = 100.0, .settle_s = 20.0,
                                                .dwell_s = 5.0, .hysteresis = 1.0, .floor_radps = 2e-5}) {
  Supervised s;
  UioBankParams p;
  p.figures = false;
  p.decoupled = false;
  s.design = design_uio_bank(rate_model(s.scenario), p);
  std::vector<int> columns;
  for (int t = 0; t < s.scenario.thrusters.count; ++t) columns.push_back(t);
  s.params = make_supervisor(s.design, columns, {kT1, kT5, kT13}, s.scenario.chaser.inertia_kgm2, keys);
  return s;
}

struct Period {
  model::ThrusterOnTimes commanded{};  // what the flight software asks (the supervisor reads it)
  model::ThrusterOnTimes applied{};    // what the thrusters give
};

// Random on-times up to 5 % on every thruster; `fault` turns the command into what is applied.
std::function<Period(int)> commands(const std::function<void(int, Period&)>& fault, std::vector<int> silent = {}) {
  auto rng = std::make_shared<std::mt19937_64>(11);
  return [=](int k) {
    std::uniform_real_distribution<double> on(0.0, 0.05);
    Period p;
    for (int t = 0; t < 24; ++t) p.commanded[static_cast<std::size_t>(t)] = on(*rng);
    for (const int t : silent) p.commanded[static_cast<std::size_t>(t)] = 0.0;
    p.applied = p.commanded;
    fault(k, p);
    return p;
  };
}

struct Flown {
  SupervisorState state;
  std::vector<int> mode_at;  // sigma after each period
};

// The discrete model from rest with gyro noise (1e-6 rad/s) and the gyroscopic torque held over
// each period, as the observer bank's tests fly it.
Flown fly(const Supervised& s, int periods, const std::function<Period(int)>& input) {
  Flown f{make_supervisor_state(s.params), {}};
  std::mt19937_64 rng(3);
  std::normal_distribution<double> gyro(0.0, 1e-6);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(s.design.Ad.rows());
  const Eigen::Index m = s.design.Bd.cols();
  for (int k = 0; k < periods; ++k) {
    const Period in = input(k);
    const Vec3 y = s.design.C * x + Vec3(gyro(rng), gyro(rng), gyro(rng));
    step_supervisor(s.params, f.state, k * kT, y, in.commanded);
    f.mode_at.push_back(f.state.mode);
    const Vec3 omega = s.design.C * x;
    const Vec3 gyroscopic_Nm = -omega.cross(s.scenario.chaser.inertia_kgm2 * omega);
    x = s.design.Ad * x + s.design.Bd * Eigen::Map<const Eigen::VectorXd>(in.applied.data(), m) +
        s.design.Ed * gyroscopic_Nm;
  }
  return f;
}

Vec3 torque_of(const model::ThrusterSetParams& set, int i) {
  const auto& t = set.thrusters[static_cast<std::size_t>(i)];
  return t.position_body_m.cross(t.direction_body);
}

TEST(ModeSupervisor, MonitoredTorquesAreNotParallel) {
  const model::Scenario s = two_tank_chaser();
  for (const auto& [a, b] : {std::pair{kT1, kT5}, std::pair{kT1, kT13}, std::pair{kT5, kT13}})
    EXPECT_GT(torque_of(s.thrusters, a).normalized().cross(torque_of(s.thrusters, b).normalized()).norm(), 0.1);
}

// The kernel's correction form against every mode's estimator run with its own input (the nominal
// observer, z(k+1) = N z + L y + Bd u_m + Ed tau): the monitoring signals agree to rounding. The
// bias the kernel subtracts is the nominal's filtered residual in the nominal mode; the reference
// forms it the same way. 1e-9 relative: a few hundred periods of sums of 1e-6-sized terms.
TEST(ModeSupervisor, CorrectionsAreTheModeMatchedEstimators) {
  const Supervised s = make_setup();
  const int periods = 600;
  const Flown f = fly(s, periods, commands([](int, Period&) {}));
  ASSERT_EQ(f.state.mode, 0);
  const auto input = commands([](int, Period&) {});  // the same commands again (its own generator)

  const Eigen::Index n = s.design.Ad.rows(), modes = static_cast<Eigen::Index>(s.params.modes.size());
  std::vector<Eigen::VectorXd> x_hat(static_cast<std::size_t>(modes), Eigen::VectorXd::Zero(n));
  Eigen::VectorXd mu = Eigen::VectorXd::Zero(modes);
  Vec3 bias = Vec3::Zero();
  std::mt19937_64 rng(3);
  std::normal_distribution<double> gyro(0.0, 1e-6);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  const Eigen::Index m = s.design.Bd.cols();
  for (int k = 0; k < periods; ++k) {
    const Period in = input(k);
    const Vec3 y = s.design.C * x + Vec3(gyro(rng), gyro(rng), gyro(rng));
    if (k == 0)
      for (auto& z : x_hat) z.head<3>() = y;
    const Vec3 tau = -y.cross(s.scenario.chaser.inertia_kgm2 * y);
    const Vec3 r0 = y - s.design.C * x_hat[0];
    bias = k == 0 ? r0 : Vec3(s.params.bias_forget * bias + (1.0 - s.params.bias_forget) * r0);
    for (Eigen::Index i = 0; i < modes; ++i) {
      Eigen::VectorXd u = Eigen::Map<const Eigen::VectorXd>(in.commanded.data(), m);
      const SupervisorMode& mode = s.params.modes[static_cast<std::size_t>(i)];
      if (mode.column >= 0) u(mode.column) = mode.on_fraction;
      Eigen::VectorXd& z = x_hat[static_cast<std::size_t>(i)];
      const Vec3 r = y - s.design.C * z;
      mu(i) = s.params.forget * mu(i) + (1.0 - s.params.forget) * (r - bias).squaredNorm();
      z = s.design.nominal.N * z + s.design.nominal.L * y + s.design.Bd * u + s.design.Ed * tau;
    }
    const Vec3 omega = s.design.C * x;
    x = s.design.Ad * x + s.design.Bd * Eigen::Map<const Eigen::VectorXd>(in.applied.data(), m) +
        s.design.Ed * (-omega.cross(s.scenario.chaser.inertia_kgm2 * omega));
  }
  for (Eigen::Index i = 0; i < modes; ++i) EXPECT_NEAR(f.state.mu(i), mu(i), 1e-9 * mu.maxCoeff()) << "mode " << i;
}

TEST(ModeSupervisor, FaultFreeStaysNominal) {
  const Supervised s = make_setup();
  const Flown f = fly(s, 3000, commands([](int, Period&) {}));
  EXPECT_EQ(f.state.switches, 0);
  EXPECT_EQ(f.state.mode, 0);
}

// T5 stuck open at 50 s: mode 3 within 3 s (measured 2.3 s: the residual's step passes the
// monitoring signal's 2 s low-pass), and no other switch.
TEST(ModeSupervisor, StuckOpenSwitchesOnceToItsMode) {
  const Supervised s = make_setup();
  const int onset = 500;
  const Flown f = fly(s, onset + 600, commands([&](int k, Period& p) {
                        if (k >= onset) p.applied[kT5] = 1.0;
                      }));
  EXPECT_EQ(f.state.mode, 3);
  EXPECT_EQ(f.state.switches, 1);
  EXPECT_GE(f.state.log[0].t_s, onset * kT);
  EXPECT_LE(f.state.log[0].t_s, onset * kT + 3.0);
}

// T13 stuck open for 30 s, then healthy again: back to nominal, and never two switches closer than
// the dwell time.
TEST(ModeSupervisor, AClearedFaultSwitchesBackAfterTheDwell) {
  const Supervised s = make_setup();
  const int onset = 500, cleared = 800;
  const Flown f = fly(s, cleared + 600, commands([&](int k, Period& p) {
                        if (k >= onset && k < cleared) p.applied[kT13] = 1.0;
                      }));
  ASSERT_EQ(f.state.switches, 2);
  EXPECT_EQ(f.state.log[0].mode, 5);
  EXPECT_EQ(f.state.log[1].mode, 0);
  EXPECT_GE(f.state.log[1].t_s - f.state.log[0].t_s, 5.0 - 1e-9);
  EXPECT_GE(f.state.log[1].t_s, cleared * kT);
  EXPECT_EQ(f.state.mode, 0);
}

// T1 stuck closed at 50 s but not commanded until 100 s: the data cannot tell the nominal from
// "T1 stuck closed" (the two estimators see the same input), so sigma stays nominal; once T1 is
// fired (random on-times up to 5 %), mode 2.
TEST(ModeSupervisor, StuckClosedWaitsForACommand) {
  const Supervised s = make_setup();
  const int onset = 500, fired = 1000;
  const auto input = commands([&](int k, Period& p) {
    if (k < fired) p.commanded[kT1] = 0.0;
    p.applied[kT1] = k >= onset ? 0.0 : p.commanded[kT1];
  });
  const Flown f = fly(s, fired + 600, input);
  EXPECT_EQ(f.mode_at[static_cast<std::size_t>(fired - 1)], 0);
  EXPECT_EQ(f.state.mode, 2);
  EXPECT_EQ(f.state.switches, 1);
  EXPECT_GE(f.state.log[0].t_s, fired * kT);
}

TEST(ModeSupervisor, RefusesAThrusterWithoutAColumnOrTwice) {
  Supervised s = make_setup();
  const std::vector<int> columns = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23};
  const SupervisorKeys keys{};
  EXPECT_THROW(make_supervisor(s.design, columns, {kT5, kT5}, s.scenario.chaser.inertia_kgm2, keys), std::invalid_argument);
  EXPECT_THROW(make_supervisor(s.design, columns, {30}, s.scenario.chaser.inertia_kgm2, keys), std::invalid_argument);
  SupervisorKeys bad = keys;
  bad.dwell_s = 0.0;
  EXPECT_THROW(make_supervisor(s.design, columns, {kT5}, s.scenario.chaser.inertia_kgm2, bad), std::invalid_argument);
  // 2N + 1 modes.
  EXPECT_EQ(s.params.modes.size(), 7u);
}

}  // namespace
}  // namespace chaser::flight::fdi
