#include "flight/modulation.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/random.hpp"

namespace chaser::flight {
namespace {

// Binary-exact numbers (T = 0.125 s, threshold 0.25) so that "at threshold" is exact in floating point.
TmuParams exact_params() {
  TmuParams p;
  p.period_s = 0.125;
  p.threshold = Vec6::Constant(0.25);
  p.limit = Vec6::Constant(100.0);
  return p;
}

// Below threshold nothing is released; the period the accumulated impulse reaches the threshold
// (|a_j| >= a_th_j, here exactly equal) the whole accumulated impulse goes out as a / T.
TEST(Tmu, NoReleaseBelowThresholdAndReleaseAtThreshold) {
  const TmuParams p = exact_params();
  TmuState s;
  Vec6 demand = Vec6::Zero();
  demand(1) = -0.5;  // [N]: 0.0625 N s per period, threshold after exactly 4 periods
  demand(4) = 0.25;  // [N m]: rides along, below its own threshold
  for (int k = 0; k < 3; ++k) EXPECT_EQ(tmu_release(p, s, demand), Vec6::Zero()) << k;
  const Vec6 released = tmu_release(p, s, demand);
  EXPECT_EQ(released(1), -2.0);  // 0.25 N s / 0.125 s
  EXPECT_EQ(released(4), 1.0);   // the other axes' accumulated impulse is released with it
  tmu_account(p, s, released);
  EXPECT_EQ(s.accumulated, Vec6::Zero());
  EXPECT_EQ(tmu_release(p, s, demand), Vec6::Zero());  // starts over
}

// Impulse conservation (the delta-sigma property): after any sequence of demands and any realised
// fraction of each release (the allocator saturating), sum(realised T) + a = sum(demand T), to
// round-off: ~1e-16 relative per operation over 1e5 periods gives < 1e-10 of the total |impulse|.
TEST(Tmu, ImpulseIsConservedOverLongRandomSequence) {
  TmuParams p;
  p.period_s = 0.1;
  p.threshold << 0.1, 0.1, 0.1, 0.05, 0.05, 0.05;
  p.limit = Vec6::Constant(1e6);  // clamp out of the way: conservation holds while it is inactive
  TmuState s;
  RandomStream rng(3, "tests/tmu");
  Vec6 demanded = Vec6::Zero(), realised = Vec6::Zero(), scale = Vec6::Zero();
  int releases = 0;
  for (int k = 0; k < 100000; ++k) {
    Vec6 demand;
    for (int j = 0; j < 6; ++j) demand(j) = rng.normal(0.0, 0.3) + 0.05;
    const Vec6 released = tmu_release(p, s, demand);
    const Vec6 actual = released * rng.uniform(0.3, 1.0);
    releases += released != Vec6::Zero();
    tmu_account(p, s, actual);
    demanded += demand * p.period_s;
    realised += actual * p.period_s;
    scale += (demand * p.period_s).cwiseAbs();
  }
  EXPECT_GT(releases, 1000);
  EXPECT_LT(((realised + s.accumulated - demanded).cwiseQuotient(scale)).cwiseAbs().maxCoeff(), 1e-10);
}

// Anti-windup: when the allocator realises nothing (full saturation, or thrusters inhibited), the
// accumulator stops at +-limit instead of growing without bound, and after the demand reverses
// the debt is cleared within limit / |demand T| periods.
TEST(Tmu, AccumulatorIsClampedWhenNothingIsRealised) {
  TmuParams p = exact_params();
  p.limit = Vec6::Constant(1.0);
  TmuState s;
  const Vec6 demand = Vec6::Constant(8.0);  // 1 N s per period
  for (int k = 0; k < 50; ++k) tmu_release(p, s, demand);
  EXPECT_EQ(s.accumulated, Vec6::Constant(1.0));
  for (int k = 0; k < 3; ++k) tmu_release(p, s, -demand);
  EXPECT_EQ(s.accumulated, Vec6::Constant(-1.0));
}

// make_tmu_params: thresholds from the scenario, clamp = windup_periods * T * the larger one-sided
// per-axis authority of the sets the vehicle may fly (the starting set and each group), floored at
// twice the threshold. Sixteen 22 N thrusters at the origin along +x in two groups of eight (the
// second on standby): 176 N on +x and nothing else, except where one group-B thruster is turned.
TEST(Tmu, MakeFromScenario) {
  model::Scenario s;
  s.thrusters.count = 16;
  s.thrusters.groups = {{"A", false}, {"B", true}};
  for (int i = 0; i < 16; ++i) s.thrusters.thrusters[i].group = i / 8;
  s.control.tmu_force_threshold_Ns = 0.1;
  s.control.tmu_torque_threshold_Nms = 0.07;
  s.control.tmu_windup_periods = 3.0;
  // One branch-B thruster turned round and offset: r x F = (0, 2, 0) x (-22, 0, 0) = (0, 0, 44) N m.
  s.thrusters.thrusters[12].position_body_m = Vec3(0.0, 2.0, 0.0);
  s.thrusters.thrusters[12].direction_body = Vec3(-1.0, 0.0, 0.0);
  const TmuParams p = make_tmu_params(s);
  EXPECT_EQ(p.period_s, s.control_period_s);
  Vec6 threshold;
  threshold << 0.1, 0.1, 0.1, 0.07, 0.07, 0.07;
  EXPECT_EQ(p.threshold, threshold);
  Vec6 limit;
  limit << 3.0 * 0.1 * 176.0, 0.2, 0.2, 0.14, 0.14, 3.0 * 0.1 * 44.0;
  EXPECT_LT((p.limit - limit).norm(), 1e-12);
}

}  // namespace
}  // namespace chaser::flight
