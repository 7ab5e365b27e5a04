#include "flight/fdi/glr.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace chaser::flight::fdi {

namespace {

int clamped_window(int window) { return std::clamp(window, 1, kMaxGlrWindow); }

// Sigma0 restricted to its top-left n_r block, the identity elsewhere, so that whitening leaves the
// unused components at zero.
Mat3 embedded_covariance(const GlrParams& params) {
  Mat3 sigma0 = Mat3::Identity();
  const int n = params.residual_dim;
  sigma0.topLeftCorner(n, n) = params.covariance0.topLeftCorner(n, n);
  return sigma0;
}

// L0^-1 r of the used components, Sigma0 = L0 L0^T; Sigma0 is constant, so it is factorised once
// per run (the state belongs to one set of parameters).
Vec3 whiten(const GlrParams& params, GlrState& state, const Vec3& r) {
  if (!state.whitening_ready) {
    const Eigen::LLT<Mat3> llt(embedded_covariance(params));
    state.whitening = llt.matrixL().solve(Mat3::Identity());
    state.whitening_ready = true;
  }
  Vec3 used = Vec3::Zero();
  used.head(params.residual_dim) = r.head(params.residual_dim);
  return state.whitening * used;
}

double increase_only(double rho_term, double rho) { return rho > 1.0 ? rho_term : 0.0; }

}  // namespace

std::vector<std::string> validate(const GlrParams& params) {
  std::vector<std::string> problems;
  if (params.window < 2 || params.window > kMaxGlrWindow)
    problems.push_back("glr.window: must be in 2..128 (N_d > 1, eq. 41)");
  if (!(params.threshold > 0.0)) problems.push_back("glr.threshold: must be > 0");
  if (params.variant == GlrVariant::kScalar && !(params.sigma0 > 0.0 && std::isfinite(params.sigma0)))
    problems.push_back("glr.sigma0: must be finite and > 0");
  if (params.residual_dim < 1 || params.residual_dim > 3) {
    problems.push_back("glr.residual_dim: must be in 1..3");
  } else if (params.variant == GlrVariant::kWhitened) {
    const int n = params.residual_dim;
    const Mat3 block = embedded_covariance(params);
    const bool symmetric = (params.covariance0.topLeftCorner(n, n) -
                            params.covariance0.topLeftCorner(n, n).transpose())
                               .cwiseAbs()
                               .maxCoeff() <= 1e-12 * block.cwiseAbs().maxCoeff();
    if (!block.allFinite() || !symmetric || Eigen::LLT<Mat3>(block).info() != Eigen::Success)
      problems.push_back("glr.covariance0: top-left residual_dim block must be symmetric positive definite");
    if (params.window < params.residual_dim + 1)
      problems.push_back("glr.window: must exceed residual_dim for a nonsingular window covariance");
  }
  return problems;
}

namespace {

// rho = sigma1^2 / sigma0^2 with the floor.
double variance_ratio(double sum_r2, int window, double sigma0) {
  return std::max(sum_r2 / (window * sigma0 * sigma0), kGlrVarianceFloor);
}

}  // namespace

double glr_scalar_statistic(double rho, int window) {
  // Eq. 41, N_d ln(sigma0) - N_d/2 (1 + ln(sigma1^2) - sigma1^2/sigma0^2), as N_d/2 (rho - ln rho - 1):
  // one logarithm instead of two, and no cancellation between two large logarithms.
  rho = std::max(rho, kGlrVarianceFloor);
  return 0.5 * window * (rho - std::log(rho) - 1.0);
}

double GlrStatistic::value() const {
  if (window_ == 0) return x_;
  const double rho = variance_ratio(x_, window_, sigma0_);
  if (increase_only_ && rho <= 1.0) return 0.0;  // the MLE under Sigma1 >= Sigma0 is rho = 1
  return glr_scalar_statistic(rho, window_);
}

GlrRatioBounds glr_ratio_bounds(int window, double threshold) {
  // h(rho) = rho - ln rho - 1 - c, c = 2 J_th / N_d, is convex with its minimum -c at rho = 1, so
  // Newton's method converges monotonically to either root from the side where h > 0: from
  // 2 (1 + c) for the upper root (h = 1 + c - ln(2 (1 + c)) > 0) and from exp(-1 - c) for the
  // lower one (h = exp(-1 - c) > 0). It stops when an iterate no longer moves towards the root.
  const double c = 2.0 * threshold / window;
  const auto h = [c](double rho) { return rho - std::log(rho) - 1.0 - c; };
  GlrRatioBounds b;
  b.hi = 2.0 * (1.0 + c);
  for (int i = 0; i < 200; ++i) {
    const double next = b.hi - h(b.hi) / (1.0 - 1.0 / b.hi);
    if (!(next < b.hi)) break;
    b.hi = next;
  }
  b.lo = std::exp(-1.0 - c);
  for (int i = 0; i < 200 && b.lo > 0.0; ++i) {
    const double next = b.lo - h(b.lo) / (1.0 - 1.0 / b.lo);
    if (!(next > b.lo)) break;
    b.lo = next;
  }
  return b;
}

