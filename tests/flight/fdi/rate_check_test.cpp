// The active checks read from the body rates (flight/fdi/rate_check.hpp) on rates made here by the
// step the reading assumes: a body of COMRADE's inertia whose rate changes each period by
// T I^-1 (tau - omega x I omega). A check whose thruster gives 1 - m of its pulse then reads m to
// rounding whatever the commanded torques around it; a slowly
// varying torque the model leaves out (the slosh's, as a 60 s sine of 1 N m, five times the pulse's
// 0.2 N m s per period) moves a reading by at most its curvature over the 2n + 1 periods, 1e-3 of
// the pulse; another thruster's pulse among the neighbours does not move the median. The decision:
// a dead thruster is confirmed stuck closed after three readings in a row, each asking for a recheck;
// a 50 % loss as a loss of 0.5; a healthy reading lets the suspicion go; a dead thruster fired in
// another thruster's check is checked itself and confirmed, never the checked one; a thruster of the
// same torque is a rival checked first; a healthy flight with the gyro's noise never alarms.
#include "flight/fdi/rate_check.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <utility>
#include <vector>

#include "tests/support/two_tank_chaser.hpp"

namespace chaser::flight::fdi {
namespace rate_check_test {

constexpr double kT = 0.1;  // [s]

RateCheckParams params() {
  const model::Scenario s = chaser::testing::two_tank_chaser();
  return make_rate_check_params(model::RateCheckParams{}, s.thrusters, Vec3::Zero(), s.chaser.inertia_kgm2, kT, 0.0);
}

// A body at rest flown period by period: each period's commanded torque, the check it carries and
// the share of that check's pulse that does not come, and a torque the model does not know.
struct Body {
  explicit Body(const RateCheckParams& params) : p(params) {}
  const RateCheckParams& p;
  RateCheckState state;
  Vec3 omega = Vec3::Zero();
  double t = 0;
  std::mt19937_64 rng{7};
  double gyro_sigma = 0;  // [rad/s]
  std::function<Vec3(double)> unknown_Nm = [](double) { return Vec3::Zero(); };

  // Another thruster commanded in the period (a canceller of the check, or the controller's) and
  // the share of its on-time that does not come.
  struct Fired {
    int thruster = model::kNoThruster;
    double on_fraction = 0;
    double missing = 0;
  };

