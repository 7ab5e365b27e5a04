#include "flight/fdi/design/cayley_hamilton_polytope.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unsupported/Eigen/MatrixFunctions>

#include "flight/fdi/design/delay_discretization.hpp"

namespace chaser::flight::fdi {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

VectorXd characteristic_coefficients(const MatrixXd& A) {
  // Faddeev-LeVerrier: M_k = A M_{k-1} + c_{n-k+1} I, c_{n-k} = -tr(A M_k) / k, M_0 = 0, c_n = 1.
  const Index n = A.rows();
  VectorXd c(n);
  MatrixXd m = MatrixXd::Zero(n, n);
  double c_prev = 1.0;
  for (Index k = 1; k <= n; ++k) {
    m = A * m + c_prev * MatrixXd::Identity(n, n);
    c_prev = -(A * m).trace() / static_cast<double>(k);
    c(n - k) = c_prev;
  }
  return c;
}

MatrixXd companion_matrix(const VectorXd& c) {
  const Index n = c.size();
  MatrixXd f = MatrixXd::Zero(n, n);
  for (Index j = 0; j + 1 < n; ++j) f(j, j + 1) = 1.0;
  f.row(n - 1) = -c.transpose();
  return f;
}

namespace {

// Coefficients of A' = A scale (c'_k = c_k scale^{n-k}) and the factors scale^{i-1}, i = 1..n.
struct ScaledCompanion {
  MatrixXd f;        // companion matrix of A'
  VectorXd factors;  // scale^{i-1}
};

ScaledCompanion scaled_companion(const VectorXd& c, double scale) {
  const Index n = c.size();
  VectorXd scaled(n);
  VectorXd factors(n);
  for (Index k = 0; k < n; ++k) {
    scaled(k) = c(k) * std::pow(scale, static_cast<double>(n - k));
    factors(k) = std::pow(scale, static_cast<double>(k));
  }
  return {companion_matrix(scaled), factors};
}

}  // namespace

VectorXd cayley_hamilton_functions(const VectorXd& c, double t, double time_scale_s) {
  const ScaledCompanion sc = scaled_companion(c, time_scale_s);
  const MatrixXd e = (sc.f * (t / time_scale_s)).exp();
  return e.row(0).transpose().cwiseProduct(sc.factors);
}

VectorXd cayley_hamilton_integrals(const VectorXd& c, double t0, double t1, double time_scale_s) {
  // int_{t0}^{t1} e^{Fs} ds = e^{F t0} int_0^{t1-t0} e^{Fs} ds: no cancellation for short spans.
  const ScaledCompanion sc = scaled_companion(c, time_scale_s);
  const Index n = c.size();
  const MatrixXd head = (sc.f * (t0 / time_scale_s)).exp();
  const MatrixXd span =
      exp_and_integral(sc.f, MatrixXd::Identity(n, n), (t1 - t0) / time_scale_s).integral_B;
  return (head.row(0) * span).transpose().cwiseProduct(sc.factors) * time_scale_s;
}

namespace {

// delta in (lo, hi) where s_i(T - delta) changes sign, by bisection (s_lo and s_hi differ in sign).
double bisect_sign_change(const VectorXd& c, Index i, double period_s, double lo, double hi,
                          double s_lo) {
  for (int iter = 0; iter < 200 && hi - lo > 1e-15 * period_s; ++iter) {
    const double mid = 0.5 * (lo + hi);
    const double s_mid = cayley_hamilton_functions(c, period_s - mid, period_s)(i);
    if ((s_mid < 0.0) == (s_lo < 0.0)) {
      lo = mid;
      s_lo = s_mid;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

// Candidate delays where some g_i can be extreme: the ends and the sign changes of every s_i.
std::vector<std::vector<double>> extremum_candidates(const VectorXd& c, double period_s,
                                                     double delta_min_s, double delta_max_s,
                                                     int grid_points) {
  const Index n = c.size();
  std::vector<std::vector<double>> candidates(n, std::vector<double>{delta_min_s, delta_max_s});
  const double step = (delta_max_s - delta_min_s) / grid_points;
  VectorXd s_prev = cayley_hamilton_functions(c, period_s - delta_min_s, period_s);
  for (int j = 1; j <= grid_points; ++j) {
    const double delta = delta_min_s + j * step;
    const VectorXd s = cayley_hamilton_functions(c, period_s - delta, period_s);
    for (Index i = 0; i < n; ++i)
      if (s_prev(i) * s(i) < 0.0)
        candidates[i].push_back(bisect_sign_change(c, i, period_s, delta - step, delta, s_prev(i)));
    s_prev = s;
  }
  return candidates;
}

}  // namespace

CayleyHamiltonPolytope cayley_hamilton_polytope(const MatrixXd& A, const MatrixXd& B,
                                                double period_s, double delta_min_s,
                                                double delta_max_s, int grid_points) {
  const Index n = A.rows();
  CayleyHamiltonPolytope p;
  p.period_s = period_s;
  p.delta_min_s = delta_min_s;
  p.delta_max_s = delta_max_s;
  p.coefficients = characteristic_coefficients(A);
  p.s_min = VectorXd::Constant(n, std::numeric_limits<double>::infinity());
  p.s_max = VectorXd::Constant(n, -std::numeric_limits<double>::infinity());
  const auto candidates = extremum_candidates(p.coefficients, period_s, delta_min_s, delta_max_s,
                                              std::max(grid_points, 1));
  for (Index i = 0; i < n; ++i) {
    for (const double delta : candidates[i]) {
      const double g = cayley_hamilton_integrals(p.coefficients, period_s - delta, period_s, period_s)(i);
      p.s_min(i) = std::min(p.s_min(i), g);
      p.s_max(i) = std::max(p.s_max(i), g);
    }
  }
  MatrixXd power_B = B;
  for (Index i = 0; i < n; ++i) {
    p.powers_B.push_back(power_B);
    p.vertices.push_back(static_cast<double>(n) * p.s_min(i) * power_B);  // eq. 51
    p.vertices.push_back(static_cast<double>(n) * p.s_max(i) * power_B);
    power_B = A * power_B;
  }
  return p;
}

VectorXd cayley_hamilton_weights(const CayleyHamiltonPolytope& p, double delta_s) {
  const Index n = p.coefficients.size();
  const VectorXd g =
      cayley_hamilton_integrals(p.coefficients, p.period_s - delta_s, p.period_s, p.period_s);
  VectorXd mu(2 * n);
  for (Index i = 0; i < n; ++i) {
    const double range = p.s_max(i) - p.s_min(i);
    const double alpha1 = range > 0.0 ? (g(i) - p.s_min(i)) / range : 0.5;
    mu(2 * i) = (1.0 - alpha1) / static_cast<double>(n);
    mu(2 * i + 1) = alpha1 / static_cast<double>(n);
  }
  return mu;
}

}  // namespace chaser::flight::fdi
