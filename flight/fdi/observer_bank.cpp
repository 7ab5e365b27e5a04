#include "flight/fdi/observer_bank.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "flight/fdi/design/uio_bank.hpp"

namespace chaser::flight::fdi {

namespace {

ObserverBankObserver flight_observer(const UioObserver& o, const Eigen::MatrixXd& Bd, const Eigen::MatrixXd& C) {
  ObserverBankObserver f;
  const Eigen::Index n = o.N.rows();
  f.update.resize(n, n + 6);
  f.update << o.N, o.L, -o.H;
  f.residual.resize(o.Q.rows(), n + 3);
  f.residual << -o.Q * C, o.Q * (Eigen::Matrix3d::Identity() - C * o.H);
  if (o.thruster >= 0) f.torque_direction = (C * Bd.col(o.thruster)).normalized();
  return f;
}

// The nominal's residual occupies rows [0, 3) of the window, observer c's [3 + 2c, 5 + 2c), and
// column c's on-time row 3 + 2 columns + c.
int residual_row(int column) { return 3 + 2 * column; }
int on_time_row(const ObserverBankFlightParams& p, int column) { return 3 + 2 * p.columns + column; }
int wrench_row(const ObserverBankFlightParams& p) { return 3 + 3 * p.columns; }  // force (3), then torque (3)

// One observer's residual and update with v = [z; y; C known] (see ObserverBankObserver); known =
// Bd u + Ed tau is shared by every observer (G = T Bd and T Ed are never formed).
void step_observer(const ObserverBankObserver& o, Eigen::VectorXd& z, ObserverBankState& s,
                   Eigen::Ref<Eigen::VectorXd> r) {
  const Eigen::Index n = z.size();
  s.v.head(n) = z;
  r.noalias() = o.residual * s.v.head(n + 3);
  z = s.known;
  z.noalias() += o.update * s.v;
}

// The new block enters W; W's oldest moves into L; L's oldest leaves the ring.
void push_block(const ObserverBankFlightParams& p, ObserverBankState& s) {
  const int capacity = p.window_blocks + p.baseline_blocks;
  if (s.filled == capacity) {
    s.baseline_sum -= s.ring.col(s.head);  // L's oldest
    s.head = (s.head + 1) % capacity;
    --s.filled;
  }
  if (s.filled >= p.window_blocks) {  // W's oldest becomes L's newest
    const int w_oldest = (s.head + s.filled - p.window_blocks) % capacity;
    s.window_sum -= s.ring.col(w_oldest);
    s.baseline_sum += s.ring.col(w_oldest);
  }
  s.ring.col((s.head + s.filled) % capacity) = s.block;
  s.window_sum += s.block;
  ++s.filled;
}

// The change of observer c's mean residual (rows [first, first + size)), W against L.
double change(const ObserverBankFlightParams& p, const ObserverBankState& s, int first, int size) {
  const double w = 1.0 / (static_cast<double>(p.window_blocks) * p.block);
  const double l = 1.0 / (static_cast<double>(p.baseline_blocks) * p.block);
  return (s.window_sum.segment(first, size) * w - s.baseline_sum.segment(first, size) * l).norm();
}

// Every block once the ring is full: the alarm, then the hypotheses (see the header).
void decide(const ObserverBankFlightParams& p, ObserverBankState& s) {
  const double w = 1.0 / (static_cast<double>(p.window_blocks) * p.block);
  const double l = 1.0 / (static_cast<double>(p.baseline_blocks) * p.block);
  const auto change_of = [&](int first) {
    return Vec3(s.window_sum.segment<3>(first) * w - s.baseline_sum.segment<3>(first) * l);
  };
  const Vec3 nominal_change = change_of(0);
  s.nominal_change_radps = nominal_change.norm();
  // As torque, against the bound the model's errors make of the commanded wrench's change.
  const Vec3 torque_Nm = p.inertia_kgm2 * nominal_change / p.period_s;
  const Vec3 dF = change_of(wrench_row(p)).cwiseAbs(), dtau = change_of(wrench_row(p) + 3).cwiseAbs();
  s.statistic_Nm = 0.0;
  for (int a = 0; a < 3; ++a) {
    const double bound = p.com_uncertainty_m * (dF((a + 1) % 3) + dF((a + 2) % 3)) + p.inertia_uncertainty * dtau(a);
    s.statistic_Nm = std::max(s.statistic_Nm, std::abs(torque_Nm(a)) - bound);
  }
  // Each observer's change, once: the smallest goes to telemetry, all of them to the hypotheses.
  std::array<double, model::kMaxThrusters> observer_change{};
  s.smallest_change_radps = std::numeric_limits<double>::infinity();
  for (int c = 0; c < p.columns; ++c) {
    observer_change[static_cast<std::size_t>(c)] = change(p, s, residual_row(c), 2);
    s.smallest_change_radps = std::min(s.smallest_change_radps, observer_change[static_cast<std::size_t>(c)]);
  }
  if (!s.alarm && s.statistic_Nm > p.threshold_Nm) {
    s.alarm = true;
    s.alarm_period = s.period - 1;
  }
  if (!s.alarm || s.confirmed >= 0) return;

  s.hypotheses = 0;
  int best = -1, count = 0;
  double best_change = std::numeric_limits<double>::infinity();
  for (int c = 0; c < p.columns; ++c) {
    const double d = observer_change[static_cast<std::size_t>(c)];
    if (!(d < p.isolation_ratio * s.nominal_change_radps)) continue;
    const double along = nominal_change.dot(p.observers[static_cast<std::size_t>(c)].torque_direction);
    const bool commanded = s.window_sum(on_time_row(p, c)) * w > p.min_commanded;
    if (along < 0.0 && !commanded) continue;  // too little from a thruster never asked for anything
    const int thruster = p.thruster_of[static_cast<std::size_t>(c)];
    s.hypotheses |= model::ThrusterMask{1} << thruster;
    ++count;
    if (d < best_change) best_change = d, best = thruster;
  }
  s.streak = count == 1 && best == s.candidate ? s.streak + 1 : (count == 1 ? 1 : 0);
  s.candidate = best;
  if (count == 1 && s.streak >= p.confirm_blocks) s.confirmed = best;
}

}  // namespace

ObserverBankFlightParams make_observer_bank(const UioBank& d, const std::vector<int>& column_thruster,
                                            const Eigen::Matrix3d& inertia_kgm2, const ObserverBankWindows& win) {
  if (static_cast<Eigen::Index>(column_thruster.size()) != d.Bd.cols())
    throw std::invalid_argument("observer bank: one thruster index per model column");
  if (win.block < 1 || win.window_blocks < 1 || win.baseline_blocks < 1 || !(win.threshold_Nm > 0) ||
      !(win.isolation_ratio > 0 && win.isolation_ratio < 1) || !(win.period_s > 0) || !(win.com_uncertainty_m >= 0) ||
      !(win.inertia_uncertainty >= 0))
    throw std::invalid_argument("observer bank: block, window and baseline >= 1, threshold > 0, ratio in (0, 1), "
                                "period > 0, uncertainties >= 0");
  ObserverBankFlightParams p;
  p.n = static_cast<int>(d.Ad.rows());
  p.columns = static_cast<int>(d.Bd.cols());
  p.column_of.fill(-1);
  p.thruster_of = column_thruster;
  for (int c = 0; c < p.columns; ++c) {
    const int t = column_thruster[static_cast<std::size_t>(c)];
    if (t < 0 || t >= model::kMaxThrusters) throw std::invalid_argument("observer bank: a thruster index out of range");
    p.column_of[static_cast<std::size_t>(t)] = c;
  }
  p.Bd = d.Bd;
  p.Ed = d.Ed;
  p.C = d.C;
  p.nominal = flight_observer(d.nominal, d.Bd, d.C);
  for (const UioObserver& o : d.observers) p.observers.push_back(flight_observer(o, d.Bd, d.C));
  p.inertia_kgm2 = inertia_kgm2;
  p.block = win.block;
  p.window_blocks = win.window_blocks;
  p.baseline_blocks = win.baseline_blocks;
  p.threshold_Nm = win.threshold_Nm;
  p.isolation_ratio = win.isolation_ratio;
  p.period_s = win.period_s;
  p.com_uncertainty_m = win.com_uncertainty_m;
  p.inertia_uncertainty = win.inertia_uncertainty;
  return p;
}

ObserverBankState make_observer_bank_state(const ObserverBankFlightParams& p) {
  ObserverBankState s;
  s.z.assign(static_cast<std::size_t>(p.columns) + 1, Eigen::VectorXd::Zero(p.n));
  const int rows = 3 + 3 * p.columns + 6;
  s.ring = Eigen::MatrixXd::Zero(rows, p.window_blocks + p.baseline_blocks);
  s.row = Eigen::VectorXd::Zero(rows);
  s.block = Eigen::VectorXd::Zero(rows);
  s.window_sum = Eigen::VectorXd::Zero(rows);
  s.baseline_sum = Eigen::VectorXd::Zero(rows);
  s.u = Eigen::VectorXd::Zero(p.columns);
  s.known = Eigen::VectorXd::Zero(p.n);
  s.v = Eigen::VectorXd::Zero(p.n + 6);
  return s;
}

void restart_observer_bank(ObserverBankState& s) {
  s.ring.setZero();
  s.block.setZero();
  s.window_sum.setZero();
  s.baseline_sum.setZero();
  s.in_block = s.head = s.filled = 0;
  s.period = 0;
  s.alarm = false;
  s.alarm_period = -1;
  s.nominal_change_radps = s.smallest_change_radps = 0;
  s.hypotheses = 0;
  s.candidate = s.confirmed = -1;
  s.streak = 0;
}

void step_observer_bank(const ObserverBankFlightParams& p, ObserverBankState& s, const Vec3& y, const WatchedSet& set,
                        const WatchedTon& lanes, const Vec6& commanded_wrench) {
  if (!s.started) {  // x_hat = [y; 0] (C = [I, C_modes] reads y from it): z = x_hat - H y
    for (std::size_t o = 0; o < s.z.size(); ++o) {
      const ObserverBankObserver& obs = o == 0 ? p.nominal : p.observers[o - 1];
      s.z[o].setZero();
      s.z[o].head<3>() = y;
      // z = x_hat - H y; the update's last three columns are -H.
      s.z[o].noalias() += obs.update.rightCols<3>() * y;
    }
    s.started = true;
  }
  s.u.setZero();
  for (int lane = 0; lane < set.count; ++lane) {
    const int c = p.column_of[static_cast<std::size_t>(set.index[static_cast<std::size_t>(lane)])];
    if (c >= 0) s.u(c) = lanes[lane];
  }
  // The known inputs: the commands and the gyroscopic torque from the measured rates.
  const Vec3 gyroscopic_Nm = -y.cross(p.inertia_kgm2 * y);
  s.known.noalias() = p.Bd * s.u;
  s.known.noalias() += p.Ed * gyroscopic_Nm;
  s.v.segment<3>(p.n) = y;
  s.v.tail<3>().noalias() = p.C * s.known;

  step_observer(p.nominal, s.z[0], s, s.row.head<3>());
  for (int c = 0; c < p.columns; ++c)
    step_observer(p.observers[static_cast<std::size_t>(c)], s.z[static_cast<std::size_t>(c) + 1], s,
                  s.row.segment(residual_row(c), 2));
  s.row.segment(on_time_row(p, 0), p.columns) = s.u;
  s.row.segment<3>(wrench_row(p)) = commanded_wrench.head<3>();
  s.row.segment<3>(wrench_row(p) + 3) = Vec3(commanded_wrench.tail<3>()) + gyroscopic_Nm;

  ++s.period;
  s.block += s.row;
  if (++s.in_block < p.block) return;
  push_block(p, s);
  s.block.setZero();
  s.in_block = 0;
  if (s.filled < p.window_blocks + p.baseline_blocks) return;
  decide(p, s);
}

}  // namespace chaser::flight::fdi
