#include "flight/fdi/deficit_detector.hpp"

namespace chaser::flight::fdi {

std::vector<std::string> validate(const DeficitDetectorParams& p) {
  std::vector<std::string> problems;
  if (p.window < 2 || p.window > kMaxDeficitDetectorWindow)
    problems.push_back("window: must be in [2, " + std::to_string(kMaxDeficitDetectorWindow) + "] periods");
  if (!(p.threshold > 0.0)) problems.push_back("threshold: must be > 0");
  if (!(p.min_a >= 0.0) || !(p.min_b >= 0.0)) problems.push_back("min_a, min_b: must be >= 0");
  if (p.evaluate_every < 1 || (p.window >= 2 && p.window % p.evaluate_every != 0))
    problems.push_back("evaluate_every: must be >= 1 and divide window");
  return problems;
}

DeficitNormals8 window_normals(const DeficitDetectorBlock& sums) {
  DeficitNormals8 n = sums.sums;
  for (int i = 0; i < model::kThrustersPerBranch; ++i)
    if (sums.commanded(i) == 0) n(i, 1) = n(i, 2) = n(i, 4) = 0.0;
  return n;
}

void step_deficit_detector(const DeficitDetectorParams& p, const DeficitIsolationParams& bp,
                           const DeficitBankState& bank, DeficitDetectorState& state) {
  if (bank.count < 2) return;
  // The row of the previous sample: its period has ended with this sample's gyro reading.
  const DeficitSample& now = bank.ring[static_cast<std::size_t>((bank.count - 2) % kMaxDeficitWindow)];
  const Vec3& y = bank.last_torque_row;  // computed once by push_deficit_sample
  const Vec3 w = deficit_torque_weights(bp, bank, now.ton);
  // Per thruster i (c = M_C,i): c'Wc and c'Wy, as two 8 x 3 products.
  const Vec3 wy = w.cwiseProduct(y);
  const DeficitVec8 cc = bp.torque_body_Nm.cwiseAbs2().transpose() * w;
  const DeficitVec8 cy = bp.torque_body_Nm.transpose() * wy;
  const DeficitVec8& u = now.ton;
  state.block.commanded += (u.array() > 0.0).cast<std::int32_t>().matrix();
  DeficitSums& block = state.block.sums;
  block.col(0) += cc;
  block.col(1) += u.cwiseProduct(cc);
  block.col(2) += u.cwiseProduct(u).cwiseProduct(cc);
  block.col(3) += cy;
  block.col(4) += u.cwiseProduct(cy);
  ++state.rows;
  if (++state.phase < p.evaluate_every) return;
  // The block is complete: its slot, the oldest block's, takes it.
  state.phase = 0;
  DeficitDetectorBlock& oldest = state.ring[static_cast<std::size_t>(state.slot)];
  if (state.rows > p.window) {  // the oldest block leaves the window
    state.sums.sums -= oldest.sums;
    state.sums.commanded -= oldest.commanded;
  }
  oldest = state.block;
  state.sums.sums += state.block.sums;
  state.sums.commanded += state.block.commanded;
  state.block = DeficitDetectorBlock{};
  state.slot = (state.slot + 1) * p.evaluate_every < p.window ? state.slot + 1 : 0;

  if (state.alarm || state.rows < p.window) return;
  // statistic: the largest gain; suspect: its thruster, among the material fits when there are any
  // (then it is the one that raises the alarm).
  const DeficitFits fits = fit_deficits(window_normals(state.sums));
  state.statistic = 0.0;
  state.suspect = -1;
  double material_gain = -1.0;
  int material_suspect = -1;
  for (int i = 0; i < model::kThrustersPerBranch; ++i) {
    const double gain = fits.gain(i);
    if (gain > state.statistic) state.statistic = gain, state.suspect = i;
    if ((fits.a(i) >= p.min_a || fits.b(i) <= -p.min_b) && gain > material_gain) material_gain = gain, material_suspect = i;
  }
  if (material_suspect >= 0) state.suspect = material_suspect;
  if (material_gain > p.threshold) {
    state.alarm = true;
    state.alarm_sample = bank.count - 1;
  }
}

}  // namespace chaser::flight::fdi
