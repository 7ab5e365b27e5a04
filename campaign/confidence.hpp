#pragma once
// Exact (Clopper-Pearson) confidence bounds for a binomial proportion, and the zero-failure
// demonstration run count. A campaign's P_nd, P_f, P_i and mission rates are proportions of runs;
// these say how far the true rate may be from the one observed.
//
// Clopper and Pearson 1934 (Biometrika 26(4), 404-413), in the Beta-quantile form given by Brown,
// Cai and DasGupta 2001 (Statistical Science 16(2), 101-133). With x events in n runs and
// B(q; a, b) the q-quantile of the Beta(a, b) distribution (Boost.Math's ibeta_inv):
//   two-sided, level 1 - alpha:  [B(alpha/2; x, n - x + 1), B(1 - alpha/2; x + 1, n - x)],
//                                 lower = 0 at x = 0, upper = 1 at x = n;
//   one-sided upper, level C:    B(C; x + 1, n - x)          (1 at x = n),
//   one-sided lower, level C:    B(1 - C; x, n - x + 1)      (0 at x = 0).
// At x = 0 the one-sided upper bound is 1 - (1 - C)^(1/n): "0 failures in n runs" shows p <= that
// with confidence C, which gives the zero-failure demonstration count below.
//
// The intervals are exact in the sense of never covering less than the stated level (they cover
// more, being built from a discrete distribution): conservative, as a verification claim should be.
#include <cstdint>

namespace chaser::campaign {

// The confidence level of every interval in summary.csv and summary.md.
inline constexpr double kSummaryConfidence = 0.95;

struct ProportionInterval {
  double lower = 0.0;  // [-]
  double upper = 1.0;  // [-]
};

// Preconditions (else NaN bounds): 0 <= events <= trials, trials >= 1, 0 < confidence < 1.
ProportionInterval clopper_pearson(std::int64_t events, std::int64_t trials, double confidence);
double clopper_pearson_upper(std::int64_t events, std::int64_t trials, double confidence);
double clopper_pearson_lower(std::int64_t events, std::int64_t trials, double confidence);

// Smallest n such that n runs without a failure show "failure probability <= p_max at confidence
// C": the smallest n with clopper_pearson_upper(0, n, C) <= p_max, i.e. (1 - p_max)^n <= 1 - C,
// n = ceil(ln(1 - C) / ln(1 - p_max)) (the "success run" theorem; e.g. p_max = 1e-3, C = 0.95:
// 2,995 runs). 0 < p_max < 1, 0 < C < 1; -1 if n would exceed kMaxDemonstrationRuns.
inline constexpr std::int64_t kMaxDemonstrationRuns = 1'000'000'000'000'000;  // 10^15
std::int64_t zero_failure_runs(double p_max, double confidence);

}  // namespace chaser::campaign
