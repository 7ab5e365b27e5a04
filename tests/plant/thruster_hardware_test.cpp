#include "plant/thruster_hardware.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/constants.hpp"
#include "model/thruster_geometry.hpp"

namespace chaser::plant {
namespace thruster_hardware_test {

constexpr TimeNs kPeriodNs = 100'000'000;  // 0.1 s, the MSR control period
constexpr TimeNs kMs = 1'000'000;
constexpr double kIsp = 220.0;  // [s]

// 16 thrusters with distinct, non-coplanar directions and positions so that every thruster's force
// and torque differ from the others'; two latch groups of eight (T1-T8, T9-T16) as on MSR.
constexpr int kCount = 16;

model::ThrusterSetParams test_set() {
  model::ThrusterSetParams set;
  set.count = kCount;
  set.groups = {{"A", false}, {"B", true}};
  for (int i = 0; i < kCount; ++i) {
    const double a = 0.7 * i + 0.3;
    set.thrusters[i].direction_body = Vec3(std::cos(a), std::sin(a), 0.3 * ((i % 3) - 1.0)).normalized();
    set.thrusters[i].position_body_m = Vec3(0.5 + 0.1 * i, -0.4 + 0.05 * i, ((i % 2) ? 0.8 : -0.8));
    set.thrusters[i].max_thrust_N = 20.0 + 0.25 * i;
    set.thrusters[i].group = i < 8 ? 0 : 1;
  }
  set.delay_max_s = 0.020;
  set.rise_time_s = 0.005;
  set.min_on_time_s = 0.005;
  set.min_off_time_s = 0.005;
  return set;
}

ThrusterHardware test_hardware(const model::ThrusterSetParams& set = test_set()) {
  RandomStream dispersion(1, "thrusters/dispersion");
  return make_thruster_hardware(set, Vec3(0.1, -0.05, 0.02), kIsp, kPeriodNs, dispersion);
}

struct Impulse {
  Vec3 force_Ns = Vec3::Zero();
  Vec3 torque_Nms = Vec3::Zero();
  double propellant_kg = 0.0;
};

void accumulate(const ThrustProfile& p, Impulse& sum) {
  for (int j = 0; j < p.count; ++j) {
    const double dt = to_seconds(p.pieces[j].t_end_ns - p.pieces[j].t_begin_ns);
    sum.force_Ns += p.pieces[j].force_body_N * dt;
    sum.torque_Nms += p.pieces[j].torque_body_Nm * dt;
  }
  sum.propellant_kg += p.propellant_kg;
}

// Pieces are contiguous, non-empty, start at t_k and end at t_k + T, and consecutive pieces differ.
void expect_tiles(const ThrustProfile& p, TimeNs t_k) {
  ASSERT_GE(p.count, 1);
  EXPECT_EQ(p.pieces[0].t_begin_ns, t_k);
  EXPECT_EQ(p.pieces[p.count - 1].t_end_ns, t_k + kPeriodNs);
  for (int j = 0; j < p.count; ++j) {
    EXPECT_LT(p.pieces[j].t_begin_ns, p.pieces[j].t_end_ns);
    if (j > 0) {
      EXPECT_EQ(p.pieces[j].t_begin_ns, p.pieces[j - 1].t_end_ns);
      EXPECT_NE(p.pieces[j].force_body_N, p.pieces[j - 1].force_body_N);
    }
  }
}

model::ThrusterCommand single(int thruster, double ton) {
  model::ThrusterCommand c;
  c.ton[thruster] = ton;
  return c;
}

// One pulse: the valve opens exactly at t_k + tau + rise/2 and closes exactly ton T later, in integer
// nanoseconds; the piece in between carries that thruster's force, torque and mass flow.
TEST(ThrusterHardware, PulseEdgesAreExact) {
  const ThrusterHardware hw = test_hardware();
  ThrusterState state;
  ThrustProfile p;
  const TimeNs t_k = 37 * kPeriodNs, delay = 7'000'123;
  schedule_period(hw, {}, state, single(5, 0.3), t_k, delay, p);
  expect_tiles(p, t_k);
  ASSERT_EQ(p.count, 3);
  EXPECT_EQ(p.pieces[1].t_begin_ns, t_k + delay + 2'500'000);
  EXPECT_EQ(p.pieces[1].t_end_ns, t_k + delay + 2'500'000 + 30'000'000);
  EXPECT_EQ(p.pieces[0].force_body_N, Vec3::Zero());
  EXPECT_EQ(p.pieces[1].force_body_N, hw.force_body_N[5]);
  EXPECT_EQ(p.pieces[1].torque_body_Nm, hw.torque_body_Nm[5]);
  EXPECT_DOUBLE_EQ(p.pieces[1].mass_flow_kgps, hw.force_body_N[5].norm() / (kIsp * kStandardGravity));
  EXPECT_EQ(p.pieces[2].force_body_N, Vec3::Zero());
  EXPECT_DOUBLE_EQ(p.ton_realised[5], 0.3);
}

// Fonod 2015, eq. 2 with a delay: the delay shifts each pulse but does not change its impulse. Over
// 1000 periods of random commands (multiples of 1e-6, so ton T is an exact number of ns) and random
// delays, the force, torque and propellant integrated over all pieces (plus one more period for the
// last spill) equal sum_k sum_i ton_i T (F_i, C_i, mdot_i). Each command is at most
// 1 + (tau(k+1) - tau(k) - min_off) / T: its pulse may spill into the next period but ends min_off
// (1 ms here) before the next opening, so nothing merges and the equality is to round-off only.
TEST(ThrusterHardware, ImpulseConservedThroughDelayAndSpill) {
  model::ThrusterSetParams set = test_set();
  set.min_off_time_s = 0.001;
  const ThrusterHardware hw = test_hardware(set);
  ThrusterState state;
  ThrustProfile p;
  RandomStream rng(3, "test"), delays(3, "thrusters/delay");
  const int periods = 1000;
  std::vector<TimeNs> delay(periods + 2);
  for (TimeNs& d : delay) d = static_cast<TimeNs>(delays.uniform(0.0, set.delay_max_s) * 1e9);
  Impulse sum, expected;
  int spills = 0;
  for (int k = 0; k <= periods; ++k) {
    model::ThrusterCommand c;
    const double ton_max = std::min(1.0, double(kPeriodNs + delay[k + 1] - delay[k] - hw.min_off_ns) / kPeriodNs);
    for (int i = 0; i < kCount && k < periods; ++i) {
      const double u = rng.uniform();
      c.ton[i] = u < 0.2 ? 0.0 : std::floor(rng.uniform(0.05, ton_max) * 1e6) / 1e6;
      const double impulse_s = c.ton[i] * to_seconds(kPeriodNs);
      expected.force_Ns += impulse_s * hw.force_body_N[i];
      expected.torque_Nms += impulse_s * hw.torque_body_Nm[i];
      expected.propellant_kg += impulse_s * hw.mass_flow_kgps[i];
    }
    schedule_period(hw, {}, state, c, k * kPeriodNs, delay[k], p);
    expect_tiles(p, k * kPeriodNs);
    for (int i = 0; i < kCount; ++i) ASSERT_NEAR(p.ton_realised[i], c.ton[i], 1e-15);
    spills += p.pieces[0].force_body_N != Vec3::Zero();
    accumulate(p, sum);
  }
  EXPECT_GT(spills, 100);  // the spill path was exercised
  // Relative round-off of ~1e5 additions of doubles: 1e-12 of the total is ample and still far below
  // one nanosecond of one thruster (2e-8 N s against ~1e3 N s totals).
  EXPECT_LT((sum.force_Ns - expected.force_Ns).norm(), 1e-12 * expected.force_Ns.norm() + 1e-9);
  EXPECT_LT((sum.torque_Nms - expected.torque_Nms).norm(), 1e-12 * expected.torque_Nms.norm() + 1e-9);
  EXPECT_NEAR(sum.propellant_kg, expected.propellant_kg, 1e-12 * expected.propellant_kg);
}

// A command shorter than the minimum on-time does not open the valve; one exactly at it does.
TEST(ThrusterHardware, MinimumOnTime) {
  const ThrusterHardware hw = test_hardware();
  ThrusterState state;
  ThrustProfile p;
  schedule_period(hw, {}, state, single(2, 0.04999), 0, 0, p);
  EXPECT_EQ(p.count, 1);
  EXPECT_EQ(p.pieces[0].force_body_N, Vec3::Zero());
  EXPECT_EQ(p.ton_realised[2], 0.0);
  EXPECT_EQ(p.propellant_kg, 0.0);
  schedule_period(hw, {}, state, single(2, 0.05), kPeriodNs, 0, p);
  EXPECT_EQ(p.count, 3);
  EXPECT_EQ(p.pieces[1].t_end_ns - p.pieces[1].t_begin_ns, 5 * kMs);
}

// A gap shorter than min_off between a spilling pulse and the next opening is bridged: the valve
// stays open from t_k to the end of the second pulse. A gap of exactly min_off is kept.
TEST(ThrusterHardware, MinimumOffTimeBridgesShortGap) {
  const ThrusterHardware hw = test_hardware();
  for (const TimeNs gap : {5 * kMs - 1, 5 * kMs}) {
    ThrusterState state;
    ThrustProfile p;
    // Period 0: [19 + 2.5, 19 + 2.5 + 79.5) ms = [21.5, 101) ms, spilling 1 ms into period 1.
    schedule_period(hw, {}, state, single(4, 0.795), 0, 19 * kMs, p);
    // Period 1 opens at t1 + delay + 2.5 ms = t1 + 1 ms + gap.
    const TimeNs delay = gap - 1'500'000;
    schedule_period(hw, {}, state, single(4, 0.2), kPeriodNs, delay, p);
    expect_tiles(p, kPeriodNs);
    if (gap < hw.min_off_ns) {
      ASSERT_EQ(p.count, 2);
      EXPECT_EQ(p.pieces[0].t_end_ns, kPeriodNs + kMs + gap + 20 * kMs);
      // The pulse commanded in period 1 adds its own 20 ms plus the gap it filled.
      EXPECT_NEAR(p.ton_realised[4], double(20 * kMs + gap) / double(kPeriodNs), 1e-15);
    } else {
      ASSERT_EQ(p.count, 4);
      EXPECT_EQ(p.pieces[0].t_end_ns, kPeriodNs + kMs);
      EXPECT_EQ(p.pieces[1].t_end_ns - p.pieces[1].t_begin_ns, gap);
      EXPECT_NEAR(p.ton_realised[4], 0.2, 1e-15);
    }
  }
}

// When the previous pulse already closed before t_k and the next opening would come sooner than
// min_off after it, the valve cannot reopen before close + min_off: the opening is postponed, its
// length kept.
TEST(ThrusterHardware, MinimumOffTimeAfterPastClosingPostponesOpening) {
  const ThrusterHardware hw = test_hardware();
  ThrusterState state;
  ThrustProfile p;
  schedule_period(hw, {}, state, single(9, 0.965), 0, 0, p);  // [2.5, 99) ms: closes at t1 - 1 ms
  schedule_period(hw, {}, state, single(9, 0.3), kPeriodNs, 0, p);  // would open at t1 + 2.5 ms
  ASSERT_EQ(p.count, 3);
  EXPECT_EQ(p.pieces[1].t_begin_ns, kPeriodNs + 4 * kMs);
  EXPECT_EQ(p.pieces[1].t_end_ns, kPeriodNs + 34 * kMs);
  EXPECT_NEAR(p.ton_realised[9], 0.3, 1e-15);
}

// Overlapping pulses of one thruster open the valve over the union of their intervals; the second
// pulse is credited only with the open time it adds.
TEST(ThrusterHardware, OverlappingPulsesGiveUnion) {
  const ThrusterHardware hw = test_hardware();
  ThrusterState state;
  ThrustProfile p;
  schedule_period(hw, {}, state, single(0, 1.0), 0, 19 * kMs, p);  // [21.5 ms, 121.5 ms)
  schedule_period(hw, {}, state, single(0, 0.5), kPeriodNs, 0, p);  // [102.5 ms, 152.5 ms)
  ASSERT_EQ(p.count, 2);
  EXPECT_EQ(p.pieces[0].t_end_ns, kPeriodNs + 52'500'000);
  EXPECT_NEAR(p.ton_realised[0], 0.31, 1e-15);
  schedule_period(hw, {}, state, model::ThrusterCommand{}, 2 * kPeriodNs, 0, p);
  EXPECT_EQ(p.count, 1);
  EXPECT_EQ(p.pieces[0].force_body_N, Vec3::Zero());
}

// A closed latch cuts its whole group (even a stuck-open thruster); the other group is untouched,
// and reopening the latch restores the flow.
TEST(ThrusterHardware, LatchValveCutsBranchIncludingStuckOpen) {
  const ThrusterHardware hw = test_hardware();
  model::FaultParams stuck;
  stuck.kind = model::FaultKind::kStuckOpen;
  stuck.thruster = 3;
  stuck.onset_s = 0.0;
  const std::vector<model::FaultParams> faults{stuck};
  model::ThrusterCommand all;
  all.ton.fill(0.5);
  ThrusterState state;
  state.latch_closed_groups = 0b01;  // group A closed
  ThrustProfile p;
  schedule_period(hw, faults, state, all, 0, 0, p);
  Impulse sum;
  accumulate(p, sum);
  Vec3 branch_b = Vec3::Zero();
  for (int i = 8; i < 16; ++i) branch_b += 0.5 * to_seconds(kPeriodNs) * hw.force_body_N[i];
  EXPECT_LT((sum.force_Ns - branch_b).norm(), 1e-12);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(p.ton_realised[i], 0.0);
  for (int i = 8; i < 16; ++i) EXPECT_EQ(p.ton_realised[i], 0.5);

  state.latch_closed_groups = 0b10;  // A open, B closed
  schedule_period(hw, faults, state, model::ThrusterCommand{}, kPeriodNs, 0, p);
  ASSERT_EQ(p.count, 1);  // only the stuck-open thruster flows, the whole period
  EXPECT_EQ(p.pieces[0].force_body_N, hw.force_body_N[3]);
  EXPECT_EQ(p.ton_realised[3], 1.0);
}

// Zero sigmas draw nothing and give exactly the nominal forces and torques of eq. 2's M.
TEST(ThrusterDispersion, ZeroSigmaIsNominalExactly) {
  const model::ThrusterSetParams set = test_set();
  const Vec3 com(0.1, -0.05, 0.02);
  const ThrusterHardware hw = test_hardware(set);
  for (int i = 0; i < kCount; ++i) {
    const Vec6 w = model::thruster_wrench(set.thrusters[i], com);
    EXPECT_EQ(hw.force_body_N[i], Vec3(w.head<3>()));
    EXPECT_EQ(hw.torque_body_Nm[i], Vec3(w.tail<3>()));
  }
}

// Over 1000 runs x 16 thrusters = 16000 draws: the thrust scale has mean 1 and the standard deviation
// of a normal truncated at 3 sigma, 0.98658 sigma; none exceeds 3 sigma. The misalignment angle
// squared has mean 2 (0.98658 sigma)^2 (two truncated axes), and none exceeds 3 sqrt(2) sigma.
// Tolerances are 5 standard errors. The torque stays (p - com) x F for the dispersed force.
TEST(ThrusterDispersion, SampleStatisticsMatchSigmaAndTruncation) {
  model::ThrusterSetParams set = test_set();
  set.thrust_sigma = 0.01;
  set.misalignment_sigma_rad = 0.002;
  const Vec3 com(0.1, -0.05, 0.02);
  const double sigma_t = 0.98658;  // std of N(0,1) truncated at +-3
  double sum = 0, sum2 = 0, max_dev = 0, sum_angle2 = 0, max_angle = 0;
  const int runs = 1000, n = runs * kCount;
  for (int run = 0; run < runs; ++run) {
    RandomStream dispersion(run_seed(11, run), "thrusters/dispersion");
    const ThrusterHardware hw = make_thruster_hardware(set, com, kIsp, kPeriodNs, dispersion);
    for (int i = 0; i < kCount; ++i) {
      const model::ThrusterParams& t = set.thrusters[i];
      const double scale = hw.force_body_N[i].norm() / t.max_thrust_N;
      sum += scale, sum2 += (scale - 1) * (scale - 1);
      max_dev = std::max(max_dev, std::abs(scale - 1));
      const Vec3 f = hw.force_body_N[i].normalized();
      const double angle = std::atan2(f.cross(t.direction_body).norm(), f.dot(t.direction_body));
      sum_angle2 += angle * angle;
      max_angle = std::max(max_angle, angle);
      ASSERT_LT((hw.torque_body_Nm[i] - (t.position_body_m - com).cross(hw.force_body_N[i])).norm(), 1e-12);
    }
  }
  const double s = set.thrust_sigma * sigma_t, m = set.misalignment_sigma_rad * sigma_t;
  EXPECT_NEAR(sum / n, 1.0, 5 * s / std::sqrt(n));
  EXPECT_NEAR(std::sqrt(sum2 / n), s, 5 * s / std::sqrt(2.0 * n));
  EXPECT_LE(max_dev, 3 * set.thrust_sigma + 1e-15);
  EXPECT_GT(max_dev, 2.5 * set.thrust_sigma);  // the tails are populated, up to the truncation
  // angle^2 / m^2 is close to chi-square with 2 dof: mean 2, std 2.
  EXPECT_NEAR(sum_angle2 / n, 2 * m * m, 5 * 2 * m * m / std::sqrt(n));
  EXPECT_LE(max_angle, 3 * std::sqrt(2.0) * set.misalignment_sigma_rad * (1 + 1e-6));
}

}  // namespace thruster_hardware_test
}  // namespace chaser::plant
