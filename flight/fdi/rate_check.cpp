#include "flight/fdi/rate_check.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "flight/fdi/euler_torque.hpp"
#include "model/thruster_geometry.hpp"

namespace chaser::flight::fdi {

RateCheckParams make_rate_check_params(const model::RateCheckParams& keys, const model::ThrusterSetParams& thrusters,
                                       const Vec3& com_body_m, const Eigen::Matrix3d& inertia_kgm2, double period_s,
                                       double inertia_uncertainty) {
  RateCheckParams p;
  p.period_s = period_s;
  p.inertia_kgm2 = inertia_kgm2;
  p.inverse_inertia = inertia_kgm2.inverse();
  p.inverse_inertia_norm = p.inverse_inertia.operatorNorm();
  for (std::size_t i = 0; i < static_cast<std::size_t>(thrusters.count); ++i) {
    p.torque_Nm[i] = model::thruster_wrench(thrusters.thrusters[i], com_body_m).tail<3>();
    p.torque_norm_Nm[i] = p.torque_Nm[i].norm();
  }
  p.neighbours = keys.neighbours;
  p.threshold = keys.threshold;
  p.confirmations = keys.confirmations;
  p.stuck_closed_from = keys.stuck_closed_from;
  p.max_uncertainty = keys.max_uncertainty;
  p.inertia_uncertainty = inertia_uncertainty;
  p.shift_max_s = thrusters.delay_max_s + 0.5 * thrusters.rise_time_s;  // plant/thruster_hardware.cpp's opening
  return p;
}

double spill_bound_Nms(const RateCheckParams& p, const WatchedSet& set, const WatchedTon& ton) {
  double spill = 0;
  for (int lane = 0; lane < set.count; ++lane) {
    const double late_s = ton[lane] * p.period_s + p.shift_max_s - p.period_s;
    const int thruster = set.index[static_cast<std::size_t>(lane)];
    if (late_s > 0) spill += p.torque_norm_Nm[static_cast<std::size_t>(thruster)] * late_s;
  }
  return spill;
}

namespace {

std::size_t slot(std::int64_t k) { return static_cast<std::size_t>(k % kRateCheckRing); }

// [-] how far past [0, 1] a reading (or another thruster's fit) may lie and still be a deficit of
// its pulse: a stuck-closed reading's spread in a busy period, within max_uncertainty's default.
constexpr double kPlausibleExcess = 0.5;

// [-] the open share from which a missing pulse reads as a valve open already: twice the largest a
// fault-free comrade_sync flight's baselines give (0.038 over 1,526 checks), below the campaigns'
// smallest leak (0.1, model/campaign.hpp).
constexpr double kOpenFrom = 0.08;

// The median of count > 0 values (of an even count, the mean of the two middle ones).
double median(std::array<double, 2 * model::kMaxRateCheckNeighbours>& values, std::size_t count) {
  const auto mid = values.begin() + static_cast<std::ptrdiff_t>(count / 2);
  std::nth_element(values.begin(), mid, values.begin() + static_cast<std::ptrdiff_t>(count));
  return count % 2 == 1 ? *mid : 0.5 * (*mid + *std::max_element(values.begin(), mid));
}

// The check's period k and its neighbours without a check of their own (another check's pulse
// carries that thruster's deficit, and a dead thruster checked again and again would fill the window
// with it), with scratch room for their medians.
struct Window {
  const RateCheckParams& p;
  const RateCheckState& state;
  std::int64_t k;
  const RateCheckPeriod& pulse;
  std::array<std::int64_t, 2 * model::kMaxRateCheckNeighbours> quiet{};
  std::size_t count = 0;
  mutable std::array<double, 2 * model::kMaxRateCheckNeighbours> around{};

  Window(const RateCheckParams& params, const RateCheckState& s, std::int64_t period)
      : p(params), state(s), k(period), pulse(s.ring[slot(period)]) {
    for (std::int64_t i = k - p.neighbours; i <= k + p.neighbours; ++i)
      if (i != k && state.ring[slot(i)].checked == model::kNoThruster) quiet[count++] = i;
  }

  const RateCheckPeriod& neighbour(std::size_t c) const { return state.ring[slot(quiet[c])]; }

