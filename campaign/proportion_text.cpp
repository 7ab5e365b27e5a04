#include "campaign/proportion_text.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "campaign/confidence.hpp"

namespace chaser::campaign {

std::string with_thousands(std::int64_t n) {
  std::string digits = fmt::format("{}", n < 0 ? -n : n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return n < 0 ? "-" + out : out;
}

std::string percent(double v, Rounding rounding) {
  if (std::isnan(v)) return "nan";
  const double pct = 100.0 * v;
  const double tail = 100.0 * std::min(v, 1.0 - v);  // [%] distance to 0 % or 100 %
  int decimals = 2;  // at most 9: 100 % x 10^9 stays below 2^53, so the scaled value is exact to 1e-5
  if (tail > 0.0 && tail < 0.1) decimals = std::min(9, 1 - static_cast<int>(std::floor(std::log10(tail))));
  const double scaled = pct * std::pow(10.0, decimals);
  // Outward rounding with a slack of 1e-4 of the last digit, so that a value printed exactly (0.19
  // from a scaled 19.000000000000004) is not pushed one digit out by its representation error.
  double shown = pct;
  if (rounding == Rounding::kUp) shown = std::ceil(scaled - 1e-4) / std::pow(10.0, decimals);
  if (rounding == Rounding::kDown) shown = std::floor(scaled + 1e-4) / std::pow(10.0, decimals);
  return fmt::format("{:.{}f} %", shown, decimals);
}

std::string proportion_cell(const Proportion& p) {
  if (p.runs <= 0) return "-";
  const double c = kSummaryConfidence;
  if (p.events == 0)
    return fmt::format("0 of {} (<= {})", with_thousands(p.runs),
                       percent(clopper_pearson_upper(0, p.runs, c), Rounding::kUp));
  if (p.events == p.runs)
    return fmt::format("{0} of {0} (>= {1})", with_thousands(p.runs),
                       percent(clopper_pearson_lower(p.runs, p.runs, c), Rounding::kDown));
  const ProportionInterval ci = clopper_pearson(p.events, p.runs, c);
  return fmt::format("{} [{}, {}]", percent(static_cast<double>(p.events) / static_cast<double>(p.runs)),
                     percent(ci.lower, Rounding::kDown), percent(ci.upper, Rounding::kUp));
}

}  // namespace chaser::campaign
