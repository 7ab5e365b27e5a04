#include "control/robustness.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "control/frequency_response.hpp"

namespace chaser::control {
namespace {

using Eigen::MatrixXd;

// The margins of every grid point on a coarser sweep than a design's own (loop_margins adds the
// points around each lightly damped mode, and the bisections refine every crossing found), from
// omega_B / 100 up: the low-frequency end holds no crossing once the nominal loop has none there.
constexpr int kGridMarginPointsPerDecade = 40;

// y = b(a(u)): a's output drives b.
StateSpace series(const StateSpace& a, const StateSpace& b) {
  const Eigen::Index na = a.states(), nb = b.states();
  StateSpace s;
  s.a = MatrixXd::Zero(na + nb, na + nb);
  s.a.topLeftCorner(na, na) = a.a;
  s.a.bottomLeftCorner(nb, na) = b.b * a.c;
  s.a.bottomRightCorner(nb, nb) = b.a;
  s.b = MatrixXd(na + nb, a.inputs());
  s.b << a.b, b.b * a.d;
  s.c = MatrixXd(b.outputs(), na + nb);
  s.c << b.d * a.c, b.c;
  s.d = b.d * a.d;
  return s;
}

void check_box(const AxisUncertainty& box) {
  std::vector<std::string> problems;
  const auto need = [&](bool ok, const std::string& what) {
    if (!ok) problems.push_back(what);
  };
  need(box.gain_lo > 0.0 && box.gain_lo <= box.gain_hi && std::isfinite(box.gain_hi),
       fmt::format("gain range must satisfy 0 < lo <= hi (got [{}, {}])", box.gain_lo, box.gain_hi));
  need(box.delay_lo_s >= 0.0 && box.delay_lo_s <= box.delay_hi_s && std::isfinite(box.delay_hi_s),
       fmt::format("delay range must satisfy 0 <= lo <= hi (got [{}, {}])", box.delay_lo_s, box.delay_hi_s));
  need(box.points_per_range >= 2 && box.points_per_range <= 50,
       fmt::format("points_per_range must be in [2, 50] (got {})", box.points_per_range));
  for (const UncertainMode& m : box.modes) {
    need(m.frequency_lo_radps > 0.0 && m.frequency_lo_radps <= m.frequency_hi_radps && std::isfinite(m.frequency_hi_radps),
         fmt::format("mode '{}': frequency range must satisfy 0 < lo <= hi", m.name));
    need(m.modal_fraction >= 0.0 && m.modal_fraction < 1.0, fmt::format("mode '{}': modal_fraction must be in [0, 1)", m.name));
    need(m.damping >= 0.0 && m.damping < 1.0, fmt::format("mode '{}': damping must be in [0, 1)", m.name));
  }
  if (problems.empty()) return;
  std::string text = "robust_stability_grid:";
  for (const std::string& p : problems) text += "\n  " + p;
  throw std::invalid_argument(text);
}

// n values from lo to hi, equally spaced (geometrically when `geometric`); one when lo = hi.
std::vector<double> range_points(double lo, double hi, int n, bool geometric) {
  if (lo == hi) return {lo};
  std::vector<double> v(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const double f = static_cast<double>(i) / (n - 1);
    v[static_cast<std::size_t>(i)] = geometric ? lo * std::pow(hi / lo, f) : lo + f * (hi - lo);
  }
  return v;
}

// The true plant at a grid point without its delay: k / s^2 and the modes.
StateSpace rigid_and_modes(const GridPoint& pt, const AxisUncertainty& box) {
  StateSpace g = delayed_double_integrator(0.0, 0.0);
  g.c *= pt.gain;
  for (std::size_t i = 0; i < box.modes.size(); ++i)
    g = series(mode_factor(pt.mode_frequency_radps[i], box.modes[i].modal_fraction, box.modes[i].damping), g);
  return g;
}

void judge(const AxisDesign& design, const AxisUncertainty& box, const GridPoint& pt, RobustnessResult& r) {
  const StateSpace g = rigid_and_modes(pt, box);
  const GeneralisedPlant p = mixed_sensitivity_plant(series(pade_delay(pt.delay_s), g), design.weights);
  const double pole = max_real_pole(lower_lft(p.p, p.n_meas, p.n_ctrl, design.synthesis.controller));
  ++r.points;
  if (r.points == 1 || pole > r.worst_max_real_pole) {
    r.worst_max_real_pole = pole;
    r.worst_pole_point = pt;
  }
  if (!(pole < 0.0)) {
    ++r.unstable;
    return;
  }
  const AxisDesignSpec& spec = design.spec;
  const LoopMargins m =
      loop_margins({g, design.synthesis.controller, pt.delay_s}, 1e-2 * spec.bandwidth_radps,
                   margin_band_top_radps(spec.bandwidth_radps, pt.delay_s), kGridMarginPointsPerDecade);
  if (m.phase_margin_deg < r.min_phase_margin_deg) {
    r.min_phase_margin_deg = m.phase_margin_deg;
    r.min_phase_margin_point = pt;
  }
  r.min_gain_margin_up = std::min(r.min_gain_margin_up, m.gain_margin_up);
  r.max_gain_margin_down = std::max(r.max_gain_margin_down, m.gain_margin_down);
}

}  // namespace

StateSpace mode_factor(double frequency_radps, double modal_fraction, double damping) {
  const double wz = frequency_radps, r = 1.0 / (1.0 - modal_fraction), wp2 = r * wz * wz;
  const double num1 = 2.0 * damping * wz, den1 = 2.0 * damping * wp2 / wz;  // the header's c on both
  // F = r (s^2 + num1 s + wz^2) / (s^2 + den1 s + wp^2) = r + r ((num1 - den1) s + (wz^2 - wp^2)) / (...)
  StateSpace f;
  f.a = (MatrixXd(2, 2) << 0.0, 1.0, -wp2, -den1).finished();
  f.b = (MatrixXd(2, 1) << 0.0, 1.0).finished();
  f.c = (MatrixXd(1, 2) << r * (wz * wz - wp2), r * (num1 - den1)).finished();
  f.d = MatrixXd::Constant(1, 1, r);
  return f;
}

RobustnessResult robust_stability_grid(const AxisDesign& design, const AxisUncertainty& box) {
  check_box(box);
  if (!design.synthesis.ok()) throw std::invalid_argument("robust_stability_grid: the axis has no controller");
  const int n = box.points_per_range;
  std::vector<std::vector<double>> axes{range_points(box.gain_lo, box.gain_hi, n, true),
                                        range_points(box.delay_lo_s, box.delay_hi_s, n, false)};
  for (const UncertainMode& m : box.modes) axes.push_back(range_points(m.frequency_lo_radps, m.frequency_hi_radps, n, true));

  RobustnessResult r;
  r.min_phase_margin_deg = std::numeric_limits<double>::infinity();
  r.min_gain_margin_up = std::numeric_limits<double>::infinity();
  std::vector<std::size_t> index(axes.size(), 0);  // an odometer over the grid
  for (;;) {
    GridPoint pt{axes[0][index[0]], axes[1][index[1]], {}};
    for (std::size_t i = 2; i < axes.size(); ++i) pt.mode_frequency_radps.push_back(axes[i][index[i]]);
    judge(design, box, pt, r);
    std::size_t d = 0;
    while (d < axes.size() && ++index[d] == axes[d].size()) index[d++] = 0;
    if (d == axes.size()) break;
  }
  return r;
}

}  // namespace chaser::control
