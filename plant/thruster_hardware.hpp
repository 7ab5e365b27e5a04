#pragma once
// Thruster hardware: valve timing, drive-electronics delay, rise time, minimum on/off times, latch
// valves, dispersion and faults (Fonod 2015, section II.C-D, eqs. 1-5).
//
// Per control period k (t_k = k T), flight commands scaled on-times ton_i in [0, 1]. The valve of
// thruster i opens at t_k + tau(k) + rise/2 and closes ton_i T later (eqs. 1-2: one delay tau(k) for
// all thrusters, drawn by the caller in [0, delay_max) from its stream "thrusters/delay"). The plant
// receives the resulting force and torque as a piecewise-constant profile that tiles [t_k, t_k + T]
// exactly, so the propagator integrates each piece to its edges.
//
// Rise time: a pulse whose thrust ramps linearly from 0 to full over rise_time after the opening
// command, and back down over the same time after the closing command, is a trapezoid; the
// rectangle of the same commanded length delayed by rise_time/2 has the same impulse and the same
// centroid (both are symmetric about the same mid-time). Only second moments differ, by O(rise^2),
// so the ramp is modelled by that equivalent delay.
//
// Valve rules, per thruster:
//  - a pulse that ends after t_{k+1} continues into the next period(s); overlapping pulses give the
//    union of their open intervals;
//  - a command with ton_i T < min_on_time does not open the valve (a leak floor still does: the leak
//    is not a command);
//  - if the next opening follows the previous closing by less than min_off_time, the valve stays
//    open through the gap. When that previous closing already happened before t_k (it lies in a
//    period whose profile is gone) the valve cannot have stayed open; it cannot reopen before
//    closing + min_off_time either, so the opening is postponed to then, keeping its length;
//  - a closed latch valve (one per redundancy group) cuts the flow of its whole group, including a
//    stuck-open thruster; a thruster in no group has no latch. Latches act from the next
//    schedule_period call (its t_k on).
// Faults: see plant/thruster_faults.hpp (evaluated at t_k).
//
// Preconditions (validated by the scenario, not here): 0 <= delay < T; period, rise, min on/off
// times are whole nanoseconds.
#include <array>
#include <cstdint>
#include <limits>
#include <span>

#include "core/random.hpp"
#include "core/time.hpp"
#include "core/types.hpp"
#include "model/faults.hpp"
#include "model/messages.hpp"
#include "model/thrusters.hpp"

namespace chaser::plant {

inline constexpr int kMaxPulsesPerThruster = 4;  // pending open intervals; delay < T needs at most 3
inline constexpr int kMaxThrustEvents = 2 * kMaxPulsesPerThruster * model::kMaxThrusters;
inline constexpr int kMaxPieces = kMaxThrustEvents + 1;

// Constant for a run: the actual (dispersed) thrusters and the valve timing.
struct ThrusterHardware {
  int count = 0;                                             // N thrusters, entries [0, N) used
  std::array<Vec3, model::kMaxThrusters> force_body_N{};    // [N] full-thrust force, dispersed
  std::array<Vec3, model::kMaxThrusters> torque_body_Nm{};  // [N m] about the true centre of mass
  std::array<double, model::kMaxThrusters> mass_flow_kgps{};  // [kg/s] at full thrust: F / (isp g0)
  std::array<int, model::kMaxThrusters> group{};            // latch group, model::kNoGroup: none
  TimeNs period_ns = 0;      // [ns] control period T
  TimeNs rise_delay_ns = 0;  // [ns] rise_time / 2, the ramp's equivalent delay
  TimeNs min_on_ns = 0;      // [ns]
  TimeNs min_off_ns = 0;     // [ns]
};

// Draws the per-run dispersion once from `dispersion` (stream "thrusters/dispersion"), thruster by
// thruster: thrust scale 1 + thrust_sigma N(0,1), then a misalignment rotation about two axes
// perpendicular to the nominal direction (a rotation about the direction changes nothing), each
// misalignment_sigma_rad N(0,1); all truncated at 3 sigma. Zero sigmas draw nothing and give the
// nominal forces exactly. Torques are about com_body_m (the true centre of mass).
ThrusterHardware make_thruster_hardware(const model::ThrusterSetParams& set, const Vec3& com_body_m, double isp_s,
                                        TimeNs period_ns, RandomStream& dispersion);

struct ValveInterval {
  TimeNs open_ns = 0;   // [ns] absolute
  TimeNs close_ns = 0;  // [ns] absolute, > open_ns
};

// Open intervals of one valve that have not finished yet, sorted, disjoint, separated by at least
// min_off_time.
struct ValveSchedule {
  std::array<ValveInterval, kMaxPulsesPerThruster> pulses{};
  int count = 0;
  TimeNs last_close_ns = std::numeric_limits<TimeNs>::min() / 2;  // [ns] end of the latest interval
};

struct ThrusterState {
  std::array<ValveSchedule, model::kMaxThrusters> valves{};
  std::uint32_t latch_closed_groups = 0;  // bit g set: group g's latch valve is closed
};

// One constant piece of the thrust profile.
struct ThrustPiece {
  TimeNs t_begin_ns = 0;                // [ns]
  TimeNs t_end_ns = 0;                  // [ns]
  Vec3 force_body_N = Vec3::Zero();     // [N]
  Vec3 torque_body_Nm = Vec3::Zero();   // [N m] about the true centre of mass
  double mass_flow_kgps = 0.0;          // [kg/s] propellant consumed
};

struct ThrustProfile {
  std::array<ThrustPiece, kMaxPieces> pieces{};  // pieces[0..count) tile [t_k, t_k + T]
  int count = 0;
  // Impulse-equivalent scaled on-time of the pulse commanded this period (eq. 5's phi_i, after the
  // minimum on-time, the leak floor and the thrust loss): open time it adds to the valve's union of
  // intervals (including a min-off gap it fills, excluding overlap with earlier pulses), times the
  // thrust scale, over T. 1 for a stuck-open thruster, 0 for a blocked one or a closed latch.
  model::ThrusterOnTimes ton_realised{};
  double propellant_kg = 0.0;  // [kg] consumed over [t_k, t_k + T]
};

// Schedules the pulses commanded at t_k with drive-electronics delay delay_ns and writes the force
// and torque profile over [t_k, t_k + T]. Call once per period, in order. Allocation-free.
void schedule_period(const ThrusterHardware& hardware, std::span<const model::FaultParams> faults,
                     ThrusterState& state, const model::ThrusterCommand& command, TimeNs t_k, TimeNs delay_ns,
                     ThrustProfile& out);

}  // namespace chaser::plant
