// The impulse statistic (flight/fdi/impulse_detector.hpp) on synthetic torque rows, against closed
// forms: a sloshing liquid's rows (a sinusoid) stay under the bound any zero-mean oscillation
// obeys; a thruster's lasting excess alarms when its impulse reaches the threshold and is pinned on
// that thruster's torque; a level cancels; a change of the commanded force on a centre of mass off
// its place stays under the bound the scenario's uncertainty gives, and alarms without it.
#include "flight/fdi/impulse_detector.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "core/random.hpp"
#include "tests/support/deficit_24.hpp"

namespace chaser::flight::fdi {
namespace impulse_detector_test {

constexpr double kT = 0.1;  // [s]

// 20 s window, 100 s baseline, blocks of 10 periods.
ImpulseDetectorParams params(double threshold_Nms = 40.0) {
  return {.block = 10, .window_blocks = 20, .baseline_blocks = 100, .threshold_Nms = threshold_Nms};
}

struct Period {
  Vec3 row = Vec3::Zero();              // [N m] the torque row of this period
  WatchedTon ton = WatchedTon::Zero();  // its commands
};

// Feeds the detector `seconds` of periods, as the FDIR does: sample k is pushed with its commands,
// and the row of sample k - 1 is the bank's last row. Returns the time of the alarm (-1: none).
double fly(const ImpulseDetectorParams& p, const DeficitIsolationParams& bp, double seconds,
           const std::function<Period(int)>& period_k, ImpulseDetectorState& state, double* largest = nullptr) {
  DeficitBankState bank;
  Period previous;
  const int periods = static_cast<int>(std::lround(seconds / kT));
  for (int k = 0; k < periods; ++k) {
    const Period now = period_k(k);
    bank.ring[static_cast<std::size_t>(bank.count % kMaxDeficitWindow)].ton = now.ton;
    bank.last_torque_row = previous.row;
    ++bank.count;
    step_impulse_detector(p, bp, bank, state);
    if (largest) *largest = std::max(*largest, state.statistic);
    if (state.alarm) return k * kT;
    previous = now;
  }
  return -1.0;
}

DeficitIsolationParams bank_params(double com_uncertainty_m = 0.0, double inertia_uncertainty = 0.0) {
  DeficitIsolationParams bp = chaser::testing::box_24_deficit_params();
  bp.com_uncertainty_m = com_uncertainty_m;
  bp.inertia_uncertainty = inertia_uncertainty;
  return bp;
}

// The liquid's strikes, as a 3 N m oscillation of period 8 s on every axis plus white row noise:
// any zero-mean sinusoid's integral over an interval is at most 2 A / omega, so the change statistic
// is at most (1 + W / L) 2 A / omega = 9.2 N m s, plus the noise's ~0.1 N m s. Never an alarm.
TEST(ImpulseDetector, ALiquidsOscillationStaysUnderItsClosedFormBound) {
  const double amplitude = 3.0, omega = 2.0 * std::numbers::pi / 8.0;
  RandomStream noise(3, "impulse_detector_test/noise");
  ImpulseDetectorState state;
  double largest = 0.0;
  const double alarm = fly(params(), bank_params(), 900.0, [&](int k) {
    Period p;
    p.row = Vec3::Constant(amplitude * std::sin(omega * k * kT + 0.3)) + 0.05 * Vec3(noise.normal(), noise.normal(), noise.normal());
    return p;
  }, state, &largest);
  EXPECT_LT(alarm, 0.0);
  EXPECT_GT(largest, 1.0);  // the statistic did see the oscillation
  EXPECT_LT(largest, (1.0 + 20.0 / 100.0) * 2.0 * amplitude / omega + 0.5);
}

// A lane's lasting excess (stuck open: its whole torque, every period) from 200 s: the window's
// impulse grows as |M_C,i| t, the baseline holds none of it, so the alarm comes at the first block
// end after t = threshold / max_a |M_C,i,a|, and the suspect has that lane's torque line: its partner
// (same torque) is as likely, and so is a thruster of the opposite torque short of its command (a
// loss); the deficit bank tells them apart after the alarm, by the position rows and the commands.
TEST(ImpulseDetector, ALastingExcessAlarmsWhenItsImpulseReachesTheThreshold) {
  const DeficitIsolationParams bp = bank_params();
  for (const int lane : {0, 7, 13, 22}) {
    const Vec3 torque = bp.torque_body_Nm.col(lane);
    ImpulseDetectorState state;
    const double alarm = fly(params(), bp, 400.0, [&](int k) {
      Period p;
      if (k * kT >= 200.0) p.row = torque;
      return p;
    }, state);
    const double expected = 200.0 + 40.0 / torque.cwiseAbs().maxCoeff();
    ASSERT_GT(alarm, 0.0) << lane;
    EXPECT_GE(alarm, expected - kT) << lane;
    EXPECT_LE(alarm, expected + 1.0 + kT) << lane;  // the next block's end
    ASSERT_GE(state.suspect, 0) << lane;
    const Vec3 suspected = bp.torque_body_Nm.col(state.suspect);
    EXPECT_NEAR(std::abs(suspected.normalized().dot(torque.normalized())), 1.0, 1e-12)
        << lane << " read as " << state.suspect;
  }
}

// A constant row (a steady thrust on a centre of mass off its place, all along) is a level: the
// window's mean and the baseline's are equal, the statistic zero.
TEST(ImpulseDetector, ALevelCancels) {
  ImpulseDetectorState state;
  double largest = 0.0;
  EXPECT_LT(fly(params(), bank_params(), 600.0, [](int) { return Period{.row = Vec3(5.0, -4.0, 3.0)}; }, state,
                &largest),
            0.0);
  EXPECT_LT(largest, 1e-9);
}

// The commanded force changes at 200 s (lane 4 fired whole periods, 22 N) on a centre of mass 2 cm
// off its nominal place: the rows change by delta_c x F. Within the scenario's bound (3 cm) the
// statistic stays zero; with no bound it alarms on the model error's 0.44 N m... once its impulse
// over 20 s reaches a threshold of 5 N m s.
TEST(ImpulseDetector, AForceChangeOnAnOffsetCentreOfMassStaysWithinItsBound) {
  const Vec3 com_error(0.02, -0.02, 0.02);
  for (const double bound : {0.03, 0.0}) {
    const DeficitIsolationParams bp = bank_params(bound);
    const Vec3 force = bp.force_body_N.col(4);
    ImpulseDetectorState state;
    double largest = 0.0;
    const double alarm = fly(params(5.0), bp, 400.0, [&](int k) {
      Period p;
      if (k * kT >= 200.0) {
        p.ton(4) = 1.0;
        p.row = com_error.cross(force);
      }
      return p;
    }, state, &largest);
    if (bound > 0.0) {
      EXPECT_LT(alarm, 0.0);
      EXPECT_LT(largest, 1e-9);  // zero but for the sums' rounding
    } else {
      EXPECT_GT(alarm, 200.0);
    }
  }
}

// Nothing before the window and the baseline are full, whatever the rows: the baseline is the
// reference, and without it the statistic is not defined.
TEST(ImpulseDetector, WaitsForAFullBaseline) {
  ImpulseDetectorState state;
  const double alarm = fly(params(), bank_params(), 200.0, [](int k) {
    return Period{.row = Vec3::Constant(k * kT < 50.0 ? 0.0 : 100.0)};
  }, state);
  EXPECT_NEAR(alarm, 120.0, 1.0 + kT);  // the first evaluation: a huge change
}

TEST(ImpulseDetector, ValidateNamesTheField) {
  EXPECT_TRUE(validate(params()).empty());
  ImpulseDetectorParams p = params();
  p.window_blocks = 0;
  ASSERT_EQ(validate(p).size(), 1u);
  EXPECT_NE(validate(p)[0].find("window_blocks"), std::string::npos);
  p = params();
  p.baseline_blocks = 590;
  EXPECT_NE(validate(p)[0].find("600"), std::string::npos);
  p = params();
  p.threshold_Nms = 0.0;
  EXPECT_NE(validate(p)[0].find("threshold_Nms"), std::string::npos);
}

}  // namespace impulse_detector_test
}  // namespace chaser::flight::fdi