  RateCheckReading period(const Vec3& torque_cmd_Nm, int checked = model::kNoThruster, double on_fraction = 0.0,
                          double missing = 0.0, const std::vector<Fired>& others = {}) {
    std::normal_distribution<double> noise(0.0, gyro_sigma);
    const Vec3 measured = omega + Vec3(noise(rng), noise(rng), noise(rng));
    RateCheckInput in{.t_s = t, .omega_body_radps = measured, .torque_cmd_body_Nm = torque_cmd_Nm, .checked = checked};
    Vec3 delivered = torque_cmd_Nm + unknown_Nm(t);
    for (const Fired& f : others) {
      in.on_fraction[static_cast<std::size_t>(f.thruster)] = f.on_fraction;
      delivered -= f.missing * f.on_fraction * p.torque_Nm[static_cast<std::size_t>(f.thruster)];
    }
    if (checked != model::kNoThruster) in.on_fraction[static_cast<std::size_t>(checked)] = on_fraction;
    const RateCheckReading r = step_rate_check(p, state, in);
    if (checked != model::kNoThruster)
      delivered -= missing * on_fraction * p.torque_Nm[static_cast<std::size_t>(checked)];
    omega += kT * (p.inverse_inertia * (delivered - omega.cross(p.inertia_kgm2 * omega)));
    t += kT;
    return r;
  }
};

// A commanded torque that changes every period, as a controller's does.
Vec3 busy_torque(int k) { return Vec3(std::sin(0.7 * k), std::cos(1.3 * k), 0.5 * std::sin(2.1 * k)); }

constexpr int kT1 = 0, kT2 = 1, kT5 = 4;
constexpr double kPulse = 0.075;  // 7.5 ms of a 0.1 s period

TEST(RateCheck, ReadsTheMissingShareOfThePulseThroughBusyTorques) {
  const RateCheckParams p = params();
  for (const double missing : {0.0, 0.5, 1.0}) {
    Body body(p);
    RateCheckReading read;
    for (int k = 0; k < 40; ++k) {
      const RateCheckReading r = body.period(busy_torque(k), k == 20 ? kT5 : model::kNoThruster, kPulse, missing);
      if (r.thruster != model::kNoThruster) read = r;
    }
    EXPECT_EQ(read.thruster, kT5);
    EXPECT_NEAR(read.missing, missing, 1e-9) << missing;  // rounding: no modelled term is left out
  }
}

TEST(RateCheck, ASlowUnknownTorqueAndAnotherPulseAmongTheNeighboursDoNotMoveTheReading) {
  const RateCheckParams p = params();
  Body body(p);
  body.unknown_Nm = [](double t) -> Vec3 {
    return Vec3(1.0, -0.5, 0.8) * std::sin(2 * M_PI * t / 60.0) + Vec3(0.3, 0.2, -0.1);
  };
  RateCheckReading read;
  for (int k = 0; k < 400; ++k) {
    int checked = model::kNoThruster;
    double missing = 0;
    if (k == 300) checked = kT1, missing = 0.5;
    if (k == 302) checked = kT2, missing = 1.0;  // a dead neighbour, two periods later
    const RateCheckReading r = body.period(busy_torque(k), checked, kPulse, missing);
    if (r.thruster == kT1) read = r;
  }
  ASSERT_EQ(read.thruster, kT1);
  // The unknown torque, up to 1.3 N m, reads as 0.5 of a pulse (T1's 35 N m x 0.075): the median
  // removes it but for the dead neighbour, which moves the median by up to two periods' change of
  // it, 0.01 N m each at the sine's steepest (t = 30 s), 0.004 of the pulse each.
  EXPECT_NEAR(read.missing, 0.5, 0.01);
}

TEST(RateCheck, ConfirmsADeadThrusterAfterThreeReadingsInARowEachAskingForARecheck) {
  const RateCheckParams p = params();
  Body body(p);
  int pulses = 0, k = 0;
  bool asked_again = false;
  int pending = model::kNoThruster;
  const int first = p.neighbours;  // the first check, its neighbours before it in
  while (body.state.confirmed == model::kNoThruster && k < 200) {
    const int checked = k == first ? kT5 : pending;
    pending = model::kNoThruster;
    if (checked != model::kNoThruster) ++pulses;
    body.period(busy_torque(k++), checked, kPulse, 1.0);
    if (body.state.recheck != model::kNoThruster) {
      asked_again = true;
      pending = body.state.recheck;  // the active check fires it in the next period
    }
    EXPECT_EQ(body.state.confirmed == model::kNoThruster, body.state.confirmed_s < 0);
  }
  EXPECT_TRUE(asked_again);
  EXPECT_EQ(pulses, 3);
  EXPECT_EQ(body.state.confirmed, kT5);
  EXPECT_EQ(body.state.kind, model::FaultKind::kStuckClosed);
  EXPECT_DOUBLE_EQ(body.state.size, 1.0);
  EXPECT_EQ(body.state.recheck, model::kNoThruster);
  EXPECT_NEAR(body.state.suspect_pulse_s, first * kT, 1e-9);  // the first pulse that read it
  // Each reading comes n + 1 periods after its pulse, its recheck one period later.
  EXPECT_EQ(k, first + 3 * (p.neighbours + 2));
}

TEST(RateCheck, AHalfLossIsALossAndAHealthyReadingLetsTheSuspicionGo) {
  const RateCheckParams p = params();
  const auto fly = [&](const std::vector<double>& missing_each_check) {
    Body body(p);
    int k = 0;
    while (k < p.neighbours) body.period(busy_torque(k++));
    for (const double missing : missing_each_check) {
      body.period(busy_torque(k++), kT5, kPulse, missing);
      for (int i = 0; i < p.neighbours + 1; ++i) body.period(busy_torque(k++));
    }
    return body.state;
  };
  const RateCheckState loss = fly({0.5, 0.5, 0.5});
  EXPECT_EQ(loss.confirmed, kT5);
  EXPECT_EQ(loss.kind, model::FaultKind::kLoss);
  EXPECT_NEAR(loss.size, 0.5, 1e-9);
  const RateCheckState cleared = fly({0.5, 0.5, 0.0});
  EXPECT_EQ(cleared.confirmed, model::kNoThruster);
  EXPECT_EQ(cleared.suspect, model::kNoThruster);
  EXPECT_EQ(cleared.recheck, model::kNoThruster);
  EXPECT_EQ(fly({0.5, 0.5, 0.0, 0.5, 0.5}).confirmed, model::kNoThruster);  // in a row, not in all
}

// A reading's bound on a healthy thruster: with a 20 % inertia error, a period whose commanded torque
// steps 10 N m off its neighbours' could read 0.2 x 10 N m / (T1's 35 N m x 0.075) ~ 0.8 off: the
// reading changes no suspicion and the check is asked for again. The spill: a thruster on for 95 ms
// of a 100 ms period whose valve opens up to 22.5 ms late spills up to 17.5 ms of its torque.
TEST(RateCheck, AReadingInABusyPeriodIsInconclusiveAndCheckedAgain) {
  RateCheckParams p = params();
  p.inertia_uncertainty = 0.2;
  p.shift_max_s = 0.0225;
  Body body(p);
  int k = 0;
  while (k < 20) body.period(Vec3(1.0, 0.0, 0.0), k++ == 10 ? kT1 : model::kNoThruster, kPulse, 1.0);
  body.period(Vec3(1.0, 10.0, 0.0), kT1, kPulse, 1.0);  // a dead T1 in a busy period
  RateCheckReading read;
  for (int i = 0; i < p.neighbours + 1; ++i) {
    const RateCheckReading r = body.period(Vec3(1.0, 0.0, 0.0));
    if (r.thruster != model::kNoThruster) read = r;
  }
  EXPECT_EQ(read.thruster, kT1);
  EXPECT_NEAR(read.missing, 1.0, 1e-9);
  EXPECT_GT(read.uncertainty, 0.5);
  EXPECT_EQ(body.state.suspect, kT1);  // the quiet check's reading before it still stands
  EXPECT_EQ(body.state.in_a_row, 1);
  EXPECT_EQ(body.state.recheck, kT1);

  WatchedSet set;
  set.count = 2;
  set.index = {0, 4};
  WatchedTon ton = WatchedTon::Zero();
  ton[0] = 0.95;  // T1: spills
  ton[1] = 0.7;   // T5: ends by 92.5 ms
  EXPECT_NEAR(spill_bound_Nms(p, set, ton), p.torque_Nm[0].norm() * 0.0175, 1e-12);
}

// A dead thruster checked again and again: T1 dead every fourth period, a healthy T5 between, so
// that half of each window's neighbours carry a check. The baseline leaves those out: each check
// reads its own pulse to rounding (in all of the neighbours' median, T1's deficit would take half a
// pulse off its own readings and add its lean on T5's to T5's). Every third period leaves fewer than
// n quiet neighbours: inconclusive.
TEST(RateCheck, ChecksAmongTheNeighboursAreLeftOutOfTheBaseline) {
  const RateCheckParams p = params();
  const auto fly = [&](int every) {
    Body body(p);
    std::vector<RateCheckReading> readings;
    for (int k = 0; k < 80; ++k) {
      int checked = model::kNoThruster;
      if (k >= 20 && k < 60 && k % every == 0) checked = kT1;
      if (k >= 20 && k < 60 && k % every == every / 2) checked = kT5;
      const RateCheckReading r =
          body.period(busy_torque(k), checked, kPulse, checked == kT1 ? 1.0 : 0.0);
      if (r.thruster != model::kNoThruster) readings.push_back(r);
    }
    return readings;
  };
  const std::vector<RateCheckReading> fourth = fly(4);
  ASSERT_EQ(fourth.size(), 20u);
  for (const RateCheckReading& r : fourth) {
    EXPECT_NEAR(r.missing, r.thruster == kT1 ? 1.0 : 0.0, 1e-9) << r.thruster;
    EXPECT_LT(r.uncertainty, p.max_uncertainty);
  }
  int inconclusive = 0;
  for (const RateCheckReading& r : fly(3)) inconclusive += std::isinf(r.uncertainty) ? 1 : 0;
  EXPECT_GT(inconclusive, 0);
}

// A dead thruster the controller fires in every period (on 20 % of each) is in every neighbour's
// residual: the baseline takes it away, and the check's reading is that of its on-time beyond the
// neighbours', 1 to rounding (on its whole on-time it would read 0.075 / 0.275).
TEST(RateCheck, AThrusterTheControllerFiresThroughoutIsReadOnTheChecksExcess) {
  const RateCheckParams p = params();
  Body body(p);
  RateCheckReading read;
  for (int k = 0; k < 30; ++k) {
    const bool check = k == 15;
    const double on = 0.2 + (check ? kPulse : 0.0);
    const RateCheckReading r = body.period(busy_torque(k), check ? kT1 : model::kNoThruster, on, 1.0,
                                           {{.thruster = kT1, .on_fraction = on, .missing = check ? 0.0 : 1.0}});
    if (r.thruster != model::kNoThruster) read = r;
  }
  ASSERT_EQ(read.thruster, kT1);
  EXPECT_NEAR(read.missing, 1.0, 1e-9);
}

// A leaking valve is open already: its pulse adds nothing and reads 1, but the baseline holds the
// leak's torque, 0.2 of T5's full thrust in every period: the open share reads it, and the fault is
// confirmed a leak of 0.2 (not stuck closed), whose thrust the recovery then cancels.
TEST(RateCheck, AMissingPulseOfAValveOpenAlreadyIsALeak) {
  const RateCheckParams p = params();
  Body body(p);
  body.unknown_Nm = [&p](double) -> Vec3 { return 0.2 * p.torque_Nm[static_cast<std::size_t>(kT5)]; };
  int pending = model::kNoThruster;
  for (int k = 0; k < 200 && body.state.confirmed == model::kNoThruster; ++k) {
    const int checked = pending != model::kNoThruster ? pending : (k == 10 ? kT5 : model::kNoThruster);
    body.period(busy_torque(k), checked, kPulse, 1.0);
    pending = body.state.recheck;
  }
  EXPECT_EQ(body.state.confirmed, kT5);
  EXPECT_EQ(body.state.kind, model::FaultKind::kLeak);
  EXPECT_NEAR(body.state.size, 0.2, 1e-9);
}

// A recheck waits until the latest check of any thruster is three periods back: checks in every
// period would leave no quiet neighbours for any reading.
TEST(RateCheck, ARecheckKeepsItsSpacingFromTheLatestCheck) {
  const RateCheckParams p = params();
  Body body(p);
  for (int k = 0; k < 10; ++k) body.period(busy_torque(k));
  body.state.recheck = kT5;
  EXPECT_EQ(next_recheck(body.state), kT5);
  body.period(busy_torque(10), kT1, kPulse);  // a routine check of another thruster
  EXPECT_EQ(next_recheck(body.state), model::kNoThruster);
  body.period(busy_torque(11));
  EXPECT_EQ(next_recheck(body.state), model::kNoThruster);
  body.period(busy_torque(12));
  EXPECT_EQ(next_recheck(body.state), kT5);  // the check would fly in period 13, 3 after T1's
}

// Two thrusters of the box layout whose torques lean on each other by `cos_from`..`cos_to` (the
// cosine of their angle), the first one found.
std::pair<int, int> torque_pair(const RateCheckParams& p, double cos_from, double cos_to) {
  for (int j = 0; j < 24; ++j)
    for (int i = 0; i < 24; ++i) {
      const Vec3& a = p.torque_Nm[static_cast<std::size_t>(j)];
      const Vec3& b = p.torque_Nm[static_cast<std::size_t>(i)];
      const double c = a.dot(b) / (a.norm() * b.norm());
      if (i != j && c >= cos_from && c <= cos_to) return {j, i};
    }
  return {model::kNoThruster, model::kNoThruster};
}

// A flight of busy periods with a check every seventh period of `routine` (the first once its n
// neighbours before it are in), or at once of the thruster the rate check asks for; each check of
// `routine` has `also` fired beside its pulse. Each thruster gives 1 - dead[i] of what it is
// commanded. Returns the thrusters checked, in order.
std::vector<int> fly_checks(Body& body, int routine, int also, const std::array<double, 24>& dead, int periods) {
  std::vector<int> checked_order;
  int pending = model::kNoThruster;
  for (int k = 0; k < periods && body.state.confirmed == model::kNoThruster; ++k) {
    int checked = pending;
    if (checked == model::kNoThruster && k % 7 == 6) checked = routine;
    pending = model::kNoThruster;
    std::vector<Body::Fired> others;
    if (checked == routine) others.push_back({also, kPulse, dead[static_cast<std::size_t>(also)]});
    const double missing = checked == model::kNoThruster ? 0.0 : dead[static_cast<std::size_t>(checked)];
    body.period(busy_torque(k), checked, kPulse, missing, others);
    if (checked != model::kNoThruster) checked_order.push_back(checked);
    pending = body.state.recheck;
  }
  return checked_order;
}

// A dead thruster the allocation fires in another thruster's check (to cancel its pulse, or for the
// controller) leaves its deficit in that check's period, on a direction that leans on the pulse's
// (cos 0.3-0.8 here): the checked thruster would read it as its own, 0.3-0.8 of its pulse. The dead
// one explains the residual to rounding; it is checked next, and its own checks confirm it.
TEST(RateCheck, ADeadThrusterFiredInAnotherChecksPeriodIsCheckedItselfNotTheCheckedOne) {
  const RateCheckParams p = params();
  const auto [checked, dead_one] = torque_pair(p, 0.3, 0.8);
  ASSERT_NE(checked, model::kNoThruster);
  Body body(p);
  std::array<double, 24> dead{};
  dead[static_cast<std::size_t>(dead_one)] = 1.0;
  RateCheckReading first;
  for (int k = 0; k < 20 && first.thruster == model::kNoThruster; ++k) {
    std::vector<Body::Fired> canceller;  // fired in the check's period only
    if (k == 5) canceller.push_back({.thruster = dead_one, .on_fraction = kPulse, .missing = 1.0});
    first = body.period(busy_torque(k), k == 5 ? checked : model::kNoThruster, kPulse, 0.0, canceller);
  }
  ASSERT_EQ(first.thruster, checked);
  EXPECT_GT(first.missing, p.threshold);  // what the checked thruster alone would have read
  EXPECT_EQ(first.culprit, dead_one);
  EXPECT_NEAR(first.culprit_missing, 1.0, 1e-9);
  EXPECT_EQ(body.state.recheck, dead_one);
  EXPECT_EQ(body.state.suspect, model::kNoThruster);

  Body flight(p);
  const std::vector<int> order = fly_checks(flight, checked, dead_one, dead, 400);
  EXPECT_EQ(flight.state.confirmed, dead_one);
  EXPECT_EQ(flight.state.kind, model::FaultKind::kStuckClosed);
  EXPECT_EQ(std::count(order.begin(), order.end(), dead_one), 3);
}

// Rates see torques only: two thrusters with the same torque read alike (COMRADE's layout has such
// pairs, T1 and T22; the box layout none: T11 is given T5's torque). A dead one fired in the other's
// check makes that check read 1 with the dead one as its rival, checked first: its own checks
// confirm it. The other way round, a dead checked thruster with a healthy rival: the rival's check
// reads it healthy, and the checked one is confirmed by three checks more.
TEST(RateCheck, AThrusterOfTheSameTorqueIsARivalCheckedFirst) {
  RateCheckParams p = params();
  const int checked = kT5, twin = 10;
  p.torque_Nm[static_cast<std::size_t>(twin)] = p.torque_Nm[static_cast<std::size_t>(checked)];
  {
    Body body(p);
    std::array<double, 24> dead{};
    dead[static_cast<std::size_t>(twin)] = 1.0;
    const std::vector<int> order = fly_checks(body, checked, twin, dead, 400);
    EXPECT_EQ(body.state.confirmed, twin);
    ASSERT_GE(order.size(), 2u);
    EXPECT_EQ(order[0], checked);
    EXPECT_EQ(order[1], twin);  // the rival, at once
  }
  {
    Body body(p);
    std::array<double, 24> dead{};
    dead[static_cast<std::size_t>(checked)] = 1.0;
    const std::vector<int> order = fly_checks(body, checked, twin, dead, 400);
    EXPECT_EQ(body.state.confirmed, checked);
    EXPECT_EQ(order, (std::vector<int>{checked, twin, checked, checked, checked}));
  }
}

// The suspect stays the suspect when another thruster's reading has it as its rival: T5 dead, read
// once (in_a_row 1), then a check of its same-torque twin with T5 fired beside it: the twin's pulse
// reads 1 with T5 its rival. The twin does not displace T5 (which would start the count again and
// leave T5 out of the twin's next readings, as read since the suspicion began): T5 is checked
// again, and its own checks confirm it.
TEST(RateCheck, TheSuspectAsAnotherReadingsRivalStaysTheSuspect) {
  RateCheckParams p = params();
  const int twin = 10;
  p.torque_Nm[static_cast<std::size_t>(twin)] = p.torque_Nm[static_cast<std::size_t>(kT5)];
  Body body(p);
  int k = 0;
  while (k < p.neighbours) body.period(busy_torque(k++));
  body.period(busy_torque(k++), kT5, kPulse, 1.0);
  for (int i = 0; i < p.neighbours + 1; ++i) body.period(busy_torque(k++));
  ASSERT_EQ(body.state.suspect, kT5);
  ASSERT_EQ(body.state.in_a_row, 1);
  body.period(busy_torque(k++), twin, kPulse, 0.0, {{.thruster = kT5, .on_fraction = kPulse, .missing = 1.0}});
  RateCheckReading read;
  for (int i = 0; i < p.neighbours + 1; ++i) {
    const RateCheckReading r = body.period(busy_torque(k++));
    if (r.thruster != model::kNoThruster) read = r;
  }
  ASSERT_EQ(read.thruster, twin);
  EXPECT_NEAR(read.missing, 1.0, 1e-9);
  EXPECT_EQ(read.rival, kT5);
  EXPECT_EQ(body.state.suspect, kT5);
  EXPECT_EQ(body.state.in_a_row, 1);
  EXPECT_EQ(body.state.recheck, kT5);
  int pending = body.state.recheck;
  for (int i = 0; i < 200 && body.state.confirmed == model::kNoThruster; ++i) {
    body.period(busy_torque(k++), pending, kPulse, pending == kT5 ? 1.0 : 0.0);
    pending = body.state.recheck;
  }
  EXPECT_EQ(body.state.confirmed, kT5);
}

// A valve that does not close (a leak, stuck open) shows only where the allocation cuts it: T5's
// opposite (a thruster given -T5's torque) is fired on 0.2 of every period but delivers its 0.2 in
// T5's check period too, where the allocation cut it to 0.125 to cancel the pulse. The healthy T5's
// pulse then reads 1, with the cut thruster as its rival, whose own pulse would read healthy (its
// valve opens): the reading decides nothing, T5 is checked again, and over 400 periods T5 is
// never confirmed.
TEST(RateCheck, ARivalThePeriodCutDecidesNothing) {
  RateCheckParams p = params();
  const int opposite = 10;
  p.torque_Nm[static_cast<std::size_t>(opposite)] = -p.torque_Nm[static_cast<std::size_t>(kT5)];
  Body body(p);
  RateCheckReading first;
  int pending = model::kNoThruster, asked_after_first = model::kNoThruster;
  for (int k = 0; k < 400; ++k) {
    const int checked = pending != model::kNoThruster ? pending : (k % 7 == 6 ? kT5 : model::kNoThruster);
    // commanded 0.125 in the check's period, delivered 0.2: missing -0.075 / 0.125
    const Body::Fired held = checked == kT5 ? Body::Fired{.thruster = opposite, .on_fraction = 0.2 - kPulse,
                                                          .missing = -kPulse / (0.2 - kPulse)}
                                            : Body::Fired{.thruster = opposite, .on_fraction = 0.2, .missing = 0.0};
    const RateCheckReading r = body.period(busy_torque(k), checked, kPulse, 0.0, {held});
    if (r.thruster == kT5 && first.thruster == model::kNoThruster) {
      first = r;
      asked_after_first = body.state.recheck;
    }
    pending = body.state.recheck;
  }
  ASSERT_EQ(first.thruster, kT5);
  EXPECT_NEAR(first.missing, 1.0, 1e-9);
  EXPECT_EQ(first.rival, opposite);
  EXPECT_TRUE(first.rival_cut);
  EXPECT_EQ(body.state.confirmed, model::kNoThruster);
  EXPECT_EQ(body.state.suspect, model::kNoThruster);
  EXPECT_EQ(asked_after_first, kT5);  // the same check again, not the rival's
}

// The gyro's noise (1e-6 rad/s, comrade_sync's) over 2,000 checks of healthy thrusters, each one
// every seventh period: the readings' spread is that noise over a pulse's 1.4e-4 rad/s, and not
// one confirmation.
TEST(RateCheck, AHealthyFlightWithTheGyrosNoiseNeverConfirms) {
  const RateCheckParams p = params();
  Body body(p);
  body.gyro_sigma = 1e-6;
  double largest = 0;
  for (int k = 0; k < 14000; ++k) {
    const int checked = k % 7 == 0 ? (k / 7) % 24 : model::kNoThruster;
    const RateCheckReading r = body.period(busy_torque(k), checked, kPulse, 0.0);
    if (r.thruster != model::kNoThruster) largest = std::max(largest, std::abs(r.missing));
  }
  EXPECT_EQ(body.state.confirmed, model::kNoThruster);
  EXPECT_GT(largest, 0.0);
  EXPECT_LT(largest, p.threshold / 2);
}

}  // namespace rate_check_test
}  // namespace chaser::flight::fdi
