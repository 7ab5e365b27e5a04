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

double glr_scalar_statistic(double sum_r2, int window, double sigma0) {
  // Eq. 41, N_d ln(sigma0) - N_d/2 (1 + ln(sigma1^2) - sigma1^2/sigma0^2), as N_d/2 (rho - ln rho - 1):
  // one logarithm instead of two, and no cancellation between two large logarithms.
  const double n = window;
  const double rho = std::max(sum_r2 / (n * sigma0 * sigma0), kGlrVarianceFloor);
  return 0.5 * n * (rho - std::log(rho) - 1.0);
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

GlrOutput step_glr(const GlrParams& params, GlrState& state, const Vec3& r) {
  const int window = clamped_window(params.window);
  const int slot = state.next < window ? state.next : 0;  // the oldest sample's slot takes r(k)
  state.next = slot + 1 < window ? slot + 1 : 0;          // no integer division in the loop
  state.count = std::min(state.count + 1, window);
  const bool full = state.count == window;                // else S = 0 and no decision
  GlrOutput out;
  if (params.variant == GlrVariant::kScalar) {
    const double r1_squared = r(0) * r(0);
    if (full) {
      // The other N_d - 1 samples are summed before the slot is overwritten (a value just stored,
      // read back by a wider load, would stall the loop), in two chains (the sum is latency-bound).
      const std::array<double, kMaxGlrWindow>& ring = state.r1_squared;
      double even = 0.0, odd = 0.0;
      int j = 0;
      for (; j + 1 < window; j += 2) even += j == slot ? 0.0 : ring[j], odd += j + 1 == slot ? 0.0 : ring[j + 1];
      if (j < window && j != slot) even += ring[j];
      const double sum_r2 = even + odd + r1_squared;
      out.statistic = glr_scalar_statistic(sum_r2, window, params.sigma0);
      if (params.sides == GlrSides::kIncreaseOnly && sum_r2 <= window * params.sigma0 * params.sigma0)
        out.statistic = 0.0;
    }
    state.r1_squared[slot] = r1_squared;
  } else {
    state.samples[slot] = whiten(params, state, r);
    if (full) {
      Mat3 moment = Mat3::Zero();
      for (int j = 0; j < window; ++j) moment.noalias() += state.samples[j] * state.samples[j].transpose();
      out.statistic = glr_whitened_statistic(moment / window, params.residual_dim, window, params.sides);
    }
  }
  out.alarm = out.statistic > params.threshold;  // eq. 40
  return out;
}

}  // namespace chaser::flight::fdi
