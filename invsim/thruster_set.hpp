#pragma once
// The manual-RVD thruster set (Zhou 2018, Fig. 5): orbit engine, six bidirectional attitude
// thrusters a, a~, b, b~, c, c~ and twelve translation thrusters d1 ... f2~, with the switching
// logic of Table 1 derived from each thruster's (role, axis, sign) (see model/invsim.hpp).
//
// A fault shuts a thruster down from the start (section 3.1): the switching logic still opens it
// (the pilot and the logic do not know), it gives no force, torque or propellant flow. A healthy
// direction's pair balances its moments; a lost member leaves its partner's moment (Table 6).
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include "core/types.hpp"
#include "model/invsim.hpp"

namespace chaser::invsim {

// Body force and torque (about the centre of mass) of a set of open thrusters.
struct Wrench {
  Vec3 force_body_N = Vec3::Zero();
  Vec3 torque_body_Nm = Vec3::Zero();
  double thrust_sum_N = 0.0;  // [N] sum of the open thrusters' magnitudes (propellant flow)
};

// The switching signal of Table 1 for one thruster: +1 open (positive polarity), -1 open with
// negative polarity (attitude thrusters only), 0 closed. translation_cmd and attitude_cmd hold -1,
// 0 or +1 per body axis.
int switching_signal(const model::InvSimThruster& t, const std::array<int, 3>& translation_cmd,
                     const std::array<int, 3>& attitude_cmd);

// Force and torque of thruster t firing with polarity `signal` (+1 or -1) at full thrust.
Wrench thruster_wrench(const model::InvSimThruster& t, int signal);

// The healthy wrench of all translation thrusters answering `direction` (+1/-1) on body `axis`.
Wrench translation_wrench(const model::InvSimParams& p, const model::InvSimFaultSet& faults,
                          int axis, int direction);

// The healthy wrench of all attitude thrusters answering `direction` on body `axis`.
Wrench attitude_wrench(const model::InvSimParams& p, const model::InvSimFaultSet& faults, int axis,
                       int direction);

// Acceleration [m/s^2] along `axis` of the translation group of (axis, direction) with `faults`
// (0 when both of its thrusters failed): the u_max of the paper reading's faulted inverse model.
double translation_accel(const model::InvSimParams& p, const model::InvSimFaultSet& faults, int axis, int direction);

// Nominal acceleration [m/s^2] of the translation group of (axis, direction), all thrusters
// healthy: the u_max the pilot's pulse conversion assumes.
double nominal_translation_accel(const model::InvSimParams& p, int axis, int direction);

// The disturbing moment [N m] that losing thruster i leaves when its group fires (Table 6): minus
// its own moment. Zero for attitude thrusters and the engine.
Vec3 fault_disturbing_moment(const model::InvSimParams& p, std::size_t i);

// Index of the thruster named `name`, if any.
std::optional<std::size_t> find_thruster(const model::InvSimParams& p, std::string_view name);

}  // namespace chaser::invsim
