// Clopper-Pearson bounds against their closed forms, their defining equations, published values,
// and the zero-failure demonstration count against its closed form.
#include "campaign/confidence.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

namespace chaser::campaign {
namespace {

// Half a unit in the last of `digits` significant digits of `printed`: a value printed so (R prints
// 7 by default) is the true one to within this.
double half_unit(double printed, int digits = 7) {
  return 0.5 * std::pow(10.0, std::floor(std::log10(std::abs(printed))) - (digits - 1));
}

// P(X <= x) and P(X >= x) for X ~ Binomial(n, p), summed term by term in logs (lgamma): an
// evaluation independent of the incomplete beta function the bounds come from.
double binomial_pmf(std::int64_t k, std::int64_t n, double p) {
  const double log_choose = std::lgamma(n + 1.0) - std::lgamma(k + 1.0) - std::lgamma(n - k + 1.0);
  return std::exp(log_choose + k * std::log(p) + (n - k) * std::log1p(-p));
}
double binomial_cdf(std::int64_t x, std::int64_t n, double p) {
  double sum = 0;
  for (std::int64_t k = 0; k <= x; ++k) sum += binomial_pmf(k, n, p);
  return sum;
}
double binomial_sf(std::int64_t x, std::int64_t n, double p) {
  double sum = 0;
  for (std::int64_t k = x; k <= n; ++k) sum += binomial_pmf(k, n, p);
  return sum;
}

// x = 0: the Beta(1, n) quantile is 1 - (1 - q)^(1/n); x = n: the Beta(n, 1) quantile is q^(1/n).
// Boost evaluates both in closed form in long double (its a == 1 / b == 1 branch), the reference
// here in double with expm1/log. Measured: 3.5e-16 relative at most (1.6 ulp); 1e-14 leaves a
// margin of 30 for other compilers' libm and still fails for any other formula.
TEST(ClopperPearson, NoEventAndEveryRunMatchTheirClosedForms) {
  for (std::int64_t n : {1, 2, 3, 10, 200, 1600, 100000}) {
    for (double confidence : {0.9, 0.95, 0.99}) {
      const double alpha = 1 - confidence;
      const ProportionInterval none = clopper_pearson(0, n, confidence);
      EXPECT_EQ(none.lower, 0.0);
      const double upper = -std::expm1(std::log(alpha / 2) / static_cast<double>(n));
      EXPECT_NEAR(none.upper, upper, 1e-14 * upper) << n;
      const ProportionInterval all = clopper_pearson(n, n, confidence);
      EXPECT_EQ(all.upper, 1.0);
      const double lower = std::exp(std::log(alpha / 2) / static_cast<double>(n));
      EXPECT_NEAR(all.lower, lower, 1e-14 * lower) << n;
      // One-sided, level C: 1 - (1 - C)^(1/n) and (1 - C)^(1/n).
      const double one_sided = -std::expm1(std::log(alpha) / static_cast<double>(n));
      EXPECT_NEAR(clopper_pearson_upper(0, n, confidence), one_sided, 1e-14 * one_sided) << n;
      EXPECT_NEAR(clopper_pearson_lower(n, n, confidence), 1 - one_sided, 1e-14) << n;
      EXPECT_EQ(clopper_pearson_upper(n, n, confidence), 1.0);
      EXPECT_EQ(clopper_pearson_lower(0, n, confidence), 0.0);
    }
  }
}

// One run: the interval is [0, 1 - alpha/2] with no event and [alpha/2, 1] with one, and the
// one-sided bounds are C and 1 - C (closed forms; exact in binary up to the one rounding of 1 - C).
TEST(ClopperPearson, OneRun) {
  const ProportionInterval none = clopper_pearson(0, 1, 0.95), one = clopper_pearson(1, 1, 0.95);
  EXPECT_EQ(none.lower, 0.0);
  EXPECT_NEAR(none.upper, 0.975, 1e-15);
  EXPECT_NEAR(one.lower, 0.025, 1e-15);
  EXPECT_EQ(one.upper, 1.0);
  EXPECT_NEAR(clopper_pearson_upper(0, 1, 0.95), 0.95, 1e-15);
  EXPECT_NEAR(clopper_pearson_lower(1, 1, 0.95), 0.05, 1e-15);
}

// R's binom.test (stats package; Clopper-Pearson, "Confidence intervals are obtained by a
// procedure first given in Clopper and Pearson (1934)", R documentation of binom.test), values as
// R prints them (7 significant digits):
//   binom.test(5, 20)$conf.int                      0.08657147 0.49104587
//   binom.test(0, 1600)$conf.int                    0            0.002303 (4 digits)
//   binom.test(9, 24, 1/6)                          0.1879929  0.5940636
//   binom.test(1, 1497, 0.0033, conf.level = 0.9)   3.426347e-05 3.164954e-03
// (the first two from the issue, which quotes R; the last two are R output quoted in the blog post
// "r binom test confidence interval", November 2020, Examples 2 and 3);
// and GenBinomApps' clopper.pearson.ci(5, 100000, alpha = 0.05), a one-sided upper limit, whose
// documented example prints Upper.limit = 0.0001051275 (rdrr.io/cran/GenBinomApps, clopper.pearson.ci).
// Tolerance: half a unit in the last printed digit (plus 1e-16 for our own rounding).
TEST(ClopperPearson, MatchesPublishedValues) {
  struct Case {
    std::int64_t x, n;
    double confidence, lower, upper;
  };
  for (const Case& c : {Case{5, 20, 0.95, 0.08657147, 0.49104587}, Case{9, 24, 0.95, 0.1879929, 0.5940636},
                        Case{1, 1497, 0.9, 3.426347e-05, 3.164954e-03}}) {
    const ProportionInterval ci = clopper_pearson(c.x, c.n, c.confidence);
    EXPECT_NEAR(ci.lower, c.lower, half_unit(c.lower) + 1e-16) << c.x << " of " << c.n;
    EXPECT_NEAR(ci.upper, c.upper, half_unit(c.upper) + 1e-16) << c.x << " of " << c.n;
  }
  EXPECT_EQ(clopper_pearson(0, 1600, 0.95).lower, 0.0);
  EXPECT_NEAR(clopper_pearson(0, 1600, 0.95).upper, 0.002303, half_unit(0.002303, 4));  // as the issue quotes it
  EXPECT_NEAR(clopper_pearson_upper(5, 100000, 0.95), 0.0001051275, half_unit(0.0001051275));
}

// The defining equations (Clopper and Pearson 1934): at the upper bound u, P(X <= x; n, u) =
// alpha/2; at the lower bound l, P(X >= x; n, l) = alpha/2. The sums of at most 138 lgamma-based
// terms carry ~1e-13 relative error (lgamma(138) ~ 540, its last bit ~1e-13); measured 1.4e-13 at
// most. 1e-11 relative leaves a margin of 70, and a bound off by 1e-9 of itself moves the tail
// probability by more than that.
TEST(ClopperPearson, SolvesItsDefiningEquations) {
  for (std::int64_t n : {1, 7, 20, 137}) {
    for (std::int64_t x = 0; x <= n; ++x) {
      const ProportionInterval ci = clopper_pearson(x, n, 0.95);
      if (x < n) {
        EXPECT_NEAR(binomial_cdf(x, n, ci.upper), 0.025, 0.025 * 1e-11) << x << " of " << n;
        const double upper90 = clopper_pearson_upper(x, n, 0.9);  // one-sided: the whole alpha on one side
        EXPECT_NEAR(binomial_cdf(x, n, upper90), 0.1, 0.1 * 1e-11) << x << " of " << n;
      }
      if (x > 0) {
        EXPECT_NEAR(binomial_sf(x, n, ci.lower), 0.025, 0.025 * 1e-11) << x << " of " << n;
      }
    }
  }
}

// More events never lower a bound; the interval holds the observed proportion; the two sides
// mirror each other (lower(x, n) = 1 - upper(n - x, n)).
TEST(ClopperPearson, MonotoneInEventsContainsTheEstimateAndIsSymmetric) {
  for (std::int64_t n : {1, 5, 50, 1600}) {
    ProportionInterval previous{-1.0, -1.0};
    for (std::int64_t x = 0; x <= n; ++x) {
      const ProportionInterval ci = clopper_pearson(x, n, 0.95);
      EXPECT_GT(ci.lower, previous.lower) << x << " of " << n;
      EXPECT_GT(ci.upper, previous.upper) << x << " of " << n;
      const double estimate = static_cast<double>(x) / static_cast<double>(n);
      EXPECT_LE(ci.lower, estimate);
      EXPECT_GE(ci.upper, estimate);
      const ProportionInterval mirror = clopper_pearson(n - x, n, 0.95);
      EXPECT_NEAR(ci.lower, 1 - mirror.upper, 1e-15) << x << " of " << n;  // measured 1.1e-16 (1 ulp of 1)
      previous = ci;
    }
  }
}

TEST(ClopperPearson, OutsideItsDomainGivesNaN) {
  EXPECT_TRUE(std::isnan(clopper_pearson(0, 0, 0.95).upper));   // no run
  EXPECT_TRUE(std::isnan(clopper_pearson(3, 2, 0.95).lower));   // more events than runs
  EXPECT_TRUE(std::isnan(clopper_pearson(-1, 2, 0.95).lower));
  EXPECT_TRUE(std::isnan(clopper_pearson_upper(1, 2, 1.0)));
  EXPECT_TRUE(std::isnan(clopper_pearson_lower(1, 2, 0.0)));
}

// p = 1e-3 at C = 0.95: ln(0.05) / ln(0.999) = 2994.23, so 2,995 runs (the "rule of three": about
// 3 / p). Across a grid, the count is the smallest n with (1 - p)^n <= 1 - C, and the bound of
// that many clean runs meets the target while one run fewer does not.
TEST(ZeroFailureRuns, IsTheClosedFormAndAgreesWithTheBound) {
  EXPECT_EQ(zero_failure_runs(1e-3, 0.95), 2995);
  EXPECT_EQ(zero_failure_runs(0.01, 0.95), 299);  // ln(0.05) / ln(0.99) = 298.07
  EXPECT_EQ(zero_failure_runs(0.01, 0.9), 230);   // ln(0.1) / ln(0.99) = 229.1
  EXPECT_EQ(zero_failure_runs(0.5, 0.75), 2);     // 0.5^2 = 0.25 exactly: a tie demonstrates it
  for (double p : {0.3, 0.05, 1e-3, 1e-5}) {
    for (double confidence : {0.5, 0.9, 0.95, 0.999}) {
      const std::int64_t n = zero_failure_runs(p, confidence);
      const double ratio = std::log1p(-confidence) / std::log1p(-p);
      EXPECT_EQ(n, static_cast<std::int64_t>(std::ceil(ratio))) << p << " " << confidence;
      EXPECT_LE(clopper_pearson_upper(0, n, confidence), p);
      if (n > 1) {
        EXPECT_GT(clopper_pearson_upper(0, n - 1, confidence), p);
      }
    }
  }
  // p = C: one clean run bounds p by exactly C (Beta(1, 1) is uniform), a tie that rounding
  // decides: Boost forms 1 - (1 - C) and gets C (1 + 1e-15) for C = 0.01. The count then follows
  // the bound, not the closed form's 1, so that the count and the verdict never disagree.
  for (double p : {0.001, 0.01, 0.3}) {
    const std::int64_t n = zero_failure_runs(p, p);
    EXPECT_LE(clopper_pearson_upper(0, n, p), p) << p;
    if (n > 1) {
      EXPECT_GT(clopper_pearson_upper(0, n - 1, p), p) << p;
    }
    EXPECT_LE(n, 2) << p;
  }
  EXPECT_EQ(zero_failure_runs(0.0, 0.95), -1);
  EXPECT_EQ(zero_failure_runs(1e-18, 0.95), -1);  // 3e18 runs: beyond kMaxDemonstrationRuns
  EXPECT_EQ(zero_failure_runs(0.5, 1.0), -1);
}

}  // namespace
}  // namespace chaser::campaign
