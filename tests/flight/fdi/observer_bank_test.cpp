// The observer bank in flight (flight/fdi/observer_bank.hpp) on the discrete rate model it was
// designed from (flight/fdi/design/uio_bank.hpp), COMRADE's two tanks and the tests' box of 24
// thrusters: a stuck-open thruster alarms within a few blocks of its onset and leaves exactly the
// hypotheses the rates allow (its torque line: itself and the same-torque thruster too much, the
// opposite-torque pair too little when commanded); a thruster alone on its line is confirmed; a
// force change on a centre of mass off its place stays under the bound and alarms without it; a
// fault-free flight with noise does not alarm.
#include "flight/fdi/observer_bank.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "flight/fdi/design/uio_bank.hpp"
#include "tests/support/two_tank_chaser.hpp"

namespace chaser::flight::fdi {
namespace observer_bank_test {

using chaser::testing::two_tank_chaser;

constexpr double kT = 0.1;         // [s]
constexpr int kFullRing = 1200;     // periods to fill W + L = 120 s of blocks
constexpr int kT5 = 4;              // thruster index: T5

struct Flight {
  UioBank design;
  ObserverBankFlightParams params;
  WatchedSet set;
};

// The bank on `scenario`'s active thrusters, 20 s against 100 s, threshold 1 N m.
Flight make_flight(const model::Scenario& scenario, double com_uncertainty_m = 0.0) {
  Flight f;
  f.design = design_uio_bank(rate_model(scenario), UioBankParams{});
  std::vector<int> columns;
  for (int t = 0; t < scenario.thrusters.count; ++t) columns.push_back(t);
  f.params = make_observer_bank(f.design, columns, scenario.chaser.inertia_kgm2,
                                {.block = 10, .window_blocks = 20, .baseline_blocks = 100, .threshold_Nm = 1.0,
                                 .isolation_ratio = 0.2, .period_s = kT, .com_uncertainty_m = com_uncertainty_m,
                                 .inertia_uncertainty = 0.0});
  f.set.count = scenario.thrusters.count;
  for (int t = 0; t < f.set.count; ++t) f.set.index[static_cast<std::size_t>(t)] = t;
  return f;
}

struct PeriodInput {
  WatchedTon commanded = WatchedTon::Zero();  // what the flight software asks
  WatchedTon applied = WatchedTon::Zero();    // what the thrusters give
  Vec3 disturbance_Nm = Vec3::Zero();         // on the body, unknown to the bank
  Vec6 wrench = Vec6::Zero();                 // the commanded wrench the bank is told (body axes)
};

// Flies the discrete model from rest with gyro noise (1e-6 rad/s, the design's) and the gyroscopic
// torque held over each period, and returns the bank's state.
ObserverBankState fly(const Flight& f, int periods, const std::function<PeriodInput(int)>& input) {
  ObserverBankState s = make_observer_bank_state(f.params);
  std::mt19937_64 rng(3);
  std::normal_distribution<double> gyro(0.0, 1e-6);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(f.design.Ad.rows());
  const Eigen::Index m = f.design.Bd.cols();
  for (int k = 0; k < periods; ++k) {
    const PeriodInput in = input(k);
    const Vec3 y = f.design.C * x + Vec3(gyro(rng), gyro(rng), gyro(rng));
    step_observer_bank(f.params, s, y, f.set, in.commanded, in.wrench);
    // Euler's gyroscopic torque, which the bank computes from the gyro: a stuck-open thruster spins
    // the body up to ~0.5 rad/s in these flights.
    const Vec3 omega = f.design.C * x;
    const Vec3 gyroscopic_Nm = -omega.cross(f.params.inertia_kgm2 * omega);
    x = f.design.Ad * x + f.design.Bd * in.applied.head(m) + f.design.Ed * (in.disturbance_Nm + gyroscopic_Nm);
  }
  return s;
}

// Random commands on every thruster (on-times up to 5 %), T5 stuck open from `onset`.
std::function<PeriodInput(int)> stuck_open_t5(int onset, int thrusters, std::vector<int> silent = {}) {
  auto rng = std::make_shared<std::mt19937_64>(11);
  return [=](int k) {
    std::uniform_real_distribution<double> on(0.0, 0.05);
    PeriodInput in;
    for (int t = 0; t < thrusters; ++t) in.commanded[t] = on(*rng);
    for (const int t : silent) in.commanded[t] = 0.0;
    in.applied = in.commanded;
    if (k >= onset) in.applied[kT5] = 1.0;
    return in;
  };
}

// Thruster i's torque direction per unit thrust about the body origin [m].
Vec3 torque_of(const model::ThrusterSetParams& set, int i) {
  const auto& t = set.thrusters[static_cast<std::size_t>(i)];
  return t.position_body_m.cross(t.direction_body);
}

std::vector<int> parallel_torques(const model::ThrusterSetParams& set, int j) {
  std::vector<int> out;
  for (int i = 0; i < set.count; ++i)
    if (torque_of(set, i).cross(torque_of(set, j)).norm() < 1e-12) out.push_back(i);
  return out;
}

// Of those, the ones whose torque is opposite to j's: they give j's excess by giving too little.
std::vector<int> opposite_torques(const model::ThrusterSetParams& set, int j) {
  std::vector<int> out;
  for (const int t : parallel_torques(set, j))
    if (torque_of(set, t).dot(torque_of(set, j)) < 0) out.push_back(t);
  return out;
}

model::ThrusterMask mask_of(const std::vector<int>& thrusters) {
  model::ThrusterMask m = 0;
  for (const int t : thrusters) m |= model::ThrusterMask{1} << t;
  return m;
}

// 30 N m from T5 against 1 N m: the window's mean moves by a tenth of it per block, past 1 N m in
// the first block. The rates leave T5's torque line: four thrusters, and no confirmation.
TEST(ObserverBank, StuckOpenAlarmsAndLeavesItsTorqueLine) {
  const model::Scenario scenario = two_tank_chaser();
  const Flight f = make_flight(scenario);
  const int onset = kFullRing + 50;
  const ObserverBankState s = fly(f, onset + 300, stuck_open_t5(onset, 24));
  ASSERT_TRUE(s.alarm);
  EXPECT_GE(s.alarm_period, onset);
  EXPECT_LE(s.alarm_period, onset + 20);  // within two blocks
  EXPECT_EQ(s.hypotheses, mask_of(parallel_torques(scenario.thrusters, kT5)));
  EXPECT_EQ(s.confirmed, -1);
}

// The opposite-torque pair never commanded: "too little" is impossible for them, and T5 and its
// same-torque partner remain.
TEST(ObserverBank, TooLittleNeedsACommand) {
  const model::Scenario scenario = two_tank_chaser();
  const Flight f = make_flight(scenario);
  const std::vector<int> opposite = opposite_torques(scenario.thrusters, kT5);
  ASSERT_EQ(opposite.size(), 2u);
  const int onset = kFullRing + 50;
  const ObserverBankState s = fly(f, onset + 300, stuck_open_t5(onset, 24, opposite));
  ASSERT_TRUE(s.alarm);
  EXPECT_EQ(s.hypotheses, mask_of({kT5, chaser::testing::box_24_partner(kT5)}));
}

// Without the same-torque partner in the layout (23 thrusters) and the opposite pair silent, T5 is
// alone: confirmed after confirm_blocks blocks.
TEST(ObserverBank, ALoneHypothesisIsConfirmed) {
  model::Scenario scenario = two_tank_chaser();
  const int partner = chaser::testing::box_24_partner(kT5);
  ASSERT_GT(partner, kT5);
  for (int t = partner; t + 1 < 24; ++t) scenario.thrusters.thrusters[static_cast<std::size_t>(t)] = scenario.thrusters.thrusters[static_cast<std::size_t>(t) + 1];
  scenario.thrusters.count = 23;
  const Flight f = make_flight(scenario);
  const std::vector<int> opposite = opposite_torques(scenario.thrusters, kT5);
  const int onset = kFullRing + 50;
  const ObserverBankState s = fly(f, onset + 300, stuck_open_t5(onset, 23, opposite));
  ASSERT_TRUE(s.alarm);
  EXPECT_EQ(s.hypotheses, mask_of({kT5}));
  EXPECT_EQ(s.confirmed, kT5);
}

// A 40 N force change along x on a centre of mass 3 cm off along y: 1.2 N m about z the bank does
// not know. Under the bound delta_c = 3 cm it stays quiet (its excess is the noise's); with
// delta_c = 0 it alarms. (The force itself is not flown: the torque is what the rates see.)
TEST(ObserverBank, ForceChangeOnAnOffsetCentreOfMassStaysUnderTheBound) {
  const model::Scenario scenario = two_tank_chaser();
  const auto input = [](int k) {
    PeriodInput in;
    const double force_N = k >= kFullRing + 50 ? 40.0 : 0.0;
    in.wrench(0) = force_N;
    in.disturbance_Nm = Vec3(0.0, 0.03, 0.0).cross(Vec3(force_N, 0.0, 0.0));
    return in;
  };
  const ObserverBankState bounded = fly(make_flight(scenario, 0.03), kFullRing + 500, input);
  EXPECT_FALSE(bounded.alarm);
  const ObserverBankState unbounded = fly(make_flight(scenario, 0.0), kFullRing + 500, input);
  EXPECT_TRUE(unbounded.alarm);
}

// Fault-free, noise and random commands only: no alarm, and the statistic stays far below 1 N m.
TEST(ObserverBank, FaultFreeStaysQuiet) {
  const Flight f = make_flight(two_tank_chaser());
  const ObserverBankState s = fly(f, kFullRing + 3000, stuck_open_t5(1 << 30, 24));
  EXPECT_FALSE(s.alarm);
  EXPECT_LT(s.statistic_Nm, 0.1);
}

}  // namespace observer_bank_test
}  // namespace chaser::flight::fdi
