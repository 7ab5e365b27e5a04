#pragma once
// A multi-rate schedule: blocks (a sensor, the platform loop, a fast inner joint loop) that run at
// their own rates on the integer nanosecond clock, and at coincident times in a declared order.
//
// Why rational periods: COMRADE 2018 (sec. 6.2.1) commands the platform at 3 Hz and the joints at
// 1 kHz, with the LIDAR at 3 Hz and the arm camera at 10 Hz. A period of 1/3 s is not a whole
// number of nanoseconds, so a rate's period is numerator_ns / denominator, and activation m
// (m = 0, 1, 2, ...) happens at
//   t_m = offset_ns + ceil(m * numerator_ns / denominator)
// computed exactly in integer arithmetic (the product in __int128). 3 Hz runs at 0, 333'333'334,
// 666'666'667, 1'000'000'000 ns, ... Time stays an integer count of nanoseconds and t_m comes from
// m itself, never from adding periods, so nothing drifts: activation 3N of 3 Hz is exactly N s,
// and a whole-nanosecond period gives the plain loop k * period bit for bit.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/time.hpp"

namespace chaser::sim {

inline constexpr int kMaxScheduledBlocks = 16;

// A time no activation reaches: the next activation of a block that would pass the int64 clock,
// and the next event of an empty schedule.
inline constexpr TimeNs kNeverNs = INT64_MAX;

struct Rate {
  std::int64_t period_numerator_ns = 0;  // [ns] period = numerator / denominator
  std::int64_t period_denominator = 1;   // [-]
  TimeNs offset_ns = 0;                  // [ns] time of activation 0, in [0, period)
};

// A whole-nanosecond period: activation m at offset + m * period_ns.
Rate rate_of_period(TimeNs period_ns);
// period = 1e9 / hz ns, the fraction reduced (1 kHz is 1'000'000 / 1).
Rate rate_of_hz(std::int64_t hz);

// Problems with the rate (empty when valid), each naming the field. A valid rate has a period of
// at least 1 ns, so its activation times are strictly increasing.
std::vector<std::string> validate(const Rate& rate);

// t_m = offset + ceil(m * numerator / denominator) for m >= 0 and a valid rate; kNeverNs when
// t_m would not fit the int64 clock.
TimeNs activation_time(const Rate& rate, std::int64_t m);

// The number of activations in [0, t_end) of a valid rate, in closed form.
std::int64_t activations_before(const Rate& rate, TimeNs t_end);

// Blocks 0..count-1 in declared order: blocks due at one time run in this order (e.g. the sensor
// before the platform loop before the inner loop).
struct ScheduleParams {
  std::array<Rate, kMaxScheduledBlocks> rates{};
  std::array<const char*, kMaxScheduledBlocks> names{};  // for messages; null reads "block i"
  int count = 0;
};

// Every block's rate, prefixed with its name, and the count in 0..kMaxScheduledBlocks.
std::vector<std::string> validate(const ScheduleParams& params);

struct ScheduleState {
  std::array<std::int64_t, kMaxScheduledBlocks> activations_run{};  // m of the next activation
  std::array<TimeNs, kMaxScheduledBlocks> next_activation_ns{};     // activation_time(rate, m)
};

// No block has run yet: each is next due at its offset.
ScheduleState start_schedule(const ScheduleParams& params);

// The earliest pending activation over all blocks (kNeverNs for none).
TimeNs next_event_ns(const ScheduleParams& params, const ScheduleState& state);

// Writes to `out` the indices of the blocks due exactly at t, in declared order, marks each run
// (its next activation computed from its count, not added to t) and returns how many there are.
// Called with t = next_event_ns, no activation is skipped.
int due_blocks(const ScheduleParams& params, ScheduleState& state, TimeNs t,
               std::array<int, kMaxScheduledBlocks>& out);

}  // namespace chaser::sim
