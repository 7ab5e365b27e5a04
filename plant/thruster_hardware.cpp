#include "plant/thruster_hardware.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <optional>

#include "core/constants.hpp"
#include "core/rotation.hpp"
#include "model/thruster_geometry.hpp"
#include "plant/thruster_faults.hpp"

namespace chaser::plant {
namespace {

constexpr double kTruncationSigmas = 3.0;
constexpr std::int64_t kThrusterKeyBase = 32;  // event key = (t - t_k) * 32 + thruster
static_assert(model::kMaxThrusters <= kThrusterKeyBase);

using Mask = std::uint32_t;  // bit i set: thruster i produces thrust

// Misalignment: rotate the direction about two axes perpendicular to it.
Vec3 misaligned_direction(const Vec3& direction, double sigma_rad, RandomStream& dispersion) {
  if (sigma_rad == 0.0) return direction;
  const Vec3 e1 = direction.unitOrthogonal();
  const Vec3 e2 = direction.cross(e1).normalized();
  const double a = dispersion.truncated_normal(sigma_rad, kTruncationSigmas);
  const double b = dispersion.truncated_normal(sigma_rad, kTruncationSigmas);
  return quat_from_rotation_vector(a * e1 + b * e2) * direction;
}

bool latch_open_for(const ThrusterHardware& hw, const ThrusterState& state, int thruster) {
  const int group = hw.group[static_cast<std::size_t>(thruster)];
  return group == model::kNoGroup || ((state.latch_closed_groups >> group) & 1U) == 0;
}

// Removes the intervals that closed at or before t_k (their whole effect lies in earlier periods).
void drop_finished(ValveSchedule& valve, TimeNs t_k) {
  int first_live = 0;
  while (first_live < valve.count && valve.pulses[first_live].close_ns <= t_k) ++first_live;
  if (first_live == 0) return;
  for (int j = first_live; j < valve.count; ++j) valve.pulses[j - first_live] = valve.pulses[j];
  valve.count -= first_live;
}

// Valve open time of the pulse commanded this period: the command if it reaches the minimum on-time,
// raised to the leak floor (eq. 5, cases 3: the leak is not a command, so no minimum applies to it).
TimeNs pulse_length_ns(const ThrusterHardware& hw, const ThrusterFaultEffect& effect, double ton) {
  const double period = static_cast<double>(hw.period_ns);
  const double ton_clamped = ton > 0.0 ? std::min(ton, 1.0) : 0.0;  // also maps NaN to 0
  // Most thrusters are off in most periods and have no leak: no rounding for them (llround(0) = 0).
  TimeNs on_ns = ton_clamped > 0.0 ? std::llround(ton_clamped * period) : 0;
  if (on_ns < hw.min_on_ns) on_ns = 0;
  if (effect.ton_floor > 0.0) on_ns = std::max(on_ns, static_cast<TimeNs>(std::llround(effect.ton_floor * period)));
  return on_ns;
}

// Adds the open interval [open, open + length) to the valve's union; returns the open time added.
TimeNs add_pulse(ValveSchedule& valve, TimeNs open_ns, TimeNs length_ns, TimeNs min_off_ns) {
  if (valve.count > 0) {
    ValveInterval& last = valve.pulses[valve.count - 1];
    assert(open_ns >= last.open_ns);  // holds for delays in [0, T)
    const bool merge = open_ns - last.close_ns < min_off_ns || valve.count == kMaxPulsesPerThruster;
    if (merge) {  // overlap or short gap: the valve stays open (the full-queue case never occurs)
      const TimeNs old_close = last.close_ns;
      last.close_ns = std::max(old_close, open_ns + length_ns);
      valve.last_close_ns = last.close_ns;
      return last.close_ns - old_close;
    }
  } else if (open_ns - valve.last_close_ns < min_off_ns) {
    open_ns = valve.last_close_ns + min_off_ns;  // closed before t_k: cannot reopen sooner
  }
  valve.pulses[valve.count++] = ValveInterval{open_ns, open_ns + length_ns};
  valve.last_close_ns = open_ns + length_ns;
  return length_ns;
}

void append_piece(const ThrusterHardware& hw, const FaultEffects& effects, Mask mask, TimeNs t_begin, TimeNs t_end,
                  ThrustProfile& out) {
  ThrustPiece& piece = out.pieces[static_cast<std::size_t>(out.count++)];
  piece.t_begin_ns = t_begin;
  piece.t_end_ns = t_end;
  piece.force_body_N.setZero();
  piece.torque_body_Nm.setZero();
  piece.mass_flow_kgps = 0.0;
  for (int i = 0; mask != 0; ++i, mask >>= 1) {
    if ((mask & 1U) == 0) continue;
    const double scale = effects[i].thrust_scale;
    piece.force_body_N += scale * hw.force_body_N[i];
    piece.torque_body_Nm += scale * hw.torque_body_Nm[i];
    piece.mass_flow_kgps += scale * hw.mass_flow_kgps[i];
  }
  out.propellant_kg += piece.mass_flow_kgps * to_seconds(t_end - t_begin);
}

// Valve openings and closings strictly inside the period, as sorted keys; thrusters already open at
// t_k go into *open_at_start.
int collect_events(const ThrusterHardware& hw, const ThrusterState& state, const FaultEffects& effects, TimeNs t_k,
                   TimeNs t_end, std::array<std::int64_t, kMaxThrustEvents>& keys, Mask* open_at_start) {
  int n = 0;
  *open_at_start = 0;
  for (int i = 0; i < hw.count; ++i) {
    if (state.valves[i].count == 0 && !effects[i].stuck_open) continue;  // no event, not open at t_k
    if (!latch_open_for(hw, state, i)) continue;
    const Mask bit = Mask{1} << i;
    if (effects[i].stuck_open) {
      *open_at_start |= bit;
      continue;
    }
    const ValveSchedule& valve = state.valves[i];
    for (int j = 0; j < valve.count && valve.pulses[j].open_ns < t_end; ++j) {
      const ValveInterval& p = valve.pulses[j];  // p.close_ns > t_k: finished ones were dropped
      if (p.open_ns <= t_k) *open_at_start |= bit;
      else keys[n++] = (p.open_ns - t_k) * kThrusterKeyBase + i;
      if (p.close_ns < t_end) keys[n++] = (p.close_ns - t_k) * kThrusterKeyBase + i;
    }
  }
  for (int a = 1; a < n; ++a) {  // insertion sort: n is a few tens
    const std::int64_t key = keys[a];
    int b = a;
    for (; b > 0 && keys[b - 1] > key; --b) keys[b] = keys[b - 1];
    keys[b] = key;
  }
  return n;
}

// Sweeps the sorted events; a piece ends where the set of thrusting valves changes, and only there.
void build_pieces(const ThrusterHardware& hw, const FaultEffects& effects, const ThrusterState& state, TimeNs t_k,
                  ThrustProfile& out) {
  const TimeNs t_end = t_k + hw.period_ns;
  std::array<std::int64_t, kMaxThrustEvents> keys;
  Mask mask = 0;
  const int n = collect_events(hw, state, effects, t_k, t_end, keys, &mask);
  out.count = 0;
  out.propellant_kg = 0.0;
  TimeNs piece_begin = t_k;
  for (int j = 0; j < n;) {
    const std::int64_t offset = keys[j] / kThrusterKeyBase;
    Mask next = mask;
    for (; j < n && keys[j] / kThrusterKeyBase == offset; ++j) next ^= Mask{1} << (keys[j] % kThrusterKeyBase);
    if (next == mask) continue;  // e.g. one interval closes where the next opens
    append_piece(hw, effects, mask, piece_begin, t_k + offset, out);
    piece_begin = t_k + offset;
    mask = next;
  }
  append_piece(hw, effects, mask, piece_begin, t_end, out);
}

}  // namespace

ThrusterHardware make_thruster_hardware(const model::ThrusterSetParams& set, const Vec3& com_body_m, double isp_s,
                                        TimeNs period_ns, RandomStream& dispersion) {
  ThrusterHardware hw;
  hw.count = set.count;
  hw.group.fill(model::kNoGroup);
  for (int i = 0; i < set.count; ++i) {
    model::ThrusterParams actual = set.thrusters[i];
    hw.group[i] = actual.group;
    actual.max_thrust_N *= 1.0 + dispersion.truncated_normal(set.thrust_sigma, kTruncationSigmas);
    actual.direction_body = misaligned_direction(actual.direction_body, set.misalignment_sigma_rad, dispersion);
    const Vec6 wrench = model::thruster_wrench(actual, com_body_m);
    hw.force_body_N[i] = wrench.head<3>();
    hw.torque_body_Nm[i] = wrench.tail<3>();
    hw.mass_flow_kgps[i] = actual.max_thrust_N / (isp_s * kStandardGravity);
  }
  hw.period_ns = period_ns;
  hw.rise_delay_ns = from_seconds(0.5 * set.rise_time_s);
  hw.min_on_ns = from_seconds(set.min_on_time_s);
  hw.min_off_ns = from_seconds(set.min_off_time_s);
  return hw;
}

void schedule_period(const ThrusterHardware& hardware, std::span<const model::FaultParams> faults,
                     ThrusterState& state, const model::ThrusterCommand& command, TimeNs t_k, TimeNs delay_ns,
                     ThrustProfile& out) {
  assert(delay_ns >= 0 && delay_ns < hardware.period_ns);
  // Without faults every effect is the default: no 32-entry table to fill each period.
  static const FaultEffects kNoFaults{};
  std::optional<FaultEffects> evaluated;
  if (!faults.empty()) evaluated.emplace(evaluate_faults(faults, t_k));
  const FaultEffects& effects = evaluated ? *evaluated : kNoFaults;
  const TimeNs open_ns = t_k + delay_ns + hardware.rise_delay_ns;  // eq. 1: same delay for all thrusters
  const double period = static_cast<double>(hardware.period_ns);
  for (int i = 0; i < hardware.count; ++i) {
    ValveSchedule& valve = state.valves[i];
    const ThrusterFaultEffect& effect = effects[i];
    if (valve.count == 0 && !(command.ton[i] > 0.0) && !effect.stuck_open && !(effect.ton_floor > 0.0)) {
      out.ton_realised[i] = 0.0;  // idle (most of 24, most periods): nothing pending, commanded or leaking
      continue;
    }
    drop_finished(valve, t_k);
    double realised = 0.0;
    if (effect.stuck_open || effect.blocked) {  // case 1: open throughout; case 2: closed from t_k
      valve.count = 0;
      realised = effect.stuck_open ? 1.0 : 0.0;
    } else {
      const TimeNs length_ns = pulse_length_ns(hardware, effect, command.ton[i]);
      const TimeNs added_ns = length_ns > 0 ? add_pulse(valve, open_ns, length_ns, hardware.min_off_ns) : 0;
      realised = effect.thrust_scale * static_cast<double>(added_ns) / period;  // eq. 5, case 4 as thrust level
    }
    out.ton_realised[i] = latch_open_for(hardware, state, i) ? realised : 0.0;
  }
  build_pieces(hardware, effects, state, t_k, out);
}

}  // namespace chaser::plant
