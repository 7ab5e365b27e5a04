#include "flight/fdi/impulse_detector.hpp"

#include <algorithm>
#include <cmath>

namespace chaser::flight::fdi {

std::vector<std::string> validate(const ImpulseDetectorParams& p) {
  std::vector<std::string> problems;
  if (p.block < 1) problems.emplace_back("block must be >= 1");
  if (p.window_blocks < 1) problems.emplace_back("window_blocks must be >= 1");
  if (p.baseline_blocks < 1) problems.emplace_back("baseline_blocks must be >= 1");
  if (p.window_blocks + p.baseline_blocks > model::kMaxImpulseBlocks)
    problems.emplace_back("window_blocks + baseline_blocks must be <= " + std::to_string(model::kMaxImpulseBlocks));
  if (!(p.threshold_Nms > 0.0)) problems.emplace_back("threshold_Nms must be > 0");
  return problems;
}

void step_impulse_detector(const ImpulseDetectorParams& p, const DeficitIsolationParams& bp,
                           const DeficitBankState& bank, ImpulseDetectorState& state) {
  if (bank.count < 2) return;  // the first row needs two samples
  // The row of the previous sample (its period ended with this sample's gyro) and its command.
  const DeficitSample& now = bank.ring[static_cast<std::size_t>((bank.count - 2) % kMaxDeficitWindow)];
  ImpulseBlock& open = state.open_block;
  open.row_Nm += bank.last_torque_row;
  for (int i = 0; i < bp.lanes; ++i) {
    if (now.ton(i) == 0.0) continue;  // most periods command few thrusters
    open.force_N += now.ton(i) * bp.force_body_N.col(i);
    open.torque_Nm += now.ton(i) * bp.torque_body_Nm.col(i);
  }
  if (++state.phase < p.block) return;
  state.phase = 0;
  const int span = p.window_blocks + p.baseline_blocks;
  state.ring[static_cast<std::size_t>(state.slot)] = open;
  open = {};
  state.slot = state.slot + 1 < span ? state.slot + 1 : 0;
  ++state.blocks;
  if (state.alarm || state.blocks < span) return;
  // The ring is full and `slot` is its oldest block: the first L blocks from there are the baseline,
  // the W after them the window. Summed afresh each block (W + L additions): no running sum to drift.
  ImpulseBlock baseline, window;
  for (int j = 0; j < span; ++j) {
    const ImpulseBlock& b = state.ring[static_cast<std::size_t>((state.slot + j) % span)];
    ImpulseBlock& sum = j < p.baseline_blocks ? baseline : window;
    sum.row_Nm += b.row_Nm, sum.force_N += b.force_N, sum.torque_Nm += b.torque_Nm;
  }
  const double ratio = static_cast<double>(p.window_blocks) / p.baseline_blocks;
  const auto change = [&](const Vec3& w, const Vec3& b) { return Vec3(bp.period_s * (w - ratio * b)); };
  state.change_Nms = change(window.row_Nm, baseline.row_Nm);
  const Vec3 dF = change(window.force_N, baseline.force_N).cwiseAbs();
  const Vec3 dtau = change(window.torque_Nm, baseline.torque_Nm).cwiseAbs();
  state.bound_Nms = bp.com_uncertainty_m * Vec3(dF.y() + dF.z(), dF.z() + dF.x(), dF.x() + dF.y()) +
                    bp.inertia_uncertainty * dtau;
  state.statistic = std::max(0.0, (state.change_Nms.cwiseAbs() - state.bound_Nms).maxCoeff());
  double best = -1.0;
  for (int i = 0; i < bp.lanes; ++i) {
    const Vec3 c = bp.torque_body_Nm.col(i);
    const double norm = c.norm();
    if (norm == 0.0) continue;  // a pure-force thruster: the torque rows say nothing of it
    const double alignment = std::abs(c.dot(state.change_Nms)) / norm;
    if (alignment > best) best = alignment, state.suspect = i;
  }
  if (state.statistic > p.threshold_Nms) {
    state.alarm = true;
    state.alarm_sample = bank.count - 1;
  }
}

}  // namespace chaser::flight::fdi
