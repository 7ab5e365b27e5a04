// The multi-rate schedule on the integer nanosecond clock (sim/rate_schedule.hpp): COMRADE 2018's
// 3 Hz platform and 1 kHz joints run at their rates, coincident blocks in declared order, a single
// 0.1 s rate is the plain integer loop, and the closed-form count agrees with stepping.
#include "sim/rate_schedule.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace chaser::sim {
namespace {

struct Event {
  TimeNs t;
  int block;
};

ScheduleParams schedule_of(const std::vector<Rate>& rates, const std::vector<const char*>& names) {
  ScheduleParams params;
  params.count = static_cast<int>(rates.size());
  for (std::size_t i = 0; i < rates.size(); ++i) {
    params.rates[i] = rates[i];
    params.names[i] = names[i];
  }
  return params;
}

// Every activation in [0, t_last], in the order the schedule hands them out.
std::vector<Event> run_until(const ScheduleParams& params, TimeNs t_last) {
  std::vector<Event> events;
  ScheduleState state = start_schedule(params);
  std::array<int, kMaxScheduledBlocks> due{};
  for (TimeNs t = next_event_ns(params, state); t <= t_last; t = next_event_ns(params, state)) {
    const int n = due_blocks(params, state, t, due);
    for (int j = 0; j < n; ++j) events.push_back({t, due[static_cast<std::size_t>(j)]});
  }
  return events;
}

// Block b's activation times, in order.
std::vector<TimeNs> times_of(const std::vector<Event>& events, int b) {
  std::vector<TimeNs> times;
  for (const Event& e : events)
    if (e.block == b) times.push_back(e.t);
  return times;
}

bool mentions(const std::vector<std::string>& problems, const std::string& field) {
  return std::any_of(problems.begin(), problems.end(),
                     [&](const std::string& p) { return p.find(field) != std::string::npos; });
}

TEST(RateSchedule, ThreeHertzPlatformAndKilohertzInnerLoopRunAtTheirRatesInOrder) {
  const Rate platform{1'000'000'000, 3, 0}, inner{1'000'000, 1, 0};
  for (const bool platform_first : {true, false}) {
    const ScheduleParams params = platform_first ? schedule_of({platform, inner}, {"platform", "inner"})
                                                 : schedule_of({inner, platform}, {"inner", "platform"});
    ASSERT_TRUE(validate(params).empty());
    const int p = platform_first ? 0 : 1, q = 1 - p;
    for (const std::int64_t seconds : {1, 10}) {
      const std::vector<Event> events = run_until(params, seconds * kNsPerSecond);
      const std::vector<TimeNs> tp = times_of(events, p), tq = times_of(events, q);
      const Rate& rate_p = params.rates[static_cast<std::size_t>(p)];
      const Rate& rate_q = params.rates[static_cast<std::size_t>(q)];
      // [0, T] holds 3T + 1 and 1000T + 1 activations: the last at T itself.
      ASSERT_EQ(tp.size(), static_cast<std::size_t>(3 * seconds + 1));
      ASSERT_EQ(tq.size(), static_cast<std::size_t>(1000 * seconds + 1));
      EXPECT_EQ(tp[0], 0);
      EXPECT_EQ(tp[1], 333'333'334);
      EXPECT_EQ(tp[2], 666'666'667);
      EXPECT_EQ(tp[3], 1'000'000'000);
      for (std::size_t m = 0; m < tp.size(); ++m)
        EXPECT_EQ(tp[m], activation_time(rate_p, static_cast<std::int64_t>(m)));
      for (std::size_t m = 0; m < tq.size(); ++m) {
        EXPECT_EQ(tq[m], static_cast<TimeNs>(m) * 1'000'000);
        EXPECT_EQ(tq[m], activation_time(rate_q, static_cast<std::int64_t>(m)));
      }
      for (std::size_t k = 1; k < events.size(); ++k) {
        ASSERT_LE(events[k - 1].t, events[k].t);
        // Within one time, declared order; distinct event times strictly increase.
        if (events[k - 1].t == events[k].t) {
          EXPECT_LT(events[k - 1].block, events[k].block);
        }
      }
      // Each whole second both run, the first declared first.
      for (std::int64_t s = 0; s <= seconds; ++s) {
        const auto at = std::find_if(events.begin(), events.end(),
                                     [&](const Event& e) { return e.t == s * kNsPerSecond; });
        ASSERT_NE(at, events.end());
        ASSERT_NE(at + 1, events.end());
        EXPECT_EQ(at->block, 0);
        EXPECT_EQ((at + 1)->t, s * kNsPerSecond);
        EXPECT_EQ((at + 1)->block, 1);
      }
    }
  }
}

TEST(RateSchedule, ComradeSensorPlatformAndJointBlocksAtCoincidentTimesRunInDeclaredOrder) {
  const ScheduleParams params = schedule_of({rate_of_hz(3), rate_of_hz(10), rate_of_hz(3), rate_of_hz(1000)},
                                            {"lidar", "arm_camera", "platform", "joints"});
  ASSERT_TRUE(validate(params).empty());
  EXPECT_EQ(params.rates[3].period_numerator_ns, 1'000'000);
  EXPECT_EQ(params.rates[3].period_denominator, 1);
  ScheduleState state = start_schedule(params);
  std::array<int, kMaxScheduledBlocks> due{};
  TimeNs previous = -1;
  for (TimeNs t = next_event_ns(params, state); t <= 2 * kNsPerSecond; t = next_event_ns(params, state)) {
    ASSERT_GT(t, previous);
    previous = t;
    const int n = due_blocks(params, state, t, due);
    ASSERT_GE(n, 1);
    if (t % kNsPerSecond == 0) {
      ASSERT_EQ(n, 4);
      for (int j = 0; j < 4; ++j) EXPECT_EQ(due[static_cast<std::size_t>(j)], j);
    }
    if (t == 100'000'000) {  // the camera and the joints, camera first
      ASSERT_EQ(n, 2);
      EXPECT_EQ(due[0], 1);
      EXPECT_EQ(due[1], 3);
    }
  }
}

// How the existing single-rate runs keep their bits: period k at exactly k * 100'000'000 ns.
TEST(RateSchedule, SinglePointOneSecondRateReproducesTheIntegerLoop) {
  const ScheduleParams params = schedule_of({rate_of_period(100'000'000)}, {"period"});
  ASSERT_TRUE(validate(params).empty());
  ScheduleState state = start_schedule(params);
  std::array<int, kMaxScheduledBlocks> due{};
  for (std::int64_t k = 0; k < 30'000; ++k) {
    const TimeNs t = next_event_ns(params, state);
    ASSERT_EQ(t, k * 100'000'000);
    ASSERT_EQ(due_blocks(params, state, t, due), 1);
    ASSERT_EQ(due[0], 0);
  }
}

TEST(RateSchedule, ActivationsBeforeMatchesSteppingForRationalRatesAndOffsets) {
  const std::vector<Rate> rates = {
      rate_of_hz(7),           {1'000'000'000, 3, 0},       {1'000'000'000, 3, 333'333'333},
      {1'000'000'000, 7, 5},   {100'000'000, 1, 50'000'000}, {1'000'000, 1, 999'999},
      {1'000'000'000, 3000, 1}, {7, 3, 2},
  };
  for (const Rate& rate : rates) {
    ASSERT_TRUE(validate(rate).empty()) << rate.period_numerator_ns << "/" << rate.period_denominator;
    const TimeNs horizon = rate.period_numerator_ns < 1000 ? 10'000 : 3 * kNsPerSecond;
    const std::vector<TimeNs> times = times_of(run_until(schedule_of({rate}, {"block"}), horizon), 0);
    auto stepped_before = [&](TimeNs t_end) {
      return static_cast<std::int64_t>(std::lower_bound(times.begin(), times.end(), t_end) - times.begin());
    };
    for (const TimeNs t : times)
      for (const TimeNs t_end : {t - 1, t, t + 1})
        ASSERT_EQ(activations_before(rate, t_end), stepped_before(t_end)) << "t_end " << t_end;
    for (TimeNs t_end = -5; t_end <= horizon; t_end += horizon / 997 + 1)
      ASSERT_EQ(activations_before(rate, t_end), stepped_before(t_end)) << "t_end " << t_end;
  }
}

TEST(RateSchedule, ThreeHertzActivationTimesNeverDrift) {
  const Rate three_hz = rate_of_hz(3);
  for (std::int64_t n = 0; n <= 1'000'000; ++n) {
    ASSERT_EQ(activation_time(three_hz, 3 * n), n * kNsPerSecond);
    ASSERT_EQ(activation_time(three_hz, 3 * n + 1), n * kNsPerSecond + 333'333'334);
    ASSERT_EQ(activation_time(three_hz, 3 * n + 2), n * kNsPerSecond + 666'666'667);
    ASSERT_EQ(activations_before(three_hz, n * kNsPerSecond), 3 * n);
  }
  // m * numerator = 2.7e19 passes int64; the time, 9e18 ns, does not.
  EXPECT_EQ(activation_time(three_hz, 27'000'000'000), 9'000'000'000 * kNsPerSecond);
  // Past the int64 clock the activation never comes.
  EXPECT_EQ(activation_time(three_hz, 28'000'000'000), kNeverNs);
}

TEST(RateSchedule, ValidateNamesTheBadFieldOfRatesAndSchedules) {
  EXPECT_TRUE(validate(rate_of_hz(3)).empty());
  EXPECT_TRUE(validate(Rate{1'000'000'000, 3, 333'333'333}).empty());  // offset < 333'333'333.3
  EXPECT_TRUE(validate(Rate{1, 1, 0}).empty());
  for (const std::int64_t bad : {0, -1}) {
    EXPECT_TRUE(mentions(validate(Rate{bad, 1, 0}), "period_numerator_ns: must be >= 1"));
    EXPECT_TRUE(mentions(validate(Rate{1'000'000, bad, 0}), "period_denominator: must be >= 1"));
  }
  EXPECT_TRUE(mentions(validate(Rate{1, 3, 0}), "period_numerator_ns: the period"));  // 1/3 ns
  EXPECT_TRUE(mentions(validate(Rate{1'000'000, 1, -1}), "offset_ns: must be >= 0"));
  EXPECT_TRUE(mentions(validate(Rate{1'000'000, 1, 1'000'000}), "offset_ns: must be <"));
  EXPECT_TRUE(mentions(validate(Rate{1'000'000'000, 3, 333'333'334}), "offset_ns: must be <"));

  ScheduleParams params = schedule_of({rate_of_hz(3), Rate{0, 1, 0}}, {"lidar", "joints"});
  EXPECT_EQ(validate(params), std::vector<std::string>{"joints.rate.period_numerator_ns: must be >= 1"});
  params.names[1] = nullptr;
  EXPECT_TRUE(mentions(validate(params), "block 1.rate.period_numerator_ns"));
  params.count = kMaxScheduledBlocks + 1;
  EXPECT_TRUE(mentions(validate(params), "count: must be in 0..16"));
}

}  // namespace
}  // namespace chaser::sim
