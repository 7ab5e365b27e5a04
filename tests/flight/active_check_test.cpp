// The bookkeeping of active checks (flight/active_check.hpp): which thruster is checked, when, and
// never one outside the active mask or inside the keep-quiet zone.
#include "flight/active_check.hpp"

#include <gtest/gtest.h>

namespace chaser::flight {
namespace {

constexpr model::ThrusterMask kBranchA = 0x00FFU;  // T1..T8
constexpr model::ThrusterMask kBranchB = 0xFF00U;  // T9..T16
constexpr double kFar_m = 10.0;                    // outside the keep-quiet zone

ActiveCheckParams params() {
  return ActiveCheckParams{.enabled = true, .max_unverified_s = 10.0, .pulse_fraction = 0.075,
                           .informative_fraction = 0.05, .keep_quiet_range_m = 2.0};
}

// One period's command firing `fired` (thruster indices) at on-time `ton`.
model::ThrusterOnTimes command(std::initializer_list<int> fired, double ton = 0.05) {
  model::ThrusterOnTimes c{};
  for (const int i : fired) c[static_cast<std::size_t>(i)] = ton;
  return c;
}

int step(const ActiveCheckParams& p, ActiveCheckState& s, double t_s, const model::ThrusterOnTimes& ton,
         model::ThrusterMask active = kBranchA, double range_m = kFar_m) {
  return step_active_check(p, s, {.t_s = t_s, .range_m = range_m, .active = active}, ton);
}

// T4 and T6 (indices 3, 5) dormant as on MSR's approach: the stalest past the bound is checked first;
// a pulse shorter than pulse_s proves nothing; once checked a thruster's clock restarts, so the
// stale ones take turns, stalest first and the lowest index among equals.
TEST(ActiveCheck, ChecksTheStalestThrusterPastTheBoundInTurn) {
  const ActiveCheckParams p = params();
  ActiveCheckState s;
  EXPECT_EQ(step(p, s, 0.0, command({})), model::kNoThruster);  // all join the set at 0
  EXPECT_EQ(step(p, s, 5.0, command({0, 1, 2, 4, 6, 7})), model::kNoThruster);
  EXPECT_EQ(step(p, s, 5.1, command({5}, 0.049)), model::kNoThruster);  // below pulse_s: not informative
  EXPECT_EQ(step(p, s, 8.0, command({3})), model::kNoThruster);
  EXPECT_EQ(step(p, s, 9.9, command({})), model::kNoThruster);
  EXPECT_EQ(step(p, s, 10.0, command({})), 5);  // T6: 10 s without an informative pulse
  EXPECT_EQ(s.next, 5);
  EXPECT_EQ(step(p, s, 10.1, command({5})), model::kNoThruster);  // its check fired: verified
  EXPECT_EQ(step(p, s, 15.0, command({})), 0);  // T1, T2, T3, T5, T7, T8 all 10 s stale: T1 first
  EXPECT_EQ(step(p, s, 15.1, command({0})), 1);
  EXPECT_EQ(step(p, s, 15.2, command({1})), 2);
  EXPECT_EQ(step(p, s, 18.0, command({2, 4, 6, 7})), 3);  // T4, verified at 8, now 10 s stale
  EXPECT_EQ(step(p, s, 18.1, command({3}, 0.3)), model::kNoThruster);
}

// A thruster outside the active mask is never checked, however stale: not one the mask leaves out,
// not the faulty branch after a recovery; the new branch is unverified from the time it joins.
TEST(ActiveCheck, NeverChecksAThrusterOutsideTheMask) {
  const ActiveCheckParams p = params();
  ActiveCheckState s;
  const model::ThrusterMask without_t6 = kBranchA & ~model::thruster_bit(5);
  for (int k = 0; k <= 300; ++k) {
    const double t_s = 0.1 * k;
    const int checked = step(p, s, t_s, command(k < 10 ? std::initializer_list<int>{5} : std::initializer_list<int>{}),
                             without_t6);
    if (checked != model::kNoThruster) {
      EXPECT_TRUE(model::has_thruster(without_t6, checked)) << t_s;
    }
    if (t_s >= 10.0) {
      EXPECT_NE(checked, model::kNoThruster) << t_s;  // the others are stale by then
    }
  }
  // A recovery to branch B at 30 s: B joins then, A is never checked again.
  for (int k = 301; k <= 500; ++k) {
    const double t_s = 0.1 * k;
    const int checked = step(p, s, t_s, command({}), kBranchB);
    if (checked != model::kNoThruster) {
      EXPECT_TRUE(model::has_thruster(kBranchB, checked)) << t_s;
      EXPECT_GE(t_s, 30.1 + p.max_unverified_s - 1e-9) << t_s;
    }
  }
  EXPECT_EQ(s.next, 8);  // T9 first among B's eight, all stale since 30.1 s
}

// Inside the keep-quiet zone nothing is checked, however stale; at its edge checks resume.
TEST(ActiveCheck, NoCheckInTheKeepQuietZone) {
  const ActiveCheckParams p = params();
  ActiveCheckState s;
  step(p, s, 0.0, command({}));
  EXPECT_EQ(step(p, s, 50.0, command({}), kBranchA, 1.999), model::kNoThruster);
  EXPECT_EQ(s.next, model::kNoThruster);
  EXPECT_EQ(step(p, s, 50.1, command({}), kBranchA, 0.0), model::kNoThruster);
  EXPECT_EQ(step(p, s, 50.2, command({}), kBranchA, 2.0), 0);
}

// With arm_range_m, checks wait for the last approach: none farther than it (the stale thruster
// stays stale, its clock running), the stalest at once on entering the window, none in the
// keep-quiet zone inside it; and arm_range_m must lie beyond the keep-quiet range.
TEST(ActiveCheck, ArmedOnlyWithinTheArmRange) {
  ActiveCheckParams p = params();
  p.arm_range_m = 3.0;
  ActiveCheckState s;
  step(p, s, 0.0, command({}));
  EXPECT_EQ(step(p, s, 50.0, command({}), kBranchA, 3.001), model::kNoThruster);
  EXPECT_EQ(step(p, s, 50.1, command({}), kBranchA, 3.0), 0);
  EXPECT_EQ(step(p, s, 50.2, command({0}), kBranchA, 2.5), 1);  // T1 fired its check: T2 next
  EXPECT_EQ(step(p, s, 50.3, command({}), kBranchA, 1.9), model::kNoThruster);
  p.arm_range_m = p.keep_quiet_range_m;
  EXPECT_EQ(validate(p).size(), 1U);
}

// A suspect of the FDI (a material deficit short of the alarm) is unverified whatever it fired and
// stalest of all: checked in the next period the window allows, before older stale thrusters; it
// stays due until a pulse after the suspicion ends it.
TEST(ActiveCheck, ASuspectIsCheckedAgainAtOnce) {
  ActiveCheckParams p = params();
  p.arm_range_m = 3.0;
  ActiveCheckState s;
  step(p, s, 0.0, command({}));
  EXPECT_EQ(step(p, s, 5.0, command({0, 1, 2, 3, 4, 5, 6, 7})), model::kNoThruster);  // all verified at 5 s
  const auto suspect = [&](double t_s, int who, const model::ThrusterOnTimes& ton, double range_m = 2.5) {
    return step_active_check(p, s, {.t_s = t_s, .range_m = range_m, .active = kBranchA, .suspect = who}, ton);
  };
  EXPECT_EQ(suspect(6.0, 3, command({3})), 3);  // fired this period, suspected: checked next
  EXPECT_EQ(suspect(6.1, model::kNoThruster, command({3})), model::kNoThruster);  // its check fired
  EXPECT_EQ(suspect(6.2, 5, command({}), 3.5), model::kNoThruster);  // outside the window: waits
  EXPECT_EQ(suspect(6.3, model::kNoThruster, command({})), 5);       // due on entering it
  EXPECT_EQ(suspect(6.4, model::kNoThruster, command({})), 5);       // until it fires
  EXPECT_EQ(suspect(6.5, model::kNoThruster, command({5})), model::kNoThruster);
  EXPECT_EQ(suspect(16.0, 4, command({})), 4);  // before T1, stale since 5 s
  EXPECT_EQ(suspect(16.1, 12, command({4})), 0);  // T5 fired; a suspect outside the mask changes nothing
}

// Once the FDI has found its fault (or while it is disarmed after a recovery) no check is fired:
// nothing it shows would be read. The clocks keep running.
TEST(ActiveCheck, NoCheckOnceTheFdiHasFoundItsFault) {
  const ActiveCheckParams p = params();
  ActiveCheckState s;
  step(p, s, 0.0, command({}));
  EXPECT_EQ(step_active_check(p, s, {.t_s = 20.0, .range_m = kFar_m, .active = kBranchA, .fdi_listening = false},
                              command({1})),
            model::kNoThruster);
  EXPECT_EQ(step(p, s, 20.1, command({})), 0);
  EXPECT_EQ(step(p, s, 20.2, command({0})), 2);  // T2 was verified at 20 s
}

// Disabled, nothing is ever chosen.
TEST(ActiveCheck, DisabledChecksNothing) {
  ActiveCheckParams p = params();
  p.enabled = false;
  ActiveCheckState s;
  for (int k = 0; k <= 1000; ++k) EXPECT_EQ(step(p, s, 0.1 * k, command({})), model::kNoThruster);
}

TEST(ActiveCheck, ValidateNamesEveryBadParameter) {
  EXPECT_TRUE(validate(params()).empty());
  const ActiveCheckParams bad{
      .enabled = true, .max_unverified_s = 0, .pulse_fraction = 1.5, .informative_fraction = 0, .keep_quiet_range_m = -1};
  EXPECT_EQ(validate(bad).size(), 4U);
  ActiveCheckParams uninformative = params();
  uninformative.informative_fraction = 0.08;  // a check's pulse would not verify the thruster it checks
  EXPECT_EQ(validate(uninformative).size(), 1U);
}

}  // namespace
}  // namespace chaser::flight
