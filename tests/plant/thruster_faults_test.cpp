#include "plant/thruster_faults.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "plant/thruster_hardware.hpp"

namespace chaser::plant {
namespace thruster_faults_test {

constexpr TimeNs kPeriodNs = 100'000'000;  // 0.1 s
constexpr double kT = 0.1;                 // [s]
constexpr int kFaulty = 6;
constexpr int kCount = 16;                 // thrusters in the test sets
constexpr int kOnsetPeriod = 10;           // t_f = 1.0 s

model::FaultParams fault_of(model::FaultKind kind) {
  model::FaultParams f;
  f.kind = kind;
  f.thruster = kFaulty;
  f.onset_s = kOnsetPeriod * kT;
  f.leak_size = 0.2;
  f.leak_slope_per_s = 0.1;
  f.loss_size = 0.6;
  return f;
}

// m_leak(t) = min(m_s (t - t_f), \hat m_leak): zero before and at onset, a ramp of slope m_s, then
// the saturation at the leak size (Fonod 2015, section II.D, case 3).
TEST(ThrusterFaults, LeakRampAndSaturation) {
  const model::FaultParams f = fault_of(model::FaultKind::kLeak);
  EXPECT_EQ(leak_size(f, 9 * kPeriodNs), 0.0);
  EXPECT_EQ(leak_size(f, 10 * kPeriodNs), 0.0);
  EXPECT_NEAR(leak_size(f, 15 * kPeriodNs), 0.05, 1e-15);
  EXPECT_NEAR(leak_size(f, 29 * kPeriodNs), 0.19, 1e-15);
  EXPECT_EQ(leak_size(f, 30 * kPeriodNs), 0.2);
  EXPECT_EQ(leak_size(f, 500 * kPeriodNs), 0.2);
  EXPECT_EQ(leak_size(fault_of(model::FaultKind::kLoss), 500 * kPeriodNs), 0.0);
}

// Eq. 5 for the four cases and a healthy thruster.
TEST(ThrusterFaults, RealisedOnTimeFollowsEq5) {
  ThrusterFaultEffect healthy, stuck, blocked, leak, loss;
  stuck.stuck_open = true;
  blocked.blocked = true;
  leak.ton_floor = 0.15;
  loss.thrust_scale = 0.4;
  for (const double ton : {0.0, 0.1, 0.5, 1.0}) {
    EXPECT_EQ(realised_on_time(healthy, ton), ton);
    EXPECT_EQ(realised_on_time(stuck, ton), 1.0);
    EXPECT_EQ(realised_on_time(blocked, ton), 0.0);
    EXPECT_EQ(realised_on_time(leak, ton), std::max(ton, 0.15));
    EXPECT_EQ(realised_on_time(loss, ton), 0.4 * ton);
  }
}

// An onset between period starts takes effect at the next period start; faults on other thrusters
// leave a thruster healthy.
TEST(ThrusterFaults, ActivationAtFirstPeriodStartAfterOnset) {
  model::FaultParams f = fault_of(model::FaultKind::kStuckOpen);
  f.onset_s = 1.05;
  const std::vector<model::FaultParams> faults{f};
  EXPECT_FALSE(evaluate_faults(faults, 10 * kPeriodNs)[kFaulty].stuck_open);
  EXPECT_TRUE(evaluate_faults(faults, 11 * kPeriodNs)[kFaulty].stuck_open);
  for (int i = 0; i < kCount; ++i) {
    if (i != kFaulty) {
      EXPECT_FALSE(evaluate_faults(faults, 11 * kPeriodNs)[i].stuck_open);
    }
  }
}

// Expected eq. 5 on-time of the faulty thruster in period k, written from the paper independently of
// the implementation; min_on = 5 ms makes commands below 0.05 zero before the fault applies.
double expected_phi(model::FaultKind kind, int k, double ton) {
  const double ton_eff = ton < 0.05 ? 0.0 : ton;
  if (k < kOnsetPeriod) return ton_eff;
  switch (kind) {
    case model::FaultKind::kStuckOpen: return 1.0;
    case model::FaultKind::kStuckClosed: return 0.0;
    case model::FaultKind::kLeak: return std::max(ton_eff, std::min(0.1 * (k - kOnsetPeriod) * kT, 0.2));
    case model::FaultKind::kLoss: return 0.4 * ton_eff;
  }
  return -1.0;
}

// Scripted sequences, 50 periods, fault onset at period 10. All 16 thrusters fire every period with
// a fixed 10 ms delay and on-times <= 0.6, so no pulse spills and each period's impulse belongs to
// its own commands. Per period, the integrated force and torque equal sum_i phi_i T (F_i, C_i) with
// phi_i = ton_i for the healthy thrusters (unaffected) and eq. 5 for the faulty one (inactive before
// onset). Tolerance: pulse lengths are rounded to whole ns, 1e-9 s x 25 N per thruster at most.
class FaultSequence : public ::testing::TestWithParam<model::FaultKind> {};

TEST_P(FaultSequence, PerPeriodImpulseFollowsEq5) {
  const model::FaultKind kind = GetParam();
  model::ThrusterSetParams set;
  set.count = kCount;
  for (int i = 0; i < kCount; ++i) {
    const double a = 0.9 * i;
    set.thrusters[i].direction_body = Vec3(std::cos(a), std::sin(a), 0.2 * (i % 3 - 1.0)).normalized();
    set.thrusters[i].position_body_m = Vec3(0.3 * (i % 4), -0.2 * (i % 5), 0.5);
  }
  RandomStream dispersion(1, "thrusters/dispersion");
  const ThrusterHardware hw = make_thruster_hardware(set, Vec3::Zero(), 220.0, kPeriodNs, dispersion);
  const std::vector<model::FaultParams> faults{fault_of(kind)};
  const double script[] = {0.0, 0.03, 0.05, 0.12, 0.3, 0.6, 0.17, 0.0, 0.25};
  ThrusterState state;
  ThrustProfile p;
  for (int k = 0; k < 50; ++k) {
    model::ThrusterCommand c;
    for (int i = 0; i < kCount; ++i) c.ton[i] = script[(k + i) % 9];
    schedule_period(hw, faults, state, c, k * kPeriodNs, 10'000'000, p);
    Vec3 force = Vec3::Zero(), torque = Vec3::Zero(), force_expected = Vec3::Zero(), torque_expected = Vec3::Zero();
    for (int j = 0; j < p.count; ++j) {
      const double dt = to_seconds(p.pieces[j].t_end_ns - p.pieces[j].t_begin_ns);
      force += p.pieces[j].force_body_N * dt;
      torque += p.pieces[j].torque_body_Nm * dt;
    }
    for (int i = 0; i < kCount; ++i) {
      const double phi = i == kFaulty ? expected_phi(kind, k, c.ton[i]) : (c.ton[i] < 0.05 ? 0.0 : c.ton[i]);
      EXPECT_NEAR(p.ton_realised[i], phi, 1e-8) << "period " << k << " thruster " << i;
      force_expected += phi * kT * hw.force_body_N[i];
      torque_expected += phi * kT * hw.torque_body_Nm[i];
    }
    EXPECT_LT((force - force_expected).norm(), 16 * 25e-9) << "period " << k;
    EXPECT_LT((torque - torque_expected).norm(), 16 * 25e-9) << "period " << k;
  }
}

INSTANTIATE_TEST_SUITE_P(AllCases, FaultSequence,
                         ::testing::Values(model::FaultKind::kStuckOpen, model::FaultKind::kStuckClosed,
                                           model::FaultKind::kLeak, model::FaultKind::kLoss),
                         [](const auto& info) { return std::string(model::to_string(info.param)); });

// Case 4 is a reduced thrust level during the pulse, not a shorter pulse: the piece where only the
// faulty thruster fires carries (1 - m_loss) F at the commanded edges, and mass flow scales alike.
TEST(ThrusterFaults, LossIsReducedThrustLevel) {
  model::ThrusterSetParams set;
  set.count = kCount;
  RandomStream dispersion(1, "thrusters/dispersion");
  const ThrusterHardware hw = make_thruster_hardware(set, Vec3::Zero(), 220.0, kPeriodNs, dispersion);
  const std::vector<model::FaultParams> faults{fault_of(model::FaultKind::kLoss)};
  ThrusterState state;
  ThrustProfile p;
  model::ThrusterCommand c;
  c.ton[kFaulty] = 0.5;
  schedule_period(hw, faults, state, c, 20 * kPeriodNs, 0, p);
  ASSERT_EQ(p.count, 3);
  EXPECT_EQ(p.pieces[1].t_end_ns - p.pieces[1].t_begin_ns, 50'000'000);
  EXPECT_LT((p.pieces[1].force_body_N - 0.4 * hw.force_body_N[kFaulty]).norm(), 1e-14);
  EXPECT_NEAR(p.pieces[1].mass_flow_kgps, 0.4 * hw.mass_flow_kgps[kFaulty], 1e-18);
}

// Case 1 is continuous across periods: the valve is open over every whole period from onset on,
// independent of commands and delays (one piece per period), and a pulse that was still open when a
// blocked-closed fault (case 2) starts is cut at that period start.
TEST(ThrusterFaults, StuckOpenContinuousAndBlockedCutsOpenPulse) {
  model::ThrusterSetParams set;
  set.count = kCount;
  RandomStream dispersion(1, "thrusters/dispersion");
  const ThrusterHardware hw = make_thruster_hardware(set, Vec3::Zero(), 220.0, kPeriodNs, dispersion);
  ThrusterState state;
  ThrustProfile p;
  const std::vector<model::FaultParams> stuck{fault_of(model::FaultKind::kStuckOpen)};
  for (int k = kOnsetPeriod; k < kOnsetPeriod + 5; ++k) {
    schedule_period(hw, stuck, state, model::ThrusterCommand{}, k * kPeriodNs, 1'000'000 * k, p);
    ASSERT_EQ(p.count, 1);
    EXPECT_EQ(p.pieces[0].force_body_N, hw.force_body_N[kFaulty]);
  }
  ThrusterState state2;
  const std::vector<model::FaultParams> blocked{fault_of(model::FaultKind::kStuckClosed)};
  model::ThrusterCommand c;
  c.ton[kFaulty] = 1.0;
  schedule_period(hw, blocked, state2, c, (kOnsetPeriod - 1) * kPeriodNs, 15'000'000, p);  // spills 17.5 ms
  schedule_period(hw, blocked, state2, c, kOnsetPeriod * kPeriodNs, 0, p);
  ASSERT_EQ(p.count, 1);
  EXPECT_EQ(p.pieces[0].force_body_N, Vec3::Zero());
}

}  // namespace thruster_faults_test
}  // namespace chaser::plant
