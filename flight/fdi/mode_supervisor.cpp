#include "flight/fdi/mode_supervisor.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "flight/fdi/design/uio_bank.hpp"

namespace chaser::flight::fdi {

const char* to_string(SupervisorFault fault) {
  switch (fault) {
    case SupervisorFault::kStuckOpen: return "stuck_open";
    case SupervisorFault::kStuckClosed: return "stuck_closed";
    case SupervisorFault::kNone: break;
  }
  return "none";
}

SupervisorParams make_supervisor(const UioBank& design, const std::vector<int>& column_thruster,
                                 const std::vector<int>& monitored, const Eigen::Matrix3d& inertia_kgm2,
                                 const SupervisorKeys& k) {
  const auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  if (!positive(k.period_s) || !positive(k.forgetting_s) || !positive(k.bias_s) || !positive(k.dwell_s) ||
      !(std::isfinite(k.settle_s) && k.settle_s >= 0.0) || !(std::isfinite(k.hysteresis) && k.hysteresis >= 0.0) ||
      !(std::isfinite(k.floor_radps) && k.floor_radps >= 0.0))
    throw std::invalid_argument("supervisor: period, forgetting_s, bias_s and dwell_s must be > 0; settle_s, "
                                "hysteresis and floor_radps >= 0");
  if (static_cast<Eigen::Index>(column_thruster.size()) != design.Bd.cols())
    throw std::invalid_argument("supervisor: one thruster index per model column");
  SupervisorParams p;
  p.n = static_cast<int>(design.Ad.rows());
  p.Bd = design.Bd;
  p.Ed = design.Ed;
  p.C = design.C;
  p.N = design.nominal.N;
  p.update.resize(p.n, p.n + 3);
  p.update << design.nominal.N, design.nominal.L;
  p.column_of.fill(-1);
  for (std::size_t c = 0; c < column_thruster.size(); ++c) {
    const int t = column_thruster[c];
    if (t < 0 || t >= model::kMaxThrusters) throw std::invalid_argument("supervisor: a thruster index out of range");
    p.column_of[static_cast<std::size_t>(t)] = static_cast<int>(c);
  }
  p.modes.push_back(SupervisorMode{});
  for (const int t : monitored) {
    if (t < 0 || t >= model::kMaxThrusters || p.column_of[static_cast<std::size_t>(t)] < 0)
      throw std::invalid_argument("supervisor: monitored thruster " + std::to_string(t + 1) +
                                  " is not in the rate model's active set");
    for (const SupervisorMode& m : p.modes)
      if (m.thruster == t) throw std::invalid_argument("supervisor: thruster " + std::to_string(t + 1) + " twice");
    const int c = p.column_of[static_cast<std::size_t>(t)];
    p.modes.push_back({.thruster = t, .column = c, .fault = SupervisorFault::kStuckOpen, .on_fraction = 1.0});
    p.modes.push_back({.thruster = t, .column = c, .fault = SupervisorFault::kStuckClosed, .on_fraction = 0.0});
  }
  p.inertia_kgm2 = inertia_kgm2;
  p.forget = std::exp(-k.period_s / k.forgetting_s);
  p.bias_forget = std::exp(-k.period_s / k.bias_s);
  p.settle_periods = std::llround(k.settle_s / k.period_s);
  p.dwell_periods = std::max<std::int64_t>(1, std::llround(k.dwell_s / k.period_s));
  p.hysteresis = k.hysteresis;
  p.floor_sq = k.floor_radps * k.floor_radps;
  return p;
}

SupervisorState make_supervisor_state(const SupervisorParams& p) {
  SupervisorState s;
  const auto modes = static_cast<Eigen::Index>(p.modes.size());
  s.z = Eigen::VectorXd::Zero(p.n);
  s.delta = Eigen::MatrixXd::Zero(p.n, modes);
  s.mu = Eigen::VectorXd::Zero(modes);
  s.u = Eigen::VectorXd::Zero(p.Bd.cols());
  s.known = Eigen::VectorXd::Zero(p.n);
  s.v = Eigen::VectorXd::Zero(p.n + 3);
  s.next = Eigen::VectorXd::Zero(p.n);
  return s;
}

bool step_supervisor(const SupervisorParams& p, SupervisorState& s, double t_s, const Vec3& y,
                     const model::ThrusterOnTimes& on_times) {
  if (!s.started) {  // x_hat = [y; 0]: C = [I, C_modes] reads y from it
    s.z.setZero();
    s.z.head<3>() = y;
    s.started = true;
  }
  for (int t = 0; t < model::kMaxThrusters; ++t) {
    const int c = p.column_of[static_cast<std::size_t>(t)];
    if (c >= 0) s.u(c) = on_times[static_cast<std::size_t>(t)];
  }
  const Vec3 gyroscopic_Nm = -y.cross(p.inertia_kgm2 * y);
  s.known.noalias() = p.Bd * s.u;
  s.known.noalias() += p.Ed * gyroscopic_Nm;
  s.v.head(p.n) = s.z;
  s.v.tail<3>() = y;
  const Vec3 r0 = y - p.C * s.z;  // the nominal's residual (Q = I, H = 0)
  s.z = s.known;
  s.z.noalias() += p.update * s.v;

  const bool settled = s.period >= p.settle_periods;
  const Vec3 r_flown = s.mode == 0 ? r0 : Vec3(r0 - p.C * s.delta.col(s.mode));
  s.bias = s.period == 0 ? r_flown : Vec3(p.bias_forget * s.bias + (1.0 - p.bias_forget) * r_flown);
  const double gain = 1.0 - p.forget;
  s.mu(0) = p.forget * s.mu(0) + gain * (r0 - s.bias).squaredNorm();
  for (std::size_t m = 1; m < p.modes.size(); ++m) {
    const SupervisorMode& mode = p.modes[m];
    auto delta = s.delta.col(static_cast<Eigen::Index>(m));
    const Vec3 r = r0 - p.C * delta;
    s.mu(static_cast<Eigen::Index>(m)) = p.forget * s.mu(static_cast<Eigen::Index>(m)) + gain * (r - s.bias).squaredNorm();
    // The mode's input differs from the command in its thruster's on-time alone.
    const double du = mode.on_fraction - s.u(mode.column);
    s.next.noalias() = p.N * delta;
    delta = s.next + p.Bd.col(mode.column) * du;
  }
  ++s.period;
  if (!settled || s.period - s.last_switch_period < p.dwell_periods) return false;
  Eigen::Index best = 0;
  s.mu.minCoeff(&best);
  if (static_cast<int>(best) == s.mode || !((1.0 + p.hysteresis) * s.mu(best) + p.floor_sq < s.mu(s.mode))) return false;
  s.mode = static_cast<int>(best);
  s.last_switch_period = s.period;
  if (s.switches < kMaxSupervisorSwitches)
    s.log[static_cast<std::size_t>(s.switches)] = {.t_s = t_s, .mode = s.mode};
  ++s.switches;
  return true;
}

}  // namespace chaser::flight::fdi
