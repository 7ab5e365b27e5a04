#include "sim/rate_schedule.hpp"

#include <algorithm>
#include <numeric>

namespace chaser::sim {

namespace {

// m * numerator passes int64 near m ~ 1e10 for a 1 s period. __extension__: the build's -Wpedantic.
__extension__ typedef __int128 Wide;

TimeNs saturate(Wide t) { return t > static_cast<Wide>(kNeverNs) ? kNeverNs : static_cast<TimeNs>(t); }

std::string block_name(const ScheduleParams& params, int i) {
  const char* name = params.names[static_cast<std::size_t>(i)];
  return name != nullptr ? std::string(name) : "block " + std::to_string(i);
}

}  // namespace

Rate rate_of_period(TimeNs period_ns) { return Rate{period_ns, 1, 0}; }

Rate rate_of_hz(std::int64_t hz) {
  // Reduced so that a whole-nanosecond period reads as one (and m * numerator keeps headroom).
  const std::int64_t g = hz > 0 ? std::gcd(kNsPerSecond, hz) : 1;
  return Rate{kNsPerSecond / g, hz / g, 0};
}

std::vector<std::string> validate(const Rate& rate) {
  std::vector<std::string> problems;
  const bool numerator_ok = rate.period_numerator_ns >= 1;
  const bool denominator_ok = rate.period_denominator >= 1;
  if (!numerator_ok) problems.push_back("period_numerator_ns: must be >= 1");
  if (!denominator_ok) problems.push_back("period_denominator: must be >= 1");
  // Below 1 ns two activations would share a nanosecond and a block would be due twice at once.
  if (numerator_ok && denominator_ok && rate.period_numerator_ns < rate.period_denominator)
    problems.push_back("period_numerator_ns: the period numerator / denominator must be >= 1 ns");
  if (rate.offset_ns < 0) problems.push_back("offset_ns: must be >= 0");
  // offset < numerator / denominator, compared without rounding.
  if (numerator_ok && denominator_ok && rate.offset_ns >= 0 &&
      static_cast<Wide>(rate.offset_ns) * rate.period_denominator >= rate.period_numerator_ns)
    problems.push_back("offset_ns: must be < the period numerator / denominator");
  return problems;
}

TimeNs activation_time(const Rate& rate, std::int64_t m) {
  const Wide product = static_cast<Wide>(m) * rate.period_numerator_ns;
  // ceil(p / d) for p >= 0, d >= 1.
  const Wide ceil_quotient = (product + rate.period_denominator - 1) / rate.period_denominator;
  return saturate(rate.offset_ns + ceil_quotient);
}

std::int64_t activations_before(const Rate& rate, TimeNs t_end) {
  // offset + ceil(m n / d) < t_end  <=>  ceil(m n / d) <= s - 1  <=>  m n <= (s - 1) d, s = t_end - offset:
  // m = 0 .. floor((s - 1) d / n). The count is at most s since the period is >= 1 ns.
  const Wide s = static_cast<Wide>(t_end) - rate.offset_ns;
  if (s <= 0) return 0;
  return static_cast<std::int64_t>((s - 1) * rate.period_denominator / rate.period_numerator_ns + 1);
}

std::vector<std::string> validate(const ScheduleParams& params) {
  std::vector<std::string> problems;
  if (params.count < 0 || params.count > kMaxScheduledBlocks) {
    problems.push_back("count: must be in 0.." + std::to_string(kMaxScheduledBlocks));
    return problems;
  }
  for (int i = 0; i < params.count; ++i)
    for (const std::string& p : validate(params.rates[static_cast<std::size_t>(i)]))
      problems.push_back(block_name(params, i) + ".rate." + p);
  return problems;
}

ScheduleState start_schedule(const ScheduleParams& params) {
  ScheduleState state;
  for (int i = 0; i < params.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    state.next_activation_ns[k] = activation_time(params.rates[k], 0);
  }
  return state;
}

TimeNs next_event_ns(const ScheduleParams& params, const ScheduleState& state) {
  TimeNs earliest = kNeverNs;
  for (int i = 0; i < params.count; ++i)
    earliest = std::min(earliest, state.next_activation_ns[static_cast<std::size_t>(i)]);
  return earliest;
}

int due_blocks(const ScheduleParams& params, ScheduleState& state, TimeNs t,
               std::array<int, kMaxScheduledBlocks>& out) {
  int n = 0;
  for (int i = 0; i < params.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (state.next_activation_ns[k] != t) continue;
    out[static_cast<std::size_t>(n++)] = i;
    state.next_activation_ns[k] = activation_time(params.rates[k], ++state.activations_run[k]);
  }
  return n;
}

}  // namespace chaser::sim
