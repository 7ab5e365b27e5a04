#include "flight/fdi/deficit_detector.hpp"

#include <algorithm>


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

DeficitFits fit_deficits(const DeficitSums& sums) {
  // One lane per thruster; every candidate (free optimum, each face) is computed on every lane and
  // the answer selected, as fit_deficit decides it. Lanes that divide by zero are never selected.
  const double* haa = sums.col(0).data();
  const double* hab = sums.col(1).data();
  const double* hbb = sums.col(2).data();
  const double* ga = sums.col(3).data();
  const double* gb = sums.col(4).data();
  DeficitFits f;
  for (int i = 0; i < model::kThrustersPerBranch; ++i) {
    const double det = haa[i] * hbb[i] - hab[i] * hab[i];
    const double inv_det = 1.0 / det;
    const double a_free = (hbb[i] * ga[i] - hab[i] * gb[i]) * inv_det;
    const double b_free = (haa[i] * gb[i] - hab[i] * ga[i]) * inv_det;
    const double gain_free = a_free * ga[i] + b_free * gb[i];
    const double a_ratio = std::max(ga[i] / haa[i], 0.0), b_ratio = std::min(gb[i] / hbb[i], 0.0);
    const double a_only = haa[i] > 0.0 ? a_ratio : 0.0;
    const double b_only = hbb[i] > 0.0 ? b_ratio : 0.0;
    // std::max(0.0, x): +0 at the origin, never -0. (A select between a product and 0 would stop
    // the vectoriser: under -ftrapping-math it will not compute the product speculatively.)
    const double gain_a = std::max(0.0, a_only * ga[i]);
    const double gain_b = std::max(0.0, b_only * gb[i]);
    const bool b_face = gain_b > gain_a;
    double a = b_face ? 0.0 : a_only, b = b_face ? b_only : 0.0, gain = b_face ? gain_b : gain_a;
    // Nested, not &&: a short-circuit is a branch, and the loop would not vectorise.
    a = det > 0.0 ? (a_free >= 0.0 ? (b_free <= 0.0 ? a_free : a) : a) : a;
    b = det > 0.0 ? (a_free >= 0.0 ? (b_free <= 0.0 ? b_free : b) : b) : b;
    gain = det > 0.0 ? (a_free >= 0.0 ? (b_free <= 0.0 ? gain_free : gain) : gain) : gain;
    f.a(i) = a, f.b(i) = b, f.gain(i) = gain;
  }
  return f;
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
  // The slot of the oldest row takes the new one (written in place: no temporary to copy).
  DeficitSums& row = state.ring[static_cast<std::size_t>(state.slot)];
  if (state.rows >= p.window) state.sums -= row;  // the oldest row leaves the window
  row.col(0) = cc;
  row.col(1) = u.cwiseProduct(cc);
  row.col(2) = u.cwiseProduct(u).cwiseProduct(cc);
  row.col(3) = cy;
  row.col(4) = u.cwiseProduct(cy);
  state.sums += row;
  ++state.rows;
  state.slot = state.slot + 1 < p.window ? state.slot + 1 : 0;
  state.phase = state.phase + 1 < p.evaluate_every ? state.phase + 1 : 0;

  if (state.alarm || state.rows < p.window || state.phase != 0) return;
  // statistic: the largest gain; suspect: its thruster, among the material fits when there are any
  // (then it is the one that raises the alarm).
  const DeficitFits fits = fit_deficits(state.sums);
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
