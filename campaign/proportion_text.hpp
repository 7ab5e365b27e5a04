#pragma once
// How summary.md and the terminal write a proportion and its confidence bounds: as a percentage
// with enough decimals to show its distance to 0 % or 100 % (0.19 %, 99.9970 %), bounds rounded
// outward so that the printed interval still contains the computed one, counts with thousands
// separators (1,600).
#include <cstdint>
#include <string>

#include "campaign/statistics.hpp"

namespace chaser::campaign {

enum class Rounding { kNearest, kUp, kDown };

std::string with_thousands(std::int64_t n);  // 1600 -> "1,600"

// 100 v with two decimals, or two significant digits of min(v, 1 - v) where that is below 0.1 %;
// then " %". "nan" for NaN.
std::string percent(double v, Rounding rounding = Rounding::kNearest);

// One proportion with its 95 % bounds (kSummaryConfidence), for a table cell:
//   no run: "-";
//   no event: "0 of 1,600 (<= 0.19 %)", the one-sided upper bound 1 - 0.05^(1/n);
//   every run an event: "1,600 of 1,600 (>= 99.81 %)", the one-sided lower bound 0.05^(1/n);
//   otherwise: "0.88 % [0.47 %, 1.47 %]" (14 of 1,600), the two-sided Clopper-Pearson interval.
std::string proportion_cell(const Proportion& p);

}  // namespace chaser::campaign
