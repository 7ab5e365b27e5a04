#pragma once
// chaser campaign --target: a requirement on one of the campaign's proportions at a confidence
// level, "P_nd<=1e-3@0.95" (P_nd <= 0.1 % with 95 % confidence), and whether a case's runs
// demonstrate it (docs/campaigns.md, "Targets").
//
// A target bounds a rate of failures, f <= f_max: for P_nd and P_f the failure is the event itself
// (f_max = p); for P_i, capture_rate and corridor_rate (">= q") it is the run without the event
// (f_max = 1 - q). A case demonstrates the target when the one-sided Clopper-Pearson upper bound
// at confidence C on its failure rate is <= f_max (confidence.hpp); with no failure that takes
// zero_failure_runs(f_max, C) runs.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "campaign/statistics.hpp"

namespace chaser::campaign {

struct Target {
  std::string text;    // as given, for messages and the summary
  RateIndex index = RateIndex::kPNd;
  bool at_most = true; // "<=" (P_nd, P_f) or ">=" (P_i, capture_rate, corridor_rate)
  double bound = 0.0;  // [-] p of "<= p" or q of ">= q", in (0, 1)
  double confidence = 0.95;  // [-] C, in (0, 1)
  std::int64_t zero_failure_runs = 0;  // runs that demonstrate it if none fails
  double failure_max() const { return at_most ? bound : 1.0 - bound; }  // [-] f_max
};

// The accepted grammar, for messages and --help.
inline constexpr std::string_view kTargetGrammar =
    "INDEX<=P@C with INDEX P_nd or P_f, or INDEX>=Q@C with INDEX P_i, capture_rate or corridor_rate; "
    "P, Q and C in (0, 1) (e.g. 'P_nd<=1e-3@0.95', 'capture_rate>=0.99@0.9')";

struct TargetParse {
  std::optional<Target> target;
  std::string error;  // names --target, the text and the grammar
};
TargetParse parse_target(std::string_view text);

struct TargetVerdict {
  Proportion failures;   // failures of runs
  double failure_upper;  // [-] one-sided upper bound at C on the failure rate; NaN with no run
  double index_bound;    // [-] the same bound on the index: upper for "<=", lower (1 - failure_upper) for ">="
  bool demonstrated;
};
// `observed`: the index's own counts (proportion_of).
TargetVerdict judge_target(const Target& target, const Proportion& observed);

}  // namespace chaser::campaign
