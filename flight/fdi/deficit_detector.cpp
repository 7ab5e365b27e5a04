#include "flight/fdi/deficit_detector.hpp"

namespace chaser::flight::fdi {

std::vector<std::string> validate(const DeficitDetectorParams& p) {
  std::vector<std::string> problems;
  if (p.window < 2 || p.window > kMaxDeficitDetectorWindow)
    problems.push_back("window: must be in [2, " + std::to_string(kMaxDeficitDetectorWindow) + "] periods");
  if (!(p.threshold > 0.0)) problems.push_back("threshold: must be > 0");
  if (!(p.min_a >= 0.0) || !(p.min_b >= 0.0)) problems.push_back("min_a, min_b: must be >= 0");
  if (p.evaluate_every < 1) problems.push_back("evaluate_every: must be >= 1");
  return problems;
}

void step_deficit_detector(const DeficitDetectorParams& p, const DeficitIsolationParams& bp,
                           const DeficitBankState& bank, DeficitDetectorState& state) {
  if (bank.count < 2) return;
  // The row of the previous sample: its period has ended with this sample's gyro reading.
  const DeficitSample& now = bank.ring[static_cast<std::size_t>((bank.count - 2) % kMaxDeficitWindow)];
  const Vec3& y = bank.last_torque_row;  // computed once by push_deficit_sample
  const Vec3 w = deficit_torque_weights(bp, bank, now.ton);
  DeficitSums row;
  for (int i = 0; i < model::kThrustersPerBranch; ++i) {
    const Vec3 wc = w.cwiseProduct(bp.torque_body_Nm.col(i));
    const double cc = wc.dot(bp.torque_body_Nm.col(i)), cy = wc.dot(y), u = now.ton(i);
    row.col(i) << cc, u * cc, u * u * cc, cy, u * cy;
  }
  DeficitSums& slot = state.ring[static_cast<std::size_t>(state.rows % p.window)];
  if (state.rows >= p.window) state.sums -= slot;  // the oldest row leaves the window
  state.sums += row;
  slot = row;
  ++state.rows;

  if (state.alarm || state.rows < p.window || state.rows % p.evaluate_every != 0) return;
  // statistic: the largest gain; suspect: its thruster, among the material fits when there are any
  // (then it is the one that raises the alarm).
  state.statistic = 0.0;
  state.suspect = -1;
  double material_gain = -1.0;
  int material_suspect = -1;
  for (int i = 0; i < model::kThrustersPerBranch; ++i) {
    const auto s = state.sums.col(i);
    const DeficitFit fit = fit_deficit({.haa = s(0), .hab = s(1), .hbb = s(2), .ga = s(3), .gb = s(4)});
    if (fit.gain > state.statistic) state.statistic = fit.gain, state.suspect = i;
    if ((fit.a >= p.min_a || fit.b <= -p.min_b) && fit.gain > material_gain) material_gain = fit.gain, material_suspect = i;
  }
  if (material_suspect >= 0) state.suspect = material_suspect;
  if (material_gain > p.threshold) {
    state.alarm = true;
    state.alarm_sample = bank.count - 1;
  }
}

}  // namespace chaser::flight::fdi
