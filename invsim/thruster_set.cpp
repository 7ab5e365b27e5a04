#include "invsim/thruster_set.hpp"

#include <cmath>

namespace chaser::invsim {

using model::InvSimThruster;
using model::InvSimThrusterRole;

int switching_signal(const InvSimThruster& t, const std::array<int, 3>& translation_cmd,
                     const std::array<int, 3>& attitude_cmd) {
  switch (t.role) {
    case InvSimThrusterRole::kTranslation:  // unidirectional: opens for its own sign only
      return translation_cmd[t.axis] == t.sign ? 1 : 0;
    case InvSimThrusterRole::kAttitude:  // bidirectional: a couple with its partner
      return t.sign * attitude_cmd[t.axis];
    case InvSimThrusterRole::kEngine:
      return 0;
  }
  return 0;
}

Wrench thruster_wrench(const InvSimThruster& t, int signal) {
  Wrench w;
  w.force_body_N = static_cast<double>(signal) * t.thrust_N * t.direction_body;
  w.torque_body_Nm = t.position_body_m.cross(w.force_body_N);
  return w;
}

namespace {

Wrench group_wrench(const model::InvSimParams& p, const model::InvSimFaultSet& faults,
                    const std::array<int, 3>& translation_cmd, const std::array<int, 3>& attitude_cmd) {
  Wrench sum;
  for (std::size_t i = 0; i < p.thrusters.size(); ++i) {
    if (faults.failed(i)) continue;
    const int signal = switching_signal(p.thrusters[i], translation_cmd, attitude_cmd);
    if (signal == 0) continue;
    const Wrench w = thruster_wrench(p.thrusters[i], signal);
    sum.force_body_N += w.force_body_N;
    sum.torque_body_Nm += w.torque_body_Nm;
    sum.thrust_sum_N += p.thrusters[i].thrust_N;
  }
  return sum;
}

}  // namespace

Wrench translation_wrench(const model::InvSimParams& p, const model::InvSimFaultSet& faults,
                          int axis, int direction) {
  std::array<int, 3> cmd{0, 0, 0};
  cmd[axis] = direction;
  return group_wrench(p, faults, cmd, {0, 0, 0});
}

Wrench attitude_wrench(const model::InvSimParams& p, const model::InvSimFaultSet& faults, int axis,
                       int direction) {
  std::array<int, 3> cmd{0, 0, 0};
  cmd[axis] = direction;
  return group_wrench(p, faults, {0, 0, 0}, cmd);
}

double translation_accel(const model::InvSimParams& p, const model::InvSimFaultSet& faults, int axis, int direction) {
  const Wrench w = translation_wrench(p, faults, axis, direction);
  return std::abs(w.force_body_N[axis]) / p.mass_kg;
}

double nominal_translation_accel(const model::InvSimParams& p, int axis, int direction) {
  return translation_accel(p, model::InvSimFaultSet{}, axis, direction);
}

Vec3 fault_disturbing_moment(const model::InvSimParams& p, std::size_t i) {
  const InvSimThruster& t = p.thrusters[i];
  if (t.role != InvSimThrusterRole::kTranslation) return Vec3::Zero();
  return -thruster_wrench(t, 1).torque_body_Nm;
}

std::optional<std::size_t> find_thruster(const model::InvSimParams& p, std::string_view name) {
  for (std::size_t i = 0; i < p.thrusters.size(); ++i)
    if (p.thrusters[i].name == name) return i;
  return std::nullopt;
}

}  // namespace chaser::invsim
