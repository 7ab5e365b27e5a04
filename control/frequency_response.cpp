#include "control/frequency_response.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>

namespace chaser::control {

using Eigen::Index;
using Eigen::MatrixXcd;
using Eigen::MatrixXd;

namespace {

constexpr double kGridMarginDecades = 2.0;  // the grid reaches two decades beyond the pole span
constexpr int kMaxGoldenSteps = 200;        // ln(range / tol) / ln(golden ratio): ~60 suffice

}  // namespace

MatrixXcd frequency_response(const StateSpace& g, double omega_radps) {
  const Index n = g.states();
  MatrixXcd out = g.d.cast<std::complex<double>>();
  if (n == 0) return out;
  MatrixXcd jw_minus_a = -g.a.cast<std::complex<double>>();
  jw_minus_a.diagonal().array() += std::complex<double>(0.0, omega_radps);
  // Partial pivoting is enough: j omega I - A is singular only at an imaginary-axis pole, where
  // G is unbounded anyway; near one, the LU solve loses digits at the rate cond(j omega I - A).
  out.noalias() += g.c.cast<std::complex<double>>() *
                   Eigen::PartialPivLU<MatrixXcd>(jw_minus_a).solve(g.b.cast<std::complex<double>>());
  return out;
}

double sigma_max(const StateSpace& g, double omega_radps) {
  const MatrixXcd response = frequency_response(g, omega_radps);
  if (response.size() == 0) return 0.0;
  return Eigen::JacobiSVD<MatrixXcd>(response).singularValues()(0);
}

std::vector<double> log_grid(double omega_min_radps, double omega_max_radps, int count) {
  std::vector<double> out(static_cast<std::size_t>(std::max(count, 0)));
  const double lo = std::log(omega_min_radps), hi = std::log(omega_max_radps);
  for (int i = 0; i < count; ++i) out[i] = std::exp(lo + (hi - lo) * i / (count - 1));
  return out;
}

Eigen::VectorXcd poles(const StateSpace& g) {
  if (g.states() == 0) return Eigen::VectorXcd(0);
  return Eigen::EigenSolver<MatrixXd>(g.a, false).eigenvalues();
}

double max_real_pole(const StateSpace& g) {
  const Eigen::VectorXcd p = poles(g);
  return p.size() == 0 ? -std::numeric_limits<double>::infinity() : p.real().maxCoeff();
}

namespace {

// The grid: log spaced over the pole span with margins, plus each pole's magnitude (where a lightly
// damped pair peaks, to within a relative zeta^2), sorted.
std::vector<double> sweep_frequencies(const StateSpace& g) {
  const Eigen::VectorXcd p = poles(g);
  std::vector<double> pole_omegas;
  for (Index i = 0; i < p.size(); ++i)
    if (std::abs(p(i)) > 0.0) pole_omegas.push_back(std::abs(p(i)));
  double lo = 1.0, hi = 1.0;
  if (!pole_omegas.empty()) {
    lo = *std::min_element(pole_omegas.begin(), pole_omegas.end());
    hi = *std::max_element(pole_omegas.begin(), pole_omegas.end());
  }
  const double margin = std::pow(10.0, kGridMarginDecades);
  lo /= margin;
  hi *= margin;
  const int count = 1 + static_cast<int>(std::ceil(std::log10(hi / lo) * kPointsPerDecade));
  std::vector<double> grid = log_grid(lo, hi, count);
  grid.insert(grid.end(), pole_omegas.begin(), pole_omegas.end());
  std::sort(grid.begin(), grid.end());
  grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
  return grid;
}

// Golden-section search for the maximum of sigma_max on [omega_a, omega_b], in ln omega.
double golden_section_peak(const StateSpace& g, double omega_a, double omega_b, HinfNormEstimate& est) {
  const double inv_phi = (std::sqrt(5.0) - 1.0) / 2.0;
  double a = std::log(omega_a), b = std::log(omega_b);
  double x1 = b - inv_phi * (b - a), x2 = a + inv_phi * (b - a);
  double f1 = sigma_max(g, std::exp(x1)), f2 = sigma_max(g, std::exp(x2));
  est.evaluations += 2;
  for (int k = 0; k < kMaxGoldenSteps && b - a > kGoldenLogTolerance; ++k) {
    if (f1 >= f2) {
      b = x2, x2 = x1, f2 = f1;
      x1 = b - inv_phi * (b - a);
      f1 = sigma_max(g, std::exp(x1));
    } else {
      a = x1, x1 = x2, f1 = f2;
      x2 = a + inv_phi * (b - a);
      f2 = sigma_max(g, std::exp(x2));
    }
    ++est.evaluations;
  }
  if (f1 >= f2) {
    est.omega_peak_radps = std::exp(x1);
    return f1;
  }
  est.omega_peak_radps = std::exp(x2);
  return f2;
}

}  // namespace

HinfNormEstimate hinf_norm_estimate(const StateSpace& g) {
  HinfNormEstimate est;
  const std::vector<double> grid = sweep_frequencies(g);
  std::size_t best = 0;
  double best_value = -1.0;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    const double s = sigma_max(g, grid[i]);
    if (s > best_value) best_value = s, best = i;
  }
  est.evaluations = static_cast<int>(grid.size());
  const double lo = grid[best > 0 ? best - 1 : 0], hi = grid[std::min(best + 1, grid.size() - 1)];
  est.norm = golden_section_peak(g, lo, hi, est);
  if (best_value > est.norm) est.norm = best_value, est.omega_peak_radps = grid[best];
  // The two ends of the axis: omega = 0 (if A is invertible; otherwise a pole sits there) and
  // omega -> inf, where G -> D.
  const double dc = sigma_max(g, 0.0);
  const double at_infinity = g.d.size() == 0 ? 0.0 : Eigen::JacobiSVD<MatrixXd>(g.d).singularValues()(0);
  est.evaluations += 1;
  if (std::isfinite(dc) && dc > est.norm) est.norm = dc, est.omega_peak_radps = 0.0;
  if (at_infinity > est.norm) est.norm = at_infinity, est.omega_peak_radps = std::numeric_limits<double>::infinity();
  return est;
}

}  // namespace chaser::control
