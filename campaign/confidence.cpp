#include "campaign/confidence.hpp"

#include "campaign/table_cells.hpp"

#include <cmath>
#include <limits>

#include <boost/math/special_functions/beta.hpp>

namespace chaser::campaign {

namespace {

bool valid(std::int64_t events, std::int64_t trials, double confidence) {
  return trials >= 1 && events >= 0 && events <= trials && confidence > 0.0 && confidence < 1.0;
}

// B(q; x + 1, n - x) as the complement's inverse: q near 1 is then passed as the small 1 - q, which
// Boost takes without the rounding of forming 1 - q in double (ibetac_inv, Boost.Math "The
// Incomplete Beta Function Inverses").
double upper_quantile(std::int64_t events, std::int64_t trials, double tail) {
  if (events == trials) return 1.0;
  return boost::math::ibetac_inv(static_cast<double>(events + 1), static_cast<double>(trials - events), tail);
}

// B(tail; x, n - x + 1).
double lower_quantile(std::int64_t events, std::int64_t trials, double tail) {
  if (events == 0) return 0.0;
  return boost::math::ibeta_inv(static_cast<double>(events), static_cast<double>(trials - events + 1), tail);
}

}  // namespace

ProportionInterval clopper_pearson(std::int64_t events, std::int64_t trials, double confidence) {
  if (!valid(events, trials, confidence)) return {kNaN, kNaN};
  const double tail = 0.5 * (1.0 - confidence);  // alpha / 2 on each side
  return {lower_quantile(events, trials, tail), upper_quantile(events, trials, tail)};
}

double clopper_pearson_upper(std::int64_t events, std::int64_t trials, double confidence) {
  return valid(events, trials, confidence) ? upper_quantile(events, trials, 1.0 - confidence) : kNaN;
}

double clopper_pearson_lower(std::int64_t events, std::int64_t trials, double confidence) {
  return valid(events, trials, confidence) ? lower_quantile(events, trials, 1.0 - confidence) : kNaN;
}

std::int64_t zero_failure_runs(double p_max, double confidence) {
  if (!(p_max > 0.0 && p_max < 1.0 && confidence > 0.0 && confidence < 1.0)) return -1;
  const double n_real = std::log1p(-confidence) / std::log1p(-p_max);
  if (!(n_real <= static_cast<double>(kMaxDemonstrationRuns))) return -1;
  // The closed form rounded up, then moved to the smallest n that the bound itself accepts, so
  // that a campaign of exactly this many clean runs is reported as demonstrating the target. The
  // two differ only at ties, where ln(1 - C) / ln(1 - p) is an integer and rounding decides: p = C
  // gives 1 run by the formula, but Boost's bound for it is 1 - (1 - C), a hair above C.
  std::int64_t n = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(n_real)));
  while (n > 1 && clopper_pearson_upper(0, n - 1, confidence) <= p_max) --n;
  while (clopper_pearson_upper(0, n, confidence) > p_max) ++n;
  return n;
}

}  // namespace chaser::campaign