  // A thruster's on-time in the period beyond its median over the quiet neighbours: the baseline
  // holds the deficit of what it fires there too (a dead thruster the controller fires every period
  // is in every residual), so a reading sees only the excess. One off in the period and around it
  // has none, and no median to take.
  double excess_on_fraction(int thruster) const {
    const auto t = static_cast<std::size_t>(thruster);
    bool fired = pulse.on_fraction_all[t] != 0.0;
    for (std::size_t c = 0; c < count; ++c) {
      around[c] = neighbour(c).on_fraction_all[t];
      fired = fired || around[c] != 0.0;
    }
    return fired ? pulse.on_fraction_all[t] - median(around, count) : 0.0;
  }

  // The rate change a thruster's on-time gives.
  Vec3 rate_change(int thruster, double on_fraction) const {
    return p.period_s * on_fraction * (p.inverse_inertia * p.torque_Nm[static_cast<std::size_t>(thruster)]);
  }
};

// The other hypotheses for the residual e left by the check's pulse u (header, "Whose deficit"):
// every other thruster whose on-time the check's period changes, not in `excluded`. Sets the
// reading's culprit (a fit better than the checked thruster's by the margin) or rival (one as good).
void weigh_other_hypotheses(const Window& w, const Vec3& e, const Vec3& u, model::ThrusterMask excluded,
                            RateCheckReading& r) {
  const RateCheckParams& p = w.p;
  const double pulse_radps = std::sqrt(u.squaredNorm());
  const double margin_radps = 0.5 * p.threshold * pulse_radps;
  const double left_checked = (e + r.missing * u).norm();
  double best_left = left_checked;
  double rival_left = std::numeric_limits<double>::infinity();
  for (int i = 0; i < model::kMaxThrusters; ++i) {
    if (i == w.pulse.checked || (excluded & (model::ThrusterMask{1} << i))) continue;
    // Fired more than around the check (a canceller) or less (the allocation cancels the pulse by
    // cutting what the controller fires against it): either change carries a deficit's share.
    const double on_fraction = w.excess_on_fraction(i);
    if (on_fraction == 0.0) continue;
    const Vec3 u_i = w.rate_change(i, on_fraction);
    const double uu_i = u_i.squaredNorm();
    if (!(uu_i > 0)) continue;
    const double m_i = -u_i.dot(e) / uu_i;
    if (m_i < p.threshold || m_i > 1.0 + kPlausibleExcess || m_i * std::sqrt(uu_i) < p.threshold * pulse_radps)
      continue;
    const double left = (e + m_i * u_i).norm();
    if (left + margin_radps < best_left) {  // explains the residual better than the checked thruster
      best_left = left + margin_radps;
      r.culprit = i;
      r.culprit_missing = m_i;
    } else if (left < left_checked + margin_radps && left < rival_left) {
      rival_left = left;
      r.rival = i;
      r.rival_cut = on_fraction < 0.0;
    }
  }
  if (r.culprit != model::kNoThruster) {
    r.rival = model::kNoThruster;
    r.rival_cut = false;
  }
}

}  // namespace

RateCheckReading read_check(const RateCheckParams& p, const RateCheckState& state, std::int64_t k,
                            model::ThrusterMask excluded) {
  RateCheckReading r{.thruster = model::kNoThruster, .missing = std::numeric_limits<double>::quiet_NaN()};
  const RateCheckPeriod& pulse = state.ring[slot(k)];
  if (pulse.checked == model::kNoThruster || !(pulse.on_fraction_all[static_cast<std::size_t>(pulse.checked)] > 0))
    return r;
  // The baseline: the residuals' median, axis by axis, over the quiet neighbours; at least n of the 2n.
  const Window w(p, state, k);
  r.thruster = pulse.checked;
  r.uncertainty = std::numeric_limits<double>::infinity();  // inconclusive until read
  if (w.count < static_cast<std::size_t>(p.neighbours)) return r;
  const Vec3 u = w.rate_change(pulse.checked, w.excess_on_fraction(pulse.checked));
  const double uu = u.squaredNorm();
  if (!(uu > 0)) return r;  // the check fired no more than the controller does around it
  Vec3 baseline_radps;
  for (int axis = 0; axis < 3; ++axis) {
    for (std::size_t c = 0; c < w.count; ++c) w.around[c] = w.neighbour(c).residual_radps[axis];
    baseline_radps[axis] = median(w.around, w.count);
  }
  Vec3 torque_sum_Nm = Vec3::Zero();
  for (std::size_t c = 0; c < w.count; ++c) torque_sum_Nm += w.neighbour(c).torque_Nm;
  const Vec3 e = pulse.residual_radps - baseline_radps;
  const Vec3 full = w.rate_change(pulse.checked, 1.0);
  r.open_share = full.dot(baseline_radps) / full.squaredNorm();
  r.missing = -u.dot(e) / uu;
  // B_k: the inertia's error on the torque's change, the spills in and out (header).
  const Vec3 change_Nm = pulse.torque_Nm - torque_sum_Nm / static_cast<double>(w.count);
  const double spill_Nms = state.ring[slot(k - 1)].spill_Nms + pulse.spill_Nms;
  const double inertia_radps = p.inertia_uncertainty * p.period_s * (p.inverse_inertia * change_Nm).norm();
  r.uncertainty = (inertia_radps + p.inverse_inertia_norm * spill_Nms) / std::sqrt(uu);
  // A step in what the model leaves out inside the window (a leak's onset, a slosh strike): the
  // baseline takes one side's level and the pulse's period may sit on the other. The quiet
  // neighbours' readings before and after the pulse, each side's median, differ by the step.
  const auto side_median = [&](bool after) {
    std::size_t m = 0;
    for (std::size_t c = 0; c < w.count; ++c)
      if ((w.quiet[c] > k) == after) w.around[m++] = -u.dot(w.neighbour(c).residual_radps) / uu;
    return m == 0 ? std::numeric_limits<double>::quiet_NaN() : median(w.around, m);
  };
  const double step = std::abs(side_median(false) - side_median(true));
  r.uncertainty += std::isnan(step) ? 0.0 : step;
  weigh_other_hypotheses(w, e, u, excluded, r);
  return r;
}

namespace {

// Asks for `thruster`'s check again after the reading of period k, unless a later check of it is
// in flight: its reading will decide (checks of one thruster stay n + 2 periods apart, outside
// each other's neighbours).
void ask_recheck(RateCheckState& state, int thruster, std::int64_t k) {
  if (state.last_pulse[static_cast<std::size_t>(thruster)] <= k) state.recheck = thruster;
}

// The fault the confirming readings say (header, "Decision" and the open valve): their mean open
// share from kOpenFrom, a valve open already: stuck open from stuck_closed_from, else a leak of that
// share; else their mean reading: stuck closed from stuck_closed_from, else a loss of that mean.
void classify_confirmation(const RateCheckParams& p, RateCheckState& state) {
  const double n = state.in_a_row;
  const double open = state.open_sum / n;
  const bool valve_open = open >= kOpenFrom;
  const double size = std::clamp(valve_open ? open : state.sum / n, 0.0, 1.0);
  const bool whole = valve_open ? open >= p.stuck_closed_from : size >= p.stuck_closed_from;
  if (valve_open)
    state.kind = whole ? model::FaultKind::kStuckOpen : model::FaultKind::kLeak;
  else
    state.kind = whole ? model::FaultKind::kStuckClosed : model::FaultKind::kLoss;
  state.size = whole ? 1.0 : size;
}

void let_suspicion_go(RateCheckState& state) {
  state.suspect = state.recheck = model::kNoThruster;
  state.in_a_row = 0;
  state.sum = state.open_sum = 0;
  state.read_since = 0;
}

}  // namespace

int next_recheck(const RateCheckState& state) {
  return state.periods - state.last_any_pulse >= kRecheckSpacing ? state.recheck : model::kNoThruster;
}

RateCheckReading step_rate_check(const RateCheckParams& p, RateCheckState& state, const RateCheckInput& in) {
  const std::int64_t now = state.periods;
  // The period before is complete now that this one's rate is measured: Euler's equation over it.
  if (now > 0) {
    RateCheckPeriod& before = state.ring[slot(now - 1)];
    const Vec3 undone_Nm =
        euler_torque_Nm(p.inertia_kgm2, before.omega_radps, in.omega_body_radps, p.period_s) - before.torque_Nm;
    before.residual_radps = p.period_s * (p.inverse_inertia * undone_Nm);
  }
  RateCheckPeriod& period = state.ring[slot(now)];
  period = RateCheckPeriod{.omega_radps = in.omega_body_radps,
                           .torque_Nm = in.torque_cmd_body_Nm,
                           .checked = in.checked,
                           .spill_Nms = in.spill_Nms,
                           .on_fraction_all = in.on_fraction};
  state.periods = now + 1;
  if (in.checked != model::kNoThruster) {
    state.last_any_pulse = now;
    state.last_pulse[static_cast<std::size_t>(in.checked)] = now;
    if (in.checked == state.recheck) state.recheck = model::kNoThruster;
  }

  // Residuals are in up to period now - 1: the check n + 1 periods back has its neighbours.
  const int n = p.neighbours;
  const std::int64_t k = now - 1 - n;
  RateCheckReading reading;
  if (k < n) return reading;
  // The suspect stays a hypothesis for every reading: the likeliest culprit of another's residual.
  const model::ThrusterMask suspect_bit =
      state.suspect == model::kNoThruster ? 0 : model::ThrusterMask{1} << state.suspect;
  reading = read_check(p, state, k, state.read_since & ~suspect_bit);
  if (reading.thruster == model::kNoThruster) return reading;
  const int checked = reading.thruster;
  const double missing = reading.missing;
  state.last_reading = missing;
  if (state.confirmed != model::kNoThruster) return reading;  // latched: read on, decide no more
  const double bound = reading.uncertainty;
  // Inconclusive, the same check again: a loose bound, or a reading no deficit of this pulse can
  // give (the residual holds more than the pulse: a fault elsewhere the controller keeps firing).
  if (bound > p.max_uncertainty || missing < -kPlausibleExcess || missing > 1.0 + kPlausibleExcess) {
    ask_recheck(state, checked, k);
    return reading;
  }
  const model::ThrusterMask checked_bit = model::ThrusterMask{1} << checked;
  if (reading.culprit != model::kNoThruster) {  // another's deficit: its own check decides
    ask_recheck(state, reading.culprit, k);
    return reading;
  }
  if (missing - bound < p.threshold && missing + bound >= p.threshold) {  // the bound straddles it
    ask_recheck(state, checked, k);
    return reading;
  }
  if (missing < p.threshold) {
    if (checked == state.suspect) {
      let_suspicion_go(state);
    } else if (state.suspect != model::kNoThruster) {  // a rival read healthy: back to the suspect
      state.read_since |= checked_bit;
      ask_recheck(state, state.suspect, k);
    }
    return reading;
  }
  // A rival the period cut: a valve that did not close (a leak, stuck open) leaves what its cut
  // should have taken away, and reads as this pulse missing; its own pulse cannot tell, as its
  // valve opens. The reading decides nothing: this thruster's check again.
  if (reading.rival != model::kNoThruster && reading.rival_cut) {
    ask_recheck(state, checked, k);
    return reading;
  }
  // The suspect as the rival of another's reading: it stays the suspect, checked again.
  if (reading.rival != model::kNoThruster && reading.rival == state.suspect) {
    ask_recheck(state, state.suspect, k);
    return reading;
  }
  if (checked != state.suspect) {
    state.suspect = checked;
    state.in_a_row = 0;
    state.sum = state.open_sum = 0;
    state.suspect_pulse_s = in.t_s - static_cast<double>(now - k) * p.period_s;
  }
  state.read_since |= checked_bit;
  if (reading.rival != model::kNoThruster) {  // the rival's own check first; this reading waits
    ask_recheck(state, reading.rival, k);
    return reading;
  }
  ++state.in_a_row;
  state.sum += missing;
  state.open_sum += reading.open_share;
  if (state.in_a_row >= p.confirmations) {
    state.confirmed = state.suspect;
    state.confirmed_s = in.t_s;
    classify_confirmation(p, state);
    state.recheck = model::kNoThruster;
  } else {
    ask_recheck(state, state.suspect, k);
  }
  return reading;
}

}  // namespace chaser::flight::fdi
