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

DeficitNormalsW deficit_normals(const DeficitIsolationParams& bp, const DeficitDetectorBlock& sums) {
  // Rows [0, lanes) only; haa_i = sum_a c_ai^2 W_a and ga_i = sum_a c_ai (W y)_a summed over the
  // axes in order, as Eigen's fixed-size products of the eight-lane detector did.
  DeficitNormalsW n;
  const Vec3& w = sums.weight_sum;
  const Vec3& wy = sums.weighted_row_sum;
  with_lanes(bp.lanes, [&](auto lanes) {
    for (int i = 0; i < lanes; ++i) {
      const auto c = bp.torque_body_Nm.col(i);
      n(i, 0) = c(0) * c(0) * w(0) + c(1) * c(1) * w(1) + c(2) * c(2) * w(2);
      n(i, 1) = sums.command(i, 0);
      n(i, 2) = sums.command(i, 1);
      n(i, 3) = c(0) * wy(0) + c(1) * wy(1) + c(2) * wy(2);
      n(i, 4) = sums.command(i, 2);
    }
  });
  return n;
}

namespace {

// Adds the row of a period with on-times u and weights w to `block`.
void add_row(const DeficitIsolationParams& bp, const Vec3& y, const Vec3& w, const WatchedTon& u,
             DeficitDetectorBlock& block) {
  const Vec3 wy = w.cwiseProduct(y);
  block.weight_sum += w, block.weighted_row_sum += wy;
  with_lanes(bp.lanes, [&](auto lanes) {
    for (int i = 0; i < lanes; ++i) {
      if (!(u(i) > 0.0)) continue;  // the row adds nothing to thruster i's command sums
      const auto c = bp.torque_body_Nm.col(i);
      const double cwc = c.cwiseAbs2().dot(w), cwy = c.dot(wy);
      block.command(i, 0) += u(i) * cwc;
      block.command(i, 1) += u(i) * u(i) * cwc;
      block.command(i, 2) += u(i) * cwy;
      ++block.commanded(i);
    }
  });
}

// The complete block enters the window and takes the oldest block's slot; the oldest leaves the
// window if `leaves`. Whole columns of the set's lanes (N of them, or `lanes` when N is Dynamic):
// the rows of a lane not commanded in a block are exact zeros, so adding or removing them changes
// nothing, and a branch per lane would mispredict (which lanes pulsed changes from block to block).
template <int N>
void enter_block(int lanes, bool leaves, DeficitDetectorBlock& sums, DeficitDetectorBlock& oldest,
                 DeficitDetectorBlock& block) {
  const auto command = [lanes](DeficitDetectorBlock& b) {
    if constexpr (N == Eigen::Dynamic) return b.command.topRows(lanes); else return b.command.template topRows<N>();
  };
  const auto commanded = [lanes](DeficitDetectorBlock& b) {
    if constexpr (N == Eigen::Dynamic) return b.commanded.head(lanes); else return b.commanded.template head<N>();
  };
  if (leaves) {
    sums.weight_sum -= oldest.weight_sum, sums.weighted_row_sum -= oldest.weighted_row_sum;
    command(sums) -= command(oldest), commanded(sums) -= commanded(oldest);
  }
  sums.weight_sum += block.weight_sum, sums.weighted_row_sum += block.weighted_row_sum;
  command(sums) += command(block), commanded(sums) += commanded(block);
  oldest.weight_sum = block.weight_sum, oldest.weighted_row_sum = block.weighted_row_sum;
  command(oldest) = command(block), commanded(oldest) = commanded(block);
  // The next block starts empty. Only the command rows it used are zeroed: zeroing the whole block
  // compiles to `rep stos`, whose start-up costs more than the detector's additions.
  block.weight_sum.setZero(), block.weighted_row_sum.setZero();
  for (int i = 0; i < (N == Eigen::Dynamic ? lanes : N); ++i) {
    if (block.commanded(i) != 0) block.command.row(i).setZero();
    // A thruster not commanded in the window: every row has u = 0, so its command sums are exactly
    // zero. Set them so (in place: the rows leaving later subtract exact zeros), not the residue of
    // its last pulse.
    if (sums.commanded(i) == 0) sums.command.row(i).setZero();
  }
  commanded(block).setZero();
}

}  // namespace

void step_deficit_detector(const DeficitDetectorParams& p, const DeficitIsolationParams& bp,
                           const DeficitBankState& bank, DeficitDetectorState& state) {
  if (bank.count < 2) return;
  // The row of the previous sample: its period has ended with this sample's gyro reading.
  const DeficitSample& now = bank.ring[static_cast<std::size_t>((bank.count - 2) % kMaxDeficitWindow)];
  const Vec3 weights = deficit_torque_weights(bp, bank, now, deficit_commands_before(bank, bank.count - 2));
  add_row(bp, bank.last_torque_row, weights, now.ton, state.block);
  ++state.rows;
  if (++state.phase < p.evaluate_every) return;
  // The block is complete: its slot, the oldest block's, takes it.
  state.phase = 0;
  DeficitDetectorBlock& oldest = state.ring[static_cast<std::size_t>(state.slot)];
  DeficitDetectorBlock& sums = state.sums;
  DeficitDetectorBlock& block = state.block;
  if (bp.lanes == kSchemeThrusters)
    enter_block<kSchemeThrusters>(bp.lanes, state.rows > p.window, sums, oldest, block);
  else
    enter_block<Eigen::Dynamic>(bp.lanes, state.rows > p.window, sums, oldest, block);
  state.slot = (state.slot + 1) * p.evaluate_every < p.window ? state.slot + 1 : 0;

  if (state.alarm || state.rows < p.window) return;
  // statistic: the largest gain; suspect: its thruster, among the material fits when there are any
  // (then it is the one that raises the alarm).
  const DeficitFits fits = fit_deficits(deficit_normals(bp, state.sums), bp.lanes);
  // Selects, not branches: which gain leads changes from one evaluation to the next, and a
  // mispredicted branch per thruster cost more than the fits.
  double statistic = 0.0, material_gain = -1.0;
  int suspect = -1, material_suspect = -1;
  for (int i = 0; i < bp.lanes; ++i) {
    const double gain = fits.gain(i);
    const bool leads = gain > statistic;
    statistic = leads ? gain : statistic;
    suspect = leads ? i : suspect;
    const bool material_leads = ((fits.a(i) >= p.min_a) | (fits.b(i) <= -p.min_b)) & (gain > material_gain);
    material_gain = material_leads ? gain : material_gain;
    material_suspect = material_leads ? i : material_suspect;
  }
  state.statistic = statistic;
  state.suspect = material_suspect >= 0 ? material_suspect : suspect;
  state.material_statistic = material_suspect >= 0 ? material_gain : 0.0;
  if (material_gain > p.threshold) {
    state.alarm = true;
    state.alarm_sample = bank.count - 1;
  }
}

}  // namespace chaser::flight::fdi
