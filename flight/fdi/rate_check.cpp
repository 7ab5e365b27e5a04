#include "flight/fdi/rate_check.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

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
  for (int i = 0; i < thrusters.count; ++i)
    p.torque_Nm[static_cast<std::size_t>(i)] =
        model::thruster_wrench(thrusters.thrusters[static_cast<std::size_t>(i)], com_body_m).tail<3>();
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
    if (late_s > 0) spill += p.torque_Nm[static_cast<std::size_t>(thruster)].norm() * late_s;
  }
  return spill;
}

namespace {

std::size_t slot(std::int64_t k) { return static_cast<std::size_t>(k % kRateCheckRing); }

}  // namespace

RateCheckReading read_check(const RateCheckParams& p, const RateCheckState& state, std::int64_t k) {
  RateCheckReading r{.thruster = model::kNoThruster, .missing = std::numeric_limits<double>::quiet_NaN()};
  const RateCheckPeriod& pulse = state.ring[slot(k)];
  if (pulse.checked == model::kNoThruster || !(pulse.on_fraction > 0)) return r;
  // u_j: the rate change of the whole commanded pulse.
  const Vec3& torque_Nm = p.torque_Nm[static_cast<std::size_t>(pulse.checked)];
  const Vec3 u = p.period_s * pulse.on_fraction * (p.inverse_inertia * torque_Nm);
  const double uu = u.squaredNorm();
  if (!(uu > 0)) return r;
  const auto missing = [&](std::int64_t i) { return -u.dot(state.ring[slot(i)].residual_radps) / uu; };
  std::array<double, 2 * model::kMaxRateCheckNeighbours> around{};
  const int n = p.neighbours;
  std::size_t count = 0;
  Vec3 torque_sum_Nm = Vec3::Zero();
  for (std::int64_t i = k - n; i <= k + n; ++i) {
    if (i == k) continue;
    around[count++] = missing(i);
    torque_sum_Nm += state.ring[slot(i)].torque_Nm;
  }
  // The median of an even count: the mean of the two middle values.
  const auto mid = around.begin() + static_cast<std::ptrdiff_t>(count / 2);
  std::nth_element(around.begin(), mid, around.begin() + static_cast<std::ptrdiff_t>(count));
  const double upper = *mid;
  const double lower = *std::max_element(around.begin(), mid);
  r.thruster = pulse.checked;
  r.missing = missing(k) - 0.5 * (lower + upper);
  // B_k: the inertia's error on the torque's change, the spills in and out (header).
  const Vec3 change_Nm = pulse.torque_Nm - torque_sum_Nm / static_cast<double>(count);
  const double spill_Nms = state.ring[slot(k - 1)].spill_Nms + pulse.spill_Nms;
  const double inertia_radps = p.inertia_uncertainty * p.period_s * (p.inverse_inertia * change_Nm).norm();
  r.uncertainty = (inertia_radps + p.inverse_inertia_norm * spill_Nms) / std::sqrt(uu);
  return r;
}

RateCheckReading step_rate_check(const RateCheckParams& p, RateCheckState& state, const RateCheckInput& in) {
  const std::int64_t now = state.periods;
  // The period before is complete now that this one's rate is measured: Euler's equation over it.
  if (now > 0) {
    RateCheckPeriod& before = state.ring[slot(now - 1)];
    const Vec3 gyroscopic_Nm = before.omega_radps.cross(p.inertia_kgm2 * before.omega_radps);
    before.residual_radps = in.omega_body_radps - before.omega_radps -
                            p.period_s * (p.inverse_inertia * (before.torque_Nm - gyroscopic_Nm));
  }
  state.ring[slot(now)] = RateCheckPeriod{.omega_radps = in.omega_body_radps,
                                          .torque_Nm = in.torque_cmd_body_Nm,
                                          .checked = in.checked,
                                          .on_fraction = in.checked == model::kNoThruster ? 0.0 : in.checked_on_fraction,
                                          .spill_Nms = in.spill_Nms};
  state.periods = now + 1;
  if (in.checked != model::kNoThruster && in.checked == state.recheck) state.recheck = model::kNoThruster;

  // Residuals are in up to period now - 1: the check n + 1 periods back has its neighbours.
  const int n = p.neighbours;
  const std::int64_t k = now - 1 - n;
  RateCheckReading reading;
  if (k < n) return reading;
  reading = read_check(p, state, k);
  if (reading.thruster == model::kNoThruster) return reading;
  const double missing = reading.missing;
  state.last_reading = missing;
  if (state.confirmed != model::kNoThruster) return reading;  // latched: read on, decide no more
  if (reading.uncertainty > p.max_uncertainty) {  // inconclusive: the same check again
    state.recheck = reading.thruster;
    return reading;
  }

  if (missing >= p.threshold) {
    if (reading.thruster != state.suspect) {
      state.suspect = reading.thruster;
      state.in_a_row = 0;
      state.sum = 0;
      state.suspect_pulse_s = in.t_s - static_cast<double>(now - k) * p.period_s;
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
  } else if (reading.thruster == state.suspect) {
    state.suspect = state.recheck = model::kNoThruster;
    state.in_a_row = 0;
    state.sum = 0;
  }
  return reading;
}

}  // namespace chaser::flight::fdi
