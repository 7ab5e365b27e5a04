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

// The median of an even count of values: the mean of the two middle ones.
double median(std::array<double, 2 * model::kMaxRateCheckNeighbours>& values, std::size_t count) {
  const auto mid = values.begin() + static_cast<std::ptrdiff_t>(count / 2);
  std::nth_element(values.begin(), mid, values.begin() + static_cast<std::ptrdiff_t>(count));
  return 0.5 * (*mid + *std::max_element(values.begin(), mid));
}

}  // namespace

RateCheckReading read_check(const RateCheckParams& p, const RateCheckState& state, std::int64_t k,
                            model::ThrusterMask excluded) {
  RateCheckReading r{.thruster = model::kNoThruster, .missing = std::numeric_limits<double>::quiet_NaN()};
  const RateCheckPeriod& pulse = state.ring[slot(k)];
  if (pulse.checked == model::kNoThruster || !(pulse.on_fraction > 0)) return r;
  // The rate change a thruster's commanded on-time gives.
  const auto rate_change = [&](int thruster, double on_fraction) -> Vec3 {
    return p.period_s * on_fraction * (p.inverse_inertia * p.torque_Nm[static_cast<std::size_t>(thruster)]);
  };
  const Vec3 u = rate_change(pulse.checked, pulse.on_fraction);
  const double uu = u.squaredNorm();
  if (!(uu > 0)) return r;
  // The baseline: the neighbours' residuals' median, axis by axis.
  const int n = p.neighbours;
  Vec3 baseline_radps;
  std::array<double, 2 * model::kMaxRateCheckNeighbours> around{};
  std::size_t count = 0;
  for (int axis = 0; axis < 3; ++axis) {
    count = 0;
    for (std::int64_t i = k - n; i <= k + n; ++i)
      if (i != k) around[count++] = state.ring[slot(i)].residual_radps[axis];
    baseline_radps[axis] = median(around, count);
  }
  Vec3 torque_sum_Nm = Vec3::Zero();
  for (std::int64_t i = k - n; i <= k + n; ++i)
    if (i != k) torque_sum_Nm += state.ring[slot(i)].torque_Nm;
  const Vec3 e = pulse.residual_radps - baseline_radps;
  r.thruster = pulse.checked;
  r.missing = -u.dot(e) / uu;
  // B_k: the inertia's error on the torque's change, the spills in and out (header).
  const Vec3 change_Nm = pulse.torque_Nm - torque_sum_Nm / static_cast<double>(count);
  const double spill_Nms = state.ring[slot(k - 1)].spill_Nms + pulse.spill_Nms;
  const double inertia_radps = p.inertia_uncertainty * p.period_s * (p.inverse_inertia * change_Nm).norm();
  r.uncertainty = (inertia_radps + p.inverse_inertia_norm * spill_Nms) / std::sqrt(uu);

  // The other hypotheses: every other thruster commanded in the period (header, "Whose deficit").
  const double pulse_radps = std::sqrt(uu);
  const double margin_radps = 0.5 * p.threshold * pulse_radps;
  const double left_checked = (e + r.missing * u).norm();
  double best_left = left_checked;
  double rival_left = std::numeric_limits<double>::infinity();
  for (int i = 0; i < model::kMaxThrusters; ++i) {
    const double on_fraction = pulse.on_fraction_all[static_cast<std::size_t>(i)];
    if (i == pulse.checked || !(on_fraction > 0) || (excluded & (model::ThrusterMask{1} << i))) continue;
    const Vec3 u_i = rate_change(i, on_fraction);
    const double uu_i = u_i.squaredNorm();
    if (!(uu_i > 0)) continue;
    const double m_i = -u_i.dot(e) / uu_i;
    if (m_i < p.threshold || m_i > 1.5 || m_i * std::sqrt(uu_i) < p.threshold * pulse_radps) continue;
    const double left = (e + m_i * u_i).norm();
    if (left + margin_radps < best_left) {  // explains the residual better than the checked thruster
      best_left = left + margin_radps;
      r.culprit = i;
      r.culprit_missing = m_i;
    } else if (left < left_checked + margin_radps && left < rival_left) {
      rival_left = left;
      r.rival = i;
    }
  }
  if (r.culprit != model::kNoThruster) r.rival = model::kNoThruster;
  return r;
}

namespace {

void let_suspicion_go(RateCheckState& state) {
  state.suspect = state.recheck = model::kNoThruster;
  state.in_a_row = 0;
  state.sum = 0;
  state.read_since = 0;
}

}  // namespace

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
                           .on_fraction = in.checked == model::kNoThruster ? 0.0 : in.checked_on_fraction,
                           .spill_Nms = in.spill_Nms,
                           .on_fraction_all = in.on_fraction};
  if (in.checked != model::kNoThruster)  // the check's own on-time, whatever the caller's list says
    period.on_fraction_all[static_cast<std::size_t>(in.checked)] = period.on_fraction;
  state.periods = now + 1;
  if (in.checked != model::kNoThruster && in.checked == state.recheck) state.recheck = model::kNoThruster;

  // Residuals are in up to period now - 1: the check n + 1 periods back has its neighbours.
  const int n = p.neighbours;
  const std::int64_t k = now - 1 - n;
  RateCheckReading reading;
  if (k < n) return reading;
  reading = read_check(p, state, k, state.read_since);
  if (reading.thruster == model::kNoThruster) return reading;
  const int checked = reading.thruster;
  const double missing = reading.missing;
  state.last_reading = missing;
  if (state.confirmed != model::kNoThruster) return reading;  // latched: read on, decide no more
  if (reading.uncertainty > p.max_uncertainty) {  // inconclusive: the same check again
    state.recheck = checked;
    return reading;
  }
  const model::ThrusterMask checked_bit = model::ThrusterMask{1} << checked;
  if (reading.culprit != model::kNoThruster) {  // another's deficit: its own check decides
    state.recheck = reading.culprit;
    return reading;
  }
  if (missing < p.threshold) {
    if (checked == state.suspect) {
      let_suspicion_go(state);
    } else if (state.suspect != model::kNoThruster) {  // a rival read healthy: back to the suspect
      state.read_since |= checked_bit;
      state.recheck = state.suspect;
    }
    return reading;
  }
  if (checked != state.suspect) {
    state.suspect = checked;
    state.in_a_row = 0;
    state.sum = 0;
    state.suspect_pulse_s = in.t_s - static_cast<double>(now - k) * p.period_s;
  }
  state.read_since |= checked_bit;
  if (reading.rival != model::kNoThruster) {  // the rival's own check first; this reading waits
    state.recheck = reading.rival;
    return reading;
  }
  ++state.in_a_row;
  state.sum += missing;
  if (state.in_a_row >= p.confirmations) {
    state.confirmed = state.suspect;
    state.confirmed_s = in.t_s;
    state.size = std::clamp(state.sum / state.in_a_row, 0.0, 1.0);
    state.kind = state.size >= p.stuck_closed_from ? model::FaultKind::kStuckClosed : model::FaultKind::kLoss;
    if (state.kind == model::FaultKind::kStuckClosed) state.size = 1.0;
    state.recheck = model::kNoThruster;
  } else {
    state.recheck = state.suspect;
  }
  return reading;
}

}  // namespace chaser::flight::fdi
