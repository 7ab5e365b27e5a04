#pragma once
// Residual evaluation by a generalised likelihood ratio test on a sliding window (Fonod 2015,
// eqs. 40-41), and its covariance-whitened extension to n_r > 1 residuals.
//
// Scalar test (eq. 41, the paper's, n_r = 1, on r_1): with sigma1^2(k) the mean of r^2 over the
// last N_d samples,
//   S(k) = N_d ln(sigma0) - N_d/2 (1 + ln(sigma1^2) - sigma1^2 / sigma0^2)
//        = N_d/2 (rho - ln(rho) - 1),   rho = sigma1^2 / sigma0^2,
// the log likelihood ratio of zero-mean white Gaussian residuals with variance sigma1^2 (fitted)
// against sigma0^2. S >= 0 with equality at rho = 1; H_1 is accepted when S > J_th (eq. 40).
//
// Whitened test (n_r = 1..3): the same GLR for a change of covariance of a zero-mean Gaussian
// vector, with Sigma0 the fault-free residual covariance and Sigma1 = (1/N_d) sum r r^T:
//   S(k) = N_d/2 (tr(Sigma0^-1 Sigma1) - ln det(Sigma0^-1 Sigma1) - n_r)
//        = N_d/2 sum_j (mu_j - ln(mu_j) - 1),   mu_j the eigenvalues of Sigma0^-1 Sigma1.
// For n_r = 1 it is eq. 41 exactly (mu = rho). Sigma1 is the second moment about zero, not about
// the window mean, so a persistent mean shift b (a bias fault) raises it by b b^T: one statistic
// catches both a mean change and a variance change, as eq. 41 does. It is chosen over the
// mean-change GLR N_d rbar' Sigma0^-1 rbar / 2 because it keeps eq. 41's behaviour and reduces to it.
//
// Choices where the paper is silent:
//   - Two-sided or one-sided. Eq. 41 is two-sided: a window whose residual is much smaller than
//     sigma0 (rho < 0.0069 for N_d = 10) also exceeds J_th = 20. `GlrSides::kIncreaseOnly` keeps only
//     the increase: the MLE under Sigma1 >= Sigma0 clips every mu_j at 1, so terms with mu_j <= 1
//     vanish (for n_r = 1: S = 0 when rho <= 1). The default is the paper's two-sided test.
//   - Floor: sigma1^2 (each mu_j) is floored at kGlrVarianceFloor = 1e-12 times sigma0^2 (whitened
//     units), so an identically zero residual gives a finite S = N_d/2 (ln 1e12 - 1) ~ 13.3 N_d
//     per dimension (two-sided) instead of infinity.
//   - Window not yet full (fewer than N_d samples since the start): S = 0 and no alarm.
//   - No drift: the window sums are recomputed from the ring buffer every period (N_d <= 128
//     samples, at most 6 products each), not updated by add-and-subtract. The scalar test keeps
//     r_1^2 itself in the ring and sums it from the oldest to the newest sample with two
//     accumulators (half the dependency chain).
//
// No logarithm and no division in the scalar test's decision: S is a function of rho alone,
// decreasing below 1 and increasing above, so S > J_th <=> rho < rho_lo or rho > rho_hi, the two
// roots of N_d/2 (rho - ln rho - 1) = J_th, found once (Newton) per window, threshold and sigma0
// and compared as window sums of r^2 (rho N_d sigma0^2). Within a margin of 1e-6 of the roots the
// decision is eq. 40 itself, S > J_th, so it is the same decision bit for bit. S is then only a
// report: GlrStatistic keeps the window sum and evaluates eq. 41 where S is read (telemetry, the
// campaign's envelopes, plots), which on board is not every period.
#include <array>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "core/zero_array.hpp"

