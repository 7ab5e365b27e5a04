#include "control/loop_mu.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "control/frequency_response.hpp"
#include "control/loop_margins.hpp"

namespace chaser::control {
namespace {

// The grid starts two decades below the controller's slowest pole, and at most at 1e-4 omega_B (the
// design's own margin band): the near-integral action makes a loop conditionally stable there, and
// its low phase crossover (the downward gain margin) lies below the slowest pole.
constexpr double kGridBottomPerBandwidth = 1e-4;
constexpr double kGridBottomPerSlowestPole = 1e-2;
constexpr double kPeakLogTolerance = 1e-6;        // golden section on ln w: the bound itself is ~1e-6
constexpr int kMaxGoldenSteps = 60;

// Both bounds at one frequency; the first AB13MD failure is kept in `out`.
struct MuPair {
  double complex_bound = 0.0, mixed_bound = 0.0;
};

MuPair bounds_at(const AxisDesign& design, const LoopUncertaintyLft& lft, double w, LoopMu& out) {
  const Eigen::MatrixXcd m = loop_interconnection(design, lft, w);
  const MuBound c = mu_upper_bound(m, {{1, BlockType::kComplex}, {1, BlockType::kComplex}});
  const MuBound r = mu_upper_bound(m, {{1, BlockType::kComplex}, {1, BlockType::kReal}});
  for (const MuBound* b : {&c, &r})
    if (!b->ok() && out.status == MuStatus::kOk) {
      out.status = b->status;
      out.message = fmt::format("at {:.6g} rad/s: {}", w, b->message);
    }
  return {c.bound, r.bound};
}

// The largest of f over the grid, refined by golden section in ln w on the two intervals beside it.
void refine_peak(const std::vector<double>& grid, const std::vector<double>& values,
                 const std::function<double(double)>& f, double& peak, double& peak_radps) {
  const auto it = std::max_element(values.begin(), values.end());
  const std::size_t i = static_cast<std::size_t>(it - values.begin());
  peak = *it;
  peak_radps = grid[i];
  double a = std::log(grid[i == 0 ? 0 : i - 1]), b = std::log(grid[std::min(i + 1, grid.size() - 1)]);
  const double r = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = b - r * (b - a), x2 = a + r * (b - a), f1 = f(std::exp(x1)), f2 = f(std::exp(x2));
  for (int k = 0; k < kMaxGoldenSteps && b - a > kPeakLogTolerance; ++k) {
    if (f1 > f2) {  // the peak lies in [a, x2]
      b = x2;
      x2 = x1;
      f2 = f1;
      x1 = b - r * (b - a);
      f1 = f(std::exp(x1));
    } else {  // in [x1, b]
      a = x1;
      x1 = x2;
      f1 = f2;
      x2 = a + r * (b - a);
      f2 = f(std::exp(x2));
    }
  }
  for (const auto& [x, fx] : {std::pair{x1, f1}, std::pair{x2, f2}}) {
    if (fx > peak) {
      peak = fx;
      peak_radps = std::exp(x);
    }
  }
}

// The closed loop at the box's centre (k0, tau0), the delay as the design's Pade approximation.
double nominal_max_real_pole(const AxisDesign& design, const LoopUncertaintyLft& lft) {
  StateSpace g = delayed_double_integrator(lft.delay_nominal_s, 0.0);
  g.c *= lft.gain_nominal;
  const GeneralisedPlant p = mixed_sensitivity_plant(g, design.weights);
  return max_real_pole(lower_lft(p.p, p.n_meas, p.n_ctrl, design.synthesis.controller));
}

double grid_bottom_radps(const AxisDesign& design) {
  double w = kGridBottomPerBandwidth * design.spec.bandwidth_radps;
  for (const std::complex<double>& p : poles(design.synthesis.controller))
    if (std::abs(p) > 0.0) w = std::min(w, kGridBottomPerSlowestPole * std::abs(p));
  return w;
}

// Where L0 is real (Im L0 changes sign between grid points, bisected in ln w): there T is real and a
// real gain alone can make 1 + T r_k delta_k vanish. Real mu is discontinuous in w, nonzero only at
// such points, so a grid alone steps over them (measured: 3 % low on a gain-only box).
std::vector<double> real_loop_frequencies(const AxisDesign& design, const LoopUncertaintyLft& lft,
                                          const std::vector<double>& grid) {
  StateSpace g = delayed_double_integrator(0.0, 0.0);
  g.c *= lft.gain_nominal;
  const SisoLoop loop{g, design.synthesis.controller, lft.delay_nominal_s};
  const auto im = [&](double w) { return loop_response(loop, w).imag(); };
  std::vector<double> found;
  for (std::size_t i = 0; i + 1 < grid.size(); ++i) {
    double a = std::log(grid[i]), b = std::log(grid[i + 1]);
    const double fa = im(grid[i]);
    if ((fa < 0.0) == (im(grid[i + 1]) < 0.0)) continue;
    while (b - a > kMarginLogTolerance) {
      const double c = 0.5 * (a + b);
      ((im(std::exp(c)) < 0.0) == (fa < 0.0) ? a : b) = c;
    }
    found.push_back(std::exp(0.5 * (a + b)));
  }
  return found;
}

double inverse(double peak) { return peak > 0.0 ? 1.0 / peak : std::numeric_limits<double>::infinity(); }

}  // namespace

LoopUncertaintyLft loop_lft(const AxisUncertainty& box) {
  std::vector<std::string> problems;
  if (!(box.gain_lo > 0.0 && box.gain_lo <= box.gain_hi && std::isfinite(box.gain_hi)))
    problems.push_back(fmt::format("gain range must satisfy 0 < lo <= hi (got [{}, {}])", box.gain_lo, box.gain_hi));
  if (!(box.delay_lo_s >= 0.0 && box.delay_lo_s <= box.delay_hi_s && std::isfinite(box.delay_hi_s)))
    problems.push_back(
        fmt::format("delay range must satisfy 0 <= lo <= hi (got [{}, {}])", box.delay_lo_s, box.delay_hi_s));
  if (!problems.empty()) {
    std::string text = "loop_lft:";
    for (const std::string& p : problems) text += "\n  " + p;
    throw std::invalid_argument(text);
  }
  return {.gain_nominal = 0.5 * (box.gain_lo + box.gain_hi),
          .gain_radius = (box.gain_hi - box.gain_lo) / (box.gain_hi + box.gain_lo),
          .delay_nominal_s = 0.5 * (box.delay_lo_s + box.delay_hi_s),
          .delay_radius_s = 0.5 * (box.delay_hi_s - box.delay_lo_s)};
}

double delay_weight(double omega_radps, double delay_radius_s) {
  return 2.0 * std::sin(std::min(0.5 * omega_radps * delay_radius_s, 0.5 * std::numbers::pi));
}

Eigen::MatrixXcd loop_interconnection(const AxisDesign& design, const LoopUncertaintyLft& lft, double omega_radps) {
  StateSpace g = delayed_double_integrator(0.0, 0.0);
  g.c *= lft.gain_nominal;
  const std::complex<double> l0 =
      loop_response({g, design.synthesis.controller, lft.delay_nominal_s}, omega_radps);
  const std::complex<double> s = 1.0 / (1.0 + l0), t = l0 * s;
  const double w_tau = delay_weight(omega_radps, lft.delay_radius_s), r_k = lft.gain_radius;
  Eigen::MatrixXcd m(2, 2);
  m << -w_tau * t, -w_tau * t, r_k * s, -r_k * t;
  return m;
}

double LoopMu::margin_complex() const { return inverse(peak_complex); }
double LoopMu::margin_mixed() const { return inverse(peak_mixed); }

LoopMu loop_mu(const AxisDesign& design, const AxisUncertainty& box) {
  LoopMu out;
  out.lft = loop_lft(box);
  if (!design.synthesis.ok()) throw std::invalid_argument("loop_mu: the axis has no controller");
  out.nominal_max_real_pole = nominal_max_real_pole(design, out.lft);
  out.nominal_stable = out.nominal_max_real_pole < 0.0;
  const double w_lo = grid_bottom_radps(design);
  const double w_hi = margin_band_top_radps(design.spec.bandwidth_radps, out.lft.delay_nominal_s);
  const int count = static_cast<int>(std::ceil(std::log10(w_hi / w_lo) * kMuPointsPerDecade)) + 1;
  out.omega_radps = log_grid(w_lo, w_hi, count);
  const std::vector<double> real_points = real_loop_frequencies(design, out.lft, out.omega_radps);
  out.omega_radps.insert(out.omega_radps.end(), real_points.begin(), real_points.end());
  std::sort(out.omega_radps.begin(), out.omega_radps.end());
  for (const double w : out.omega_radps) {
    const MuPair b = bounds_at(design, out.lft, w, out);
    out.mu_complex.push_back(b.complex_bound);
    out.mu_mixed.push_back(b.mixed_bound);
  }
  refine_peak(out.omega_radps, out.mu_complex,
              [&](double w) { return bounds_at(design, out.lft, w, out).complex_bound; }, out.peak_complex,
              out.peak_complex_radps);
  refine_peak(out.omega_radps, out.mu_mixed,
              [&](double w) { return bounds_at(design, out.lft, w, out).mixed_bound; }, out.peak_mixed,
              out.peak_mixed_radps);
  return out;
}

}  // namespace chaser::control
