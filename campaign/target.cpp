#include "campaign/target.hpp"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "campaign/confidence.hpp"

namespace chaser::campaign {

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  return s;
}

// A number in the open interval (0, 1), the whole field.
std::optional<double> fraction(std::string_view field) {
  field = trim(field);
  double value = 0;
  const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (field.empty() || ec != std::errc() || end != field.data() + field.size()) return std::nullopt;
  if (!(value > 0.0 && value < 1.0)) return std::nullopt;  // NaN fails too
  return value;
}

std::optional<RateIndex> rate_index(std::string_view name) {
  for (RateIndex i : kRateIndices)
    if (to_string(i) == name) return i;
  return std::nullopt;
}

// The index's direction: a failure rate is bounded from above, a success rate from below.
bool bounded_above(RateIndex i) { return i == RateIndex::kPNd || i == RateIndex::kPF; }

}  // namespace

TargetParse parse_target(std::string_view text) {
  const auto fail = [&](std::string_view what) {
    return TargetParse{std::nullopt, fmt::format("--target '{}': {}; expected {}", text, what, kTargetGrammar)};
  };
  const std::size_t at = text.find('@');
  if (at == std::string_view::npos || text.find('@', at + 1) != std::string_view::npos)
    return fail("give the confidence once, after '@'");
  const std::string_view claim = text.substr(0, at);
  std::size_t op = claim.find("<=");
  const bool at_most = op != std::string_view::npos;
  if (!at_most) op = claim.find(">=");
  if (op == std::string_view::npos) return fail("no '<=' or '>='");
  const std::string_view name = trim(claim.substr(0, op));
  const auto index = rate_index(name);
  if (!index) return fail(fmt::format("unknown index '{}'", name));
  if (at_most != bounded_above(*index))
    return fail(fmt::format("{} takes '{}'", name, bounded_above(*index) ? "<=" : ">="));
  const auto bound = fraction(claim.substr(op + 2));
  if (!bound) return fail(fmt::format("the bound '{}' is not a number in (0, 1)", trim(claim.substr(op + 2))));
  const auto confidence = fraction(text.substr(at + 1));
  if (!confidence) return fail(fmt::format("the confidence '{}' is not a number in (0, 1)", trim(text.substr(at + 1))));
  Target t{std::string(text), *index, at_most, *bound, *confidence, 0};
  t.zero_failure_runs = zero_failure_runs(t.failure_max(), t.confidence);
  if (t.zero_failure_runs < 0)
    return fail(fmt::format("demonstrating it would take more than {} runs", kMaxDemonstrationRuns));
  return {t, ""};
}

TargetVerdict judge_target(const Target& target, const Proportion& observed) {
  const Proportion failures{target.at_most ? observed.events : observed.runs - observed.events, observed.runs};
  const double upper = clopper_pearson_upper(failures.events, failures.runs, target.confidence);
  return {failures, upper, target.at_most ? upper : 1.0 - upper, upper <= target.failure_max()};
}

}  // namespace chaser::campaign