namespace chaser::flight::fdi {

inline constexpr int kMaxGlrWindow = 128;        // largest N_d the fixed ring buffer holds
inline constexpr double kGlrVarianceFloor = 1e-12;  // [-] floor of rho (mu_j), in units of sigma0^2

enum class GlrVariant {
  kScalar,    // eq. 41 on the first residual component, with sigma0
  kWhitened,  // covariance-change GLR on n_r components, with Sigma0
};

enum class GlrSides {
  kTwoSided,      // eq. 41 as printed: alarms on a variance increase or decrease
  kIncreaseOnly,  // only an increase of the residual covariance counts
};

struct GlrParams {
  GlrVariant variant = GlrVariant::kScalar;
  GlrSides sides = GlrSides::kTwoSided;
  int window = 10;                      // N_d, 2..kMaxGlrWindow (the paper: 10)
  double threshold = 20.0;              // J_th [-] (the paper: 20)
  double sigma0 = 1.0;                  // [residual unit] fault-free std of r_1 (kScalar)
  Mat3 covariance0 = Mat3::Identity();  // [residual unit^2] Sigma0, top-left n_r block (kWhitened)
  int residual_dim = 1;                 // n_r, 1..3 (kWhitened; kScalar uses r_1 only)
};

// S^{N_d}(k) as the test produced it: the value itself (whitened test), or the scalar test's window
// sum of r_1^2, from which value() evaluates eq. 41 when asked.
class GlrStatistic {
 public:
  GlrStatistic() = default;
  static GlrStatistic of_value(double s) { return GlrStatistic(s, 0.0, 0, false); }
  // The sum of r_1^2 over a window of N_d >= 1 samples, sigma0 > 0.
  static GlrStatistic of_scalar_sum(double sum_r2, double sigma0, int window, GlrSides sides) {
    return GlrStatistic(sum_r2, sigma0, window, sides == GlrSides::kIncreaseOnly);
  }
  double value() const;  // [-] S
 private:
  GlrStatistic(double x, double sigma0, int window, bool increase_only)
      : x_(x), sigma0_(sigma0), window_(window), increase_only_(increase_only) {}
  double x_ = 0.0;              // S (window_ == 0) or the window sum of r_1^2
  double sigma0_ = 0.0;         // scalar test: sigma0
  int window_ = 0;              // N_d of the scalar test, 0: x_ is S
  bool increase_only_ = false;  // scalar test, kIncreaseOnly: S = 0 for rho <= 1
};

struct GlrState {
  std::array<Vec3, kMaxGlrWindow> samples = zero_array<Vec3, kMaxGlrWindow>();  // ring buffer of L0^-1 r (kWhitened)
  // r_1^2 (kScalar), each stored twice, at slot and slot + N_d: the window's other samples are then
  // the contiguous span after the slot (no test per sample, which the branch predictor can miss).
  std::array<double, 2 * kMaxGlrWindow> r1_squared{};
  int next = 0;                               // slot of the next sample
  int count = 0;                              // samples stored, up to the window
  Mat3 whitening = Mat3::Identity();          // L0^-1 of the embedded Sigma0, factorised at the first step
  bool whitening_ready = false;
  // The scalar test's decision bounds on the window sum of r_1^2 (see above), for the window,
  // threshold and sigma0 they were found for; a sum strictly between them cannot give S > J_th.
  int bounds_window = 0;
  double bounds_threshold = 0.0, bounds_sigma0 = 0.0;
  double sum_inside_lo = 0.0, sum_inside_hi = 0.0;
};

struct GlrOutput {
  GlrStatistic statistic;  // S^{N_d}(k) [-], 0 until the window is full
  bool alarm = false;      // S > J_th, eq. 40
};

// Problems with the parameters (empty when valid), each naming the field.
std::vector<std::string> validate(const GlrParams& params);

// Eq. 41 from rho = sigma1^2 / sigma0^2 (two-sided, rho floored at kGlrVarianceFloor), N_d = window >= 1.
double glr_scalar_statistic(double rho, int window);

// The roots rho_lo < 1 < rho_hi of N_d/2 (rho - ln rho - 1) = threshold (rho_lo = 0 when it is
// below the smallest double), threshold > 0.
struct GlrRatioBounds {
  double lo = 0.0, hi = 0.0;
};
GlrRatioBounds glr_ratio_bounds(int window, double threshold);

// N_d/2 sum_j (mu_j - ln mu_j - 1) over the eigenvalues of the whitened second moment M (n_r x n_r
// top-left block of a 3 x 3), with the floor; kIncreaseOnly drops the terms with mu_j <= 1.
double glr_whitened_statistic(const Mat3& whitened_moment, int residual_dim, int window,
                              GlrSides sides);

// Pushes r(k) into the window and evaluates eqs. 40-41 (or the whitened test): writes S^{N_d}(k)
// and returns the alarm. (Written in place, not returned in a GlrOutput: the caller's read of the
// returned struct, wider than its fields' stores, stalled on store forwarding.)
bool step_glr(const GlrParams& params, GlrState& state, const Vec3& r, GlrStatistic& statistic);
inline GlrOutput step_glr(const GlrParams& params, GlrState& state, const Vec3& r) {
  GlrOutput out;
  out.alarm = step_glr(params, state, r, out.statistic);
  return out;
}

}  // namespace chaser::flight::fdi
