#include "campaign/target_report.hpp"

#include <fmt/format.h>

#include "campaign/proportion_text.hpp"

namespace chaser::campaign {

namespace {

// What counts as a failure against each index's target (plural).
std::string_view failures_name(RateIndex i) {
  switch (i) {
    case RateIndex::kPNd: return "missed detections";
    case RateIndex::kPF: return "false alarms";
    case RateIndex::kPI: return "runs without a right isolation";
    case RateIndex::kCaptureRate: return "runs without capture";
    case RateIndex::kCorridorRate: return "runs out of the corridor";
  }
  return "";
}

bool is_mission(RateIndex i) { return i == RateIndex::kCaptureRate || i == RateIndex::kCorridorRate; }

// "P_nd <= 0.1 % at 95 %"
std::string claim(const Target& t, double bound, Rounding rounding) {
  return fmt::format("{} {} {} at {:g} %", to_string(t.index), t.at_most ? "<=" : ">=",
                     rounding == Rounding::kNearest ? fmt::format("{:g} %", 100 * bound) : percent(bound, rounding),
                     100 * t.confidence);
}

// The target stated once, with its zero-failure run count; `name` is its text as given, decorated.
std::string heading(const Target& t, const std::string& name) {
  return fmt::format("{}: {}; a case demonstrates it with {} run{} and 0 {}", name,
                     claim(t, t.bound, Rounding::kNearest), with_thousands(t.zero_failure_runs),
                     t.zero_failure_runs == 1 ? "" : "s", failures_name(t.index));
}

// The verdict on one case (and scheme); nullopt where the index means nothing or the case has no run.
// Terminal: "demonstrated: P_nd <= 0.0999 % at 95 % (0 missed detections in 3,000 runs)";
// table cell: "yes: <= 0.0999 % (0 of 3,000)".
std::optional<std::string> verdict(const Target& t, const SchemeCaseStats& s, FaultCase c, bool cell) {
  const auto observed = proportion_of(s, t.index, c);
  if (!observed || observed->runs <= 0) return std::nullopt;
  const TargetVerdict v = judge_target(t, *observed);
  const Rounding outward = t.at_most ? Rounding::kUp : Rounding::kDown;
  if (cell)
    return fmt::format("{}: {} {} ({} of {})", v.demonstrated ? "**yes**" : "no", t.at_most ? "<=" : ">=",
                       percent(v.index_bound, outward), with_thousands(v.failures.events),
                       with_thousands(v.failures.runs));
  return fmt::format("{}: {} ({} {} in {} runs)", v.demonstrated ? "demonstrated" : "not demonstrated",
                     claim(t, v.index_bound, outward), with_thousands(v.failures.events), failures_name(t.index),
                     with_thousands(v.failures.runs));
}

}  // namespace

std::string targets_markdown(const CampaignStats& stats, const std::vector<Target>& targets) {
  if (targets.empty()) return "";
  std::string out =
      "\n### Targets (--target)\n\nA case demonstrates a target when the one-sided Clopper-Pearson bound at the "
      "target's confidence, from that case's runs, is within the target (upper bound for P_nd and P_f, lower bound "
      "for the others). With no failure that takes n = ceil(ln(1 - C) / ln(1 - f)) runs, f the largest failure rate "
      "the target allows (p of '<= p', 1 - q of '>= q').\n";
  for (const Target& t : targets) {
    fmt::format_to(std::back_inserter(out),
                   "\n{}. Cells: demonstrated?, the one-sided {:g} % bound on {} from the case's runs, and {} of "
                   "runs.\n\n| {} |",
                   heading(t, fmt::format("`{}`", t.text)), 100 * t.confidence, to_string(t.index),
                   failures_name(t.index), is_mission(t.index) ? "mission" : "scheme");
    for (FaultCase c : stats.cases()) fmt::format_to(std::back_inserter(out), " {} |", to_string(c));
    out += "\n|---|";
    for (std::size_t i = 0; i < stats.cases().size(); ++i) out += "---|";
    out += '\n';
    // The mission rates are the same whatever the scheme (statistics.cpp): one row.
    const std::size_t rows = is_mission(t.index) ? 1 : statistics_schemes().size();
    for (std::size_t k = 0; k < rows; ++k) {
      fmt::format_to(std::back_inserter(out), "| {} |", is_mission(t.index) ? "all schemes" : statistics_schemes()[k]);
      for (std::size_t c = 0; c < stats.cases().size(); ++c) {
        const auto v = verdict(t, stats.at(c, k), stats.cases()[c], true);
        fmt::format_to(std::back_inserter(out), " {} |", v.value_or("-"));
      }
      out += '\n';
    }
  }
  return out;
}

std::string targets_text(const CampaignStats& stats, const std::vector<Target>& targets) {
  std::string out;
  for (const Target& t : targets) {
    fmt::format_to(std::back_inserter(out), "target {}\n", heading(t, t.text));
    const std::size_t rows = is_mission(t.index) ? 1 : statistics_schemes().size();
    for (std::size_t k = 0; k < rows; ++k)
      for (std::size_t c = 0; c < stats.cases().size(); ++c)
        if (const auto v = verdict(t, stats.at(c, k), stats.cases()[c], false))
          fmt::format_to(std::back_inserter(out), "  {}{}: {}\n",
                         is_mission(t.index) ? "" : statistics_schemes()[k] + " ", to_string(stats.cases()[c]), *v);
  }
  return out;
}

}  // namespace chaser::campaign
