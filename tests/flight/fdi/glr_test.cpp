#include "flight/fdi/glr.hpp"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <vector>

#include "core/random.hpp"

namespace chaser::flight::fdi {
namespace {

constexpr double kEulerGamma = 0.57721566490153286;

// Digamma at n/2, n >= 1: psi(1) = -gamma, psi(1/2) = -gamma - 2 ln 2, psi(x + 1) = psi(x) + 1/x.
double digamma_half(int n) {
  double x = (n % 2 == 0) ? 1.0 : 0.5;
  double psi = (n % 2 == 0) ? -kEulerGamma : -kEulerGamma - 2.0 * std::log(2.0);
  for (; x < 0.5 * n - 1e-12; x += 1.0) psi += 1.0 / x;
  return psi;
}

// E[S] under H0 for white Gaussian residuals with covariance Sigma0: N Sigma0^-1 Sigma1 is
// Wishart(N, I_n), E tr = n, E ln det = sum_{i=1..n} psi((N - i + 1)/2) + n ln(2/N), so
// E[S] = -N/2 (sum_i psi((N - i + 1)/2) + n ln(2/N)).
double expected_statistic_h0(int window, int n) {
  double sum = 0.0;
  for (int i = 1; i <= n; ++i) sum += digamma_half(window - i + 1);
  return -0.5 * window * (sum + n * std::log(2.0 / window));
}

Vec3 gaussian(RandomStream& rng) { return Vec3(rng.normal(), rng.normal(), rng.normal()); }

// Mean and standard error of a correlated sequence by batch means (50 batches of consecutive
// values, each much longer than the window, so batch means are nearly independent).
struct MeanAndError {
  double mean;
  double error;
};
MeanAndError batch_mean(const std::vector<double>& v) {
  const int batches = 50;
  const std::size_t size = v.size() / batches;
  std::vector<double> means(batches, 0.0);
  for (int b = 0; b < batches; ++b) {
    for (std::size_t j = 0; j < size; ++j) means[b] += v[b * size + j];
    means[b] /= static_cast<double>(size);
  }
  double mean = 0.0;
  for (double m : means) mean += m / batches;
  double var = 0.0;
  for (double m : means) var += (m - mean) * (m - mean) / (batches - 1);
  return {mean, std::sqrt(var / batches)};
}

// Eq. 41 term by term on the last N values, for comparison.
double eq41_direct(const std::deque<double>& window, double sigma0) {
  double s2 = 0.0;
  for (double r : window) s2 += r * r;
  const double n = static_cast<double>(window.size());
  s2 /= n;
  return n * std::log(sigma0) - n / 2 * (1 + std::log(s2) - s2 / (sigma0 * sigma0));
}

// Eq. 41 evaluated by the step function equals eq. 41 evaluated directly on the window, equals the
// whitened test with Sigma0 = sigma0^2 and n_r = 1, and S = 0 until N_d samples are in.
TEST(Glr, ScalarIsEq41AndTheWhitenedTestReducesToIt) {
  GlrParams scalar;
  scalar.window = 10;
  scalar.sigma0 = 0.3;
  GlrParams whitened = scalar;
  whitened.variant = GlrVariant::kWhitened;
  whitened.covariance0(0, 0) = 0.09;
  GlrState s1;
  GlrState s2;
  RandomStream rng(11, "glr/eq41");
  std::deque<double> window;
  for (int k = 0; k < 400; ++k) {
    const double sigma = k < 200 ? 0.3 : 0.7;
    const Vec3 r(rng.normal(0, sigma), rng.normal(), rng.normal());  // r_2, r_3 must be ignored
    window.push_back(r(0));
    if (window.size() > 10) window.pop_front();
    const GlrOutput a = step_glr(scalar, s1, r);
    const GlrOutput b = step_glr(whitened, s2, r);
    if (k < 9) {
      EXPECT_EQ(a.statistic.value(), 0.0);
      EXPECT_FALSE(a.alarm);
      EXPECT_EQ(b.statistic.value(), 0.0);
      continue;
    }
    const double direct = eq41_direct(window, 0.3);
    EXPECT_NEAR(a.statistic.value(), direct, 1e-11 * std::max(1.0, std::abs(direct))) << k;
    EXPECT_NEAR(b.statistic.value(), direct, 1e-11 * std::max(1.0, std::abs(direct))) << k;
    EXPECT_EQ(a.alarm, direct > 20.0);
  }
}

// The whitened statistic against N/2 (tr(Sigma0^-1 Sigma1) - ln det(Sigma0^-1 Sigma1) - n_r) with
// dynamic-size matrices, for n_r = 2 and 3 and a correlated Sigma0.
TEST(Glr, WhitenedMatchesTraceLogDetForm) {
  for (int n : {2, 3}) {
    GlrParams p;
    p.variant = GlrVariant::kWhitened;
    p.residual_dim = n;
    p.window = 12;
    p.covariance0 << 2.0, 0.5, -0.3, 0.5, 1.0, 0.2, -0.3, 0.2, 0.5;
    GlrState state;
    RandomStream rng(12, "glr/whitened");
    std::deque<Vec3> window;
    for (int k = 0; k < 100; ++k) {
      const Vec3 r = gaussian(rng) * (k < 50 ? 1.0 : 2.0);
      window.push_back(r);
      if (window.size() > 12) window.pop_front();
      const double s = step_glr(p, state, r).statistic.value();
      if (k < 11) continue;
      Eigen::MatrixXd sigma1 = Eigen::MatrixXd::Zero(n, n);
      for (const Vec3& v : window) sigma1 += v.head(n) * v.head(n).transpose();
      sigma1 /= 12.0;
      const Eigen::MatrixXd w = p.covariance0.topLeftCorner(n, n).inverse() * sigma1;
      const double direct = 6.0 * (w.trace() - std::log(w.determinant()) - n);
      EXPECT_NEAR(s, direct, 1e-10 * std::max(1.0, direct)) << "n_r " << n << " k " << k;
    }
  }
}

// The statistic's two paths agree: the two-sided trace/log-det form (taken when 4 det / tr^2 is
// above the floor) against the eigenvalue sum with the floor, on random SPD moments from well to
// badly conditioned. The 3x3 determinant's relative error is about cond(m) eps, so log det is off by
// that much: tolerance 10 cond eps N_d/2 (1e-14 for the whitened moments of a fault-free window,
// cond ~ 10); and a moment with an eigenvalue under the floor takes the floored eigenvalue path.
TEST(Glr, TwoSidedShortcutEqualsTheEigenvalueSum) {
  RandomStream rng(7, "glr/shortcut");
  for (int k = 0; k < 2000; ++k) {
    Mat3 a;
    for (int i = 0; i < 9; ++i) a(i) = rng.normal();
    const double spread = std::pow(10.0, rng.uniform(-6.0, 2.0));
    Mat3 m = a * a.transpose() + spread * Mat3::Identity();
    const Eigen::SelfAdjointEigenSolver<Mat3> eig(m);
    double direct = 0.0;
    for (int j = 0; j < 3; ++j) {
      const double mu = std::max(eig.eigenvalues()(j), kGlrVarianceFloor);
      direct += mu - std::log(mu) - 1.0;
    }
    direct *= 0.5 * 10;
    const double cond = eig.eigenvalues()(2) / eig.eigenvalues()(0);
    const double tol = 10.0 * cond * 2.3e-16 * 5.0 + 1e-13 * std::abs(direct);
    EXPECT_NEAR(glr_whitened_statistic(m, 3, 10, GlrSides::kTwoSided), direct, tol) << k << " cond " << cond;
  }
  const Mat3 tiny = Vec3(1.0, 2.0, 1e-14).asDiagonal();
  const double expected = 5.0 * ((1.0 - 0.0 - 1.0) + (2.0 - std::log(2.0) - 1.0) +
                                 (kGlrVarianceFloor - std::log(kGlrVarianceFloor) - 1.0));
  EXPECT_NEAR(glr_whitened_statistic(tiny, 3, 10, GlrSides::kTwoSided), expected, 1e-10);
}

// Under H0 (white Gaussian residual with the assumed covariance) the mean of S matches the
// Wishart expectation: 0.517 for N_d = 10, n_r = 1 (0.5 would be the chi-square(1)/2 limit).
// 200,000 samples; the tolerance is 4 batch-means standard errors.
TEST(Glr, MeanUnderH0MatchesTheory) {
  for (int n : {1, 2, 3}) {
    GlrParams p;
    p.variant = n == 1 ? GlrVariant::kScalar : GlrVariant::kWhitened;
    p.residual_dim = n;
    p.window = 10;
    p.sigma0 = 2.0;
    p.covariance0 << 4.0, 1.0, 0.5, 1.0, 3.0, -0.4, 0.5, -0.4, 1.0;
    const Mat3 chol = p.covariance0.llt().matrixL();
    GlrState state;
    RandomStream rng(13, "glr/h0");
    std::vector<double> s;
    for (int k = 0; k < 200000; ++k) {
      const Vec3 r = n == 1 ? Vec3(rng.normal(0, 2.0), 0, 0) : Vec3(chol * gaussian(rng));
      const GlrOutput out = step_glr(p, state, r);
      if (k >= 9) s.push_back(out.statistic.value());
    }
    const MeanAndError m = batch_mean(s);
    const double theory = expected_statistic_h0(10, n);
    std::printf("[ measured ] n_r = %d: mean S under H0 %.4f +- %.4f, theory %.4f\n", n, m.mean,
                m.error, theory);
    EXPECT_NEAR(m.mean, theory, 4.0 * m.error) << "n_r " << n;
    EXPECT_LT(m.error, 0.02);
  }
}

// A variance step from sigma0 to 3 sigma0: once the window holds only post-step samples,
// E[S] = N/2 (9 - ln 9 - psi(5) - ln(2/10) - 1) = 29.53 for N_d = 10 (> J_th = 20). S crosses 20
// when the window's mean square passes 6.94 sigma0^2, i.e. after ~8 post-step samples on average
// ((8 * 9 + 2) / 10 = 7.4); the median delay over 300 runs is checked to be 6..10 samples and
// no run may alarm before the step (P ~ 1e-9 per sample under H0).
TEST(Glr, VarianceStepRaisesSAboveThreshold) {
  GlrParams p;
  p.window = 10;
  p.sigma0 = 1.0;
  p.threshold = 20.0;
  std::vector<int> delays;
  std::vector<double> after;
  for (int run = 0; run < 300; ++run) {
    RandomStream rng(1000 + run, "glr/step");
    GlrState state;
    int delay = -1;
    for (int k = 0; k < 300; ++k) {
      const double sigma = k < 100 ? 1.0 : 3.0;
      const GlrOutput out = step_glr(p, state, Vec3(rng.normal(0, sigma), 0, 0));
      if (k < 100) {
        EXPECT_FALSE(out.alarm) << "run " << run << " k " << k;
      }
      if (k >= 100 && delay < 0 && out.alarm) delay = k - 100 + 1;
      if (k >= 110) after.push_back(out.statistic.value());
    }
    ASSERT_GT(delay, 0) << "run " << run;
    delays.push_back(delay);
  }
  std::sort(delays.begin(), delays.end());
  const double psi5 = digamma_half(10);
  const double theory = 5.0 * (9.0 - std::log(9.0) - psi5 - std::log(0.2) - 1.0);
  const MeanAndError m = batch_mean(after);
  std::printf("[ measured ] detection delay median %d, 90%% %d samples; mean S after %.3f +- %.3f "
              "(theory %.3f)\n", delays[150], delays[270], m.mean, m.error, theory);
  EXPECT_GE(delays[150], 6);
  EXPECT_LE(delays[150], 10);
  EXPECT_NEAR(m.mean, theory, 4.0 * m.error);
}

// Floor and sidedness: an identically zero residual gives the floored two-sided value
// N/2 (1e-12 - ln 1e-12 - 1) = 133.2 for N_d = 10 (eq. 41 alarms on a vanished residual), and 0
// with kIncreaseOnly; a variance increase gives the same S either way.
TEST(Glr, FloorAndIncreaseOnly) {
  GlrParams two;
  two.window = 10;
  GlrParams one = two;
  one.sides = GlrSides::kIncreaseOnly;
  GlrParams white_one = one;
  white_one.variant = GlrVariant::kWhitened;
  GlrState s2, s1, sw;
  for (int k = 0; k < 10; ++k) {
    const double a = step_glr(two, s2, Vec3::Zero()).statistic.value();
    const double b = step_glr(one, s1, Vec3::Zero()).statistic.value();
    const double c = step_glr(white_one, sw, Vec3::Zero()).statistic.value();
    if (k == 9) {
      EXPECT_NEAR(a, 5.0 * (1e-12 - std::log(1e-12) - 1.0), 1e-9);
      EXPECT_EQ(b, 0.0);
      EXPECT_EQ(c, 0.0);
    }
  }
  for (int k = 0; k < 10; ++k) {
    const double a = step_glr(two, s2, Vec3(3.0, 0, 0)).statistic.value();
    const double b = step_glr(one, s1, Vec3(3.0, 0, 0)).statistic.value();
    const double c = step_glr(white_one, sw, Vec3(3.0, 0, 0)).statistic.value();
    if (k == 9) {
      EXPECT_NEAR(a, 5.0 * (9.0 - std::log(9.0) - 1.0), 1e-12);
      EXPECT_EQ(a, b);
      EXPECT_NEAR(c, a, 1e-12);
    }
  }
}

// No drift: after samples of 1e8 leave the window, S is that of the small samples alone to
// rounding (an add-and-subtract running sum would keep an error of ~1e16 * 1e-16 = O(1) >> 1e-6).
TEST(Glr, WindowSumDoesNotDrift) {
  GlrParams p;
  p.window = 10;
  GlrState state;
  for (int k = 0; k < 1000; ++k) step_glr(p, state, Vec3(1e8 * (1 + k % 7), 0, 0));
  double s = 0.0;
  for (int k = 0; k < 10; ++k) s = step_glr(p, state, Vec3(1e-3 * (k + 1), 0, 0)).statistic.value();
  std::deque<double> w;
  for (int k = 0; k < 10; ++k) w.push_back(1e-3 * (k + 1));
  EXPECT_NEAR(s, eq41_direct(w, 1.0), 1e-12 * eq41_direct(w, 1.0));
}

// The scalar test decides on rho against the roots of eq. 41 = J_th (no logarithm per period).
// The roots solve it (to 1e-12 of J_th: a few ulp of rho - ln rho - 1 near them), and the decision
// is eq. 40 on the reported S for every rho, including those within an ulp of either root, for
// windows and thresholds where the lower root is ordinary, tiny, or below the floor.
TEST(Glr, DecisionByRatioBoundsIsEq40) {
  for (const int window : {2, 10, 128}) {
    for (const double threshold : {0.5, 20.0, 500.0}) {
      const GlrRatioBounds b = glr_ratio_bounds(window, threshold);
      ASSERT_LT(b.lo, 1.0);
      ASSERT_GT(b.hi, 1.0);
      EXPECT_NEAR(glr_scalar_statistic(b.hi, window), threshold, 1e-12 * threshold) << window << " " << threshold;
      if (b.lo > kGlrVarianceFloor) {
        EXPECT_NEAR(glr_scalar_statistic(b.lo, window), threshold, 1e-12 * threshold) << window << " " << threshold;
      }
      std::vector<double> rhos = {1e-300, 1e-12, 0.3, 1.0, 1.7, 1e3};
      for (const double root : {b.lo, b.hi}) {
        for (const double rel : {-1e-3, -1e-6, -1e-9, -1e-14, -4e-16, 0.0, 4e-16, 1e-14, 1e-9, 1e-6, 1e-3})
          rhos.push_back(root * (1.0 + rel));
      }
      for (const GlrSides sides : {GlrSides::kTwoSided, GlrSides::kIncreaseOnly}) {
        GlrParams p;
        p.window = window;
        p.threshold = threshold;
        p.sigma0 = 0.5;
        p.sides = sides;
        int alarms = 0;
        for (const double rho : rhos) {
          GlrState state;
          GlrOutput out;
          for (int k = 0; k < window; ++k) out = step_glr(p, state, Vec3(0.5 * std::sqrt(rho), 0.0, 0.0));
          EXPECT_EQ(out.alarm, out.statistic.value() > threshold) << window << " " << threshold << " rho " << rho;
          alarms += out.alarm;
        }
        EXPECT_GT(alarms, 0);  // the grid does reach beyond the upper root
      }
    }
  }
}

TEST(Glr, ValidateNamesTheProblems) {
  GlrParams p;
  EXPECT_TRUE(validate(p).empty());
  p.window = 129;
  p.sigma0 = 0.0;
  EXPECT_EQ(validate(p).size(), 2u);
  GlrParams w;
  w.variant = GlrVariant::kWhitened;
  w.residual_dim = 3;
  w.window = 3;
  w.covariance0(2, 2) = -1.0;
  const std::vector<std::string> problems = validate(w);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_NE(problems[0].find("covariance0"), std::string::npos);
}

}  // namespace
}  // namespace chaser::flight::fdi
