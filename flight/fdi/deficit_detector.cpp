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
  const DeficitCommandedRows commanded = (u.array() > 0.0).cast<std::int32_t>().matrix();
  DeficitSums& block = state.block.sums;
  // The first row of a block is assigned (not added to a zeroed block: zeroing 320 bytes compiles
  // to `rep stos`, whose start-up cost a sixth of the detector's time); 0 + x = x, the same sums.
  if (state.phase == 0) {
    state.block.commanded = commanded;
    block.col(0) = cc;
    block.col(1) = u.cwiseProduct(cc);
    block.col(2) = u.cwiseProduct(u).cwiseProduct(cc);
    block.col(3) = cy;
    block.col(4) = u.cwiseProduct(cy);
  } else {
    state.block.commanded += commanded;
    block.col(0) += cc;
    block.col(1) += u.cwiseProduct(cc);
    block.col(2) += u.cwiseProduct(u).cwiseProduct(cc);
    block.col(3) += cy;
    block.col(4) += u.cwiseProduct(cy);
  }
  ++state.rows;
  if (++state.phase < p.evaluate_every) return;
  // The block is complete: its slot, the oldest block's, takes it.
  state.phase = 0;
  DeficitDetectorBlock& oldest = state.ring[static_cast<std::size_t>(state.slot)];
  if (state.rows > p.window) {  // the oldest block leaves the window
    state.sums.sums -= oldest.sums;
    state.sums.commanded -= oldest.commanded;
  }
  // Member by member: a whole-struct copy compiles to `rep movs`, whose start-up cost more than the
  // copy (a quarter of the detector's time).
  oldest.sums = block;
  oldest.commanded = state.block.commanded;
  state.sums.sums += block;
  state.sums.commanded += state.block.commanded;
  // Every row in the window has u = 0 for such a thruster, so its u-columns are exactly zero: set
  // them so (in place, the rows leaving later subtract exact zeros), not the residue of its last pulse.
  for (int i = 0; i < model::kThrustersPerBranch; ++i)
    if (state.sums.commanded(i) == 0) state.sums.sums(i, 1) = state.sums.sums(i, 2) = state.sums.sums(i, 4) = 0.0;
  state.slot = (state.slot + 1) * p.evaluate_every < p.window ? state.slot + 1 : 0;

  if (state.alarm || state.rows < p.window) return;
  // statistic: the largest gain; suspect: its thruster, among the material fits when there are any
  // (then it is the one that raises the alarm).
  const DeficitFits fits = fit_deficits(state.sums.sums);
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