double glr_whitened_statistic(const Mat3& whitened_moment, int residual_dim, int window,
                              GlrSides sides) {
  Mat3 m = Mat3::Identity();
  m.topLeftCorner(residual_dim, residual_dim) =
      whitened_moment.topLeftCorner(residual_dim, residual_dim);
  // Two-sided: sum_j (mu_j - log mu_j - 1) = tr m - log det m - 3 when every mu_j is above the
  // floor, which holds when 4 det / tr^2 (a lower bound of the smallest mu_j: mu_2 mu_3 <= tr^2 / 4)
  // is; no eigenvalues (and their trigonometry) needed.
  if (sides == GlrSides::kTwoSided) {
    const double trace = m.trace(), det = m.determinant();
    if (det > 0.0 && 4.0 * det > kGlrVarianceFloor * trace * trace)
      return 0.5 * window * (trace - std::log(det) - 3.0);
  }
  Eigen::SelfAdjointEigenSolver<Mat3> eig;
  eig.computeDirect(m, Eigen::EigenvaluesOnly);
  double sum = 0.0;
  for (int j = 0; j < 3; ++j) {
    const double mu = std::max(eig.eigenvalues()(j), kGlrVarianceFloor);
    const double term = mu - std::log(mu) - 1.0;  // zero for the unused (identity) directions
    sum += sides == GlrSides::kIncreaseOnly ? increase_only(term, mu) : term;
  }
  return 0.5 * window * sum;
}

bool step_glr(const GlrParams& params, GlrState& state, const Vec3& r, GlrStatistic& statistic) {
  const int window = clamped_window(params.window);
  statistic = GlrStatistic();
  bool alarm = false;
  const int slot = state.next < window ? state.next : 0;  // the oldest sample's slot takes r(k)
  state.next = slot + 1 < window ? slot + 1 : 0;          // no integer division in the loop
  state.count = std::min(state.count + 1, window);
  const bool full = state.count == window;                // else S = 0 and no decision
  if (params.variant == GlrVariant::kScalar) {
    const double r1_squared = r(0) * r(0);
    if (full) {
      // The other N_d - 1 samples, oldest first, are summed before the slot is overwritten (a value
      // just stored, read back by a wider load, would stall the loop), in two chains (the sum is
      // latency-bound).
      const double* others = state.r1_squared.data() + slot + 1;
      const int n_others = window - 1;
      double even = 0.0, odd = 0.0;
      int j = 0;
      for (; j + 1 < n_others; j += 2) even += others[j], odd += others[j + 1];
      if (j < n_others) even += others[j];
      const double sum_r2 = even + odd + r1_squared;
      statistic = GlrStatistic::of_scalar_sum(sum_r2, params.sigma0, window, params.sides);
      if (state.bounds_window != window || state.bounds_threshold != params.threshold ||
          state.bounds_sigma0 != params.sigma0) {
        const GlrRatioBounds b = glr_ratio_bounds(window, params.threshold);
        const double sum_per_rho = window * params.sigma0 * params.sigma0;
        state.sum_inside_lo = params.sides == GlrSides::kIncreaseOnly ? 0.0 : b.lo * (1.0 + 1e-6) * sum_per_rho;
        state.sum_inside_hi = b.hi * (1.0 - 1e-6) * sum_per_rho;
        state.bounds_window = window, state.bounds_threshold = params.threshold, state.bounds_sigma0 = params.sigma0;
      }
      // Eq. 40, S > J_th, evaluated only near or beyond the bounds (see glr.hpp).
      if (sum_r2 < state.sum_inside_lo || sum_r2 > state.sum_inside_hi)
        alarm = statistic.value() > params.threshold;
    }
    state.r1_squared[slot] = state.r1_squared[slot + window] = r1_squared;
  } else {
    state.samples[slot] = whiten(params, state, r);
    if (full) {
      Mat3 moment = Mat3::Zero();
      for (int j = 0; j < window; ++j) moment.noalias() += state.samples[j] * state.samples[j].transpose();
      statistic =
          GlrStatistic::of_value(glr_whitened_statistic(moment / window, params.residual_dim, window, params.sides));
      alarm = statistic.value() > params.threshold;  // eq. 40
    }
  }
  return alarm;
}

}  // namespace chaser::flight::fdi
