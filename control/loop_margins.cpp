#include "control/loop_margins.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>

#include "control/frequency_response.hpp"

namespace chaser::control {
namespace {

using Complex = std::complex<double>;
using ScalarOfLogOmega = std::function<double(double)>;

void check_siso(const StateSpace& sys, const char* name, std::vector<std::string>& problems) {
  for (const std::string& p : validate(sys, name)) problems.push_back(p);
  if (sys.inputs() != 1 || sys.outputs() != 1)
    problems.push_back(std::string(name) + " must be SISO (1 input, 1 output), got " + std::to_string(sys.inputs()) +
                       " inputs and " + std::to_string(sys.outputs()) + " outputs");
}

void check_loop(const SisoLoop& loop, double omega_min, double omega_max) {
  std::vector<std::string> problems;
  check_siso(loop.plant, "plant", problems);
  check_siso(loop.controller, "controller", problems);
  if (!std::isfinite(loop.delay_s) || loop.delay_s < 0.0) problems.push_back("delay_s must be finite and >= 0");
  if (!(std::isfinite(omega_min) && std::isfinite(omega_max) && omega_min > 0.0 && omega_min < omega_max))
    problems.push_back("the range must satisfy 0 < omega_min < omega_max, finite");
  if (problems.empty()) return;
  std::string text = "loop_margins:";
  for (const std::string& p : problems) text += "\n  " + p;
  throw std::invalid_argument(text);
}

// A root of f in [a, b] (f(a), f(b) of opposite signs) by bisection to kMarginLogTolerance.
double bisect(const ScalarOfLogOmega& f, double a, double b) {
  double fa = f(a);
  while (b - a > kMarginLogTolerance) {
    const double m = 0.5 * (a + b);
    const double fm = f(m);
    if ((fm < 0.0) == (fa < 0.0)) {
      a = m;
      fa = fm;
    } else {
      b = m;
    }
  }
  return 0.5 * (a + b);
}

struct Peak {
  double value = 0.0;
  double log_omega = 0.0;
};

// The largest of f over the grid, refined by golden section on the two intervals beside it.
Peak peak_of(const ScalarOfLogOmega& f, const std::vector<double>& grid, const std::vector<double>& values) {
  const auto best = static_cast<std::size_t>(std::max_element(values.begin(), values.end()) - values.begin());
  double a = grid[best == 0 ? 0 : best - 1];
  double b = grid[std::min(best + 1, grid.size() - 1)];
  const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
  double c = b - ratio * (b - a), d = a + ratio * (b - a);
  double fc = f(c), fd = f(d);
  while (b - a > kMarginLogTolerance) {
    if (fc > fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - ratio * (b - a);
      fc = f(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + ratio * (b - a);
      fd = f(d);
    }
  }
  Peak peak{values[best], grid[best]};
  const double refined = std::max(fc, fd);
  if (refined > peak.value) peak = {refined, fc > fd ? c : d};
  return peak;
}

// Around each lightly damped pole of G and K (damping ratio below kResonanceDamping), points
// spaced by a fraction of its half-power width, so that a resonance narrower than the log grid's
// spacing is not stepped over; the grid is then sorted.
void add_resonance_points(const SisoLoop& loop, double omega_min, double omega_max, std::vector<double>& grid) {
  constexpr double kResonanceDamping = 0.2;
  for (const StateSpace* sys : {&loop.plant, &loop.controller}) {
    if (sys->states() == 0) continue;
    for (const Complex& p : poles(*sys)) {
      const double magnitude = std::abs(p);
      if (!(magnitude > 0.0) || magnitude < omega_min || magnitude > omega_max) continue;
      const double zeta = -p.real() / magnitude;
      if (!(std::abs(zeta) < kResonanceDamping)) continue;
      const double width = std::max(std::abs(zeta), 1e-4);
      for (int k = -16; k <= 16; ++k) {
        const double w = magnitude * (1.0 + 0.5 * k * width);
        if (w > omega_min && w < omega_max) grid.push_back(std::log(w));
      }
    }
  }
  std::sort(grid.begin(), grid.end());
  grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
}

}  // namespace

Complex loop_response(const SisoLoop& loop, double omega_radps) {
  const Complex g = frequency_response(loop.plant, omega_radps)(0, 0);
  const Complex k = frequency_response(loop.controller, omega_radps)(0, 0);
  return g * k * std::polar(1.0, -omega_radps * loop.delay_s);
}

LoopMargins loop_margins(const SisoLoop& loop, double omega_min_radps, double omega_max_radps, int points_per_decade) {
  check_loop(loop, omega_min_radps, omega_max_radps);
  if (points_per_decade < 2) throw std::invalid_argument("loop_margins: points_per_decade must be >= 2");
  const auto l_at = [&loop](double log_omega) { return loop_response(loop, std::exp(log_omega)); };
  const ScalarOfLogOmega log_gain = [&](double x) { return std::log(std::abs(l_at(x))); };
  const ScalarOfLogOmega imag = [&](double x) { return l_at(x).imag(); };
  const ScalarOfLogOmega s_mag = [&](double x) { return 1.0 / std::abs(1.0 + l_at(x)); };
  const ScalarOfLogOmega t_mag = [&](double x) {
    const Complex l = l_at(x);
    return std::abs(l / (1.0 + l));
  };
  const double half_power = 1.0 / std::numbers::sqrt2;
  const ScalarOfLogOmega s_above_half_power = [&](double x) { return s_mag(x) - half_power; };

  const double decades = std::log10(omega_max_radps / omega_min_radps);
  const int count = std::max(2, static_cast<int>(std::ceil(decades * points_per_decade)) + 1);
  std::vector<double> grid;
  for (const double w : log_grid(omega_min_radps, omega_max_radps, count)) grid.push_back(std::log(w));
  add_resonance_points(loop, omega_min_radps, omega_max_radps, grid);
  std::vector<Complex> l(grid.size());
  std::vector<double> s(grid.size()), t(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i) {
    l[i] = l_at(grid[i]);
    s[i] = 1.0 / std::abs(1.0 + l[i]);
    t[i] = std::abs(l[i]) * s[i];
  }

  LoopMargins m;
  for (std::size_t i = 0; i + 1 < grid.size(); ++i) {
    const double a = grid[i], b = grid[i + 1];
    if ((std::abs(l[i]) < 1.0) != (std::abs(l[i + 1]) < 1.0)) {  // gain crossover
      const double x = bisect(log_gain, a, b);
      const Complex lc = l_at(x);
      // The phase margin is L's angular distance from -1 on the unit circle, either way round:
      // 180 deg - |arg L| (a lightly damped mode can carry the phase past 0). A delay only turns L
      // clockwise, so the delay margin is the clockwise angle to -1, pi + arg L in (0, 2 pi].
      const double arg = std::arg(lc);
      const double pm_deg = (std::numbers::pi - std::abs(arg)) * 180.0 / std::numbers::pi;
      if (pm_deg < m.phase_margin_deg) {
        m.phase_margin_deg = pm_deg;
        m.gain_crossover_radps = std::exp(x);
      }
      m.delay_margin_s = std::min(m.delay_margin_s, (std::numbers::pi + arg) / std::exp(x));
    }
    if ((l[i].imag() < 0.0) != (l[i + 1].imag() < 0.0)) {  // L crosses the real axis
      const double x = bisect(imag, a, b);
      const Complex lc = l_at(x);
      if (lc.real() < 0.0) {  // the negative real axis: a phase crossover
        const double factor = 1.0 / std::abs(lc);
        if (factor > 1.0 && factor < m.gain_margin_up) {
          m.gain_margin_up = factor;
          m.phase_crossover_radps = std::exp(x);
        }
        if (factor < 1.0) m.gain_margin_down = std::max(m.gain_margin_down, factor);
      }
    }
    if (std::isnan(m.bandwidth_radps) && s[i] < half_power && s[i + 1] >= half_power)
      m.bandwidth_radps = std::exp(bisect(s_above_half_power, a, b));
  }
  const Peak s_peak = peak_of(s_mag, grid, s);
  const Peak t_peak = peak_of(t_mag, grid, t);
  m.sensitivity_peak = s_peak.value;
  m.sensitivity_peak_radps = std::exp(s_peak.log_omega);
  m.complementary_peak = t_peak.value;
  m.complementary_peak_radps = std::exp(t_peak.log_omega);
  return m;
}

}  // namespace chaser::control
