#include "campaign/cases.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <stdexcept>

#include <fmt/format.h>

namespace chaser::campaign {

namespace {

constexpr std::array<FaultCase, 5> kAllCases = {FaultCase::kNone, FaultCase::kStuckOpen, FaultCase::kStuckClosed,
                                                FaultCase::kLeak, FaultCase::kLoss};

std::vector<std::string_view> split(std::string_view text, char sep) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t at = text.find(sep, start);
    parts.push_back(text.substr(start, at == std::string_view::npos ? std::string_view::npos : at - start));
    if (at == std::string_view::npos) return parts;
    start = at + 1;
  }
}

// A whole number >= 1 written in full (no sign, no trailing text).
std::optional<std::int64_t> positive_count(std::string_view text) {
  std::int64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || value <= 0) return std::nullopt;
  return value;
}

std::optional<int> whole(std::string_view text) {
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

}  // namespace

std::string_view to_string(FaultCase c) {
  switch (c) {
    case FaultCase::kNone: return "none";
    case FaultCase::kStuckOpen: return "stuck_open";
    case FaultCase::kStuckClosed: return "stuck_closed";
    case FaultCase::kLeak: return "leak";
    case FaultCase::kLoss: return "loss";
  }
  return "none";
}

std::optional<FaultCase> parse_case(std::string_view name) {
  for (FaultCase c : kAllCases)
    if (name == to_string(c)) return c;
  return std::nullopt;
}

RunLayout::RunLayout(std::vector<CaseRuns> cases) : cases_(std::move(cases)) {
  for (const CaseRuns& c : cases_) total_ += c.runs;
}

FaultCase RunLayout::case_of(std::int64_t run) const {
  for (const CaseRuns& c : cases_) {
    if (run < c.runs) return c.fault_case;
    run -= c.runs;
  }
  throw std::out_of_range(fmt::format("run index beyond the campaign's {} runs", total_));
}

RunRange shard_range(const Shard& shard, std::int64_t total_runs) {
  // Blocks of N / m runs, the first N % m shards one run longer: exact, no overflow.
  const std::int64_t base = total_runs / shard.count, extra = total_runs % shard.count;
  const auto edge = [&](std::int64_t i) { return i * base + std::min(i, extra); };
  return RunRange{edge(shard.index), edge(shard.index + 1)};
}

ShardParse parse_shard(std::string_view text) {
  const std::string usage = fmt::format("--shard: expected I/M with whole numbers 0 <= I < M (got '{}')", text);
  const std::size_t slash = text.find('/');
  if (slash == std::string_view::npos) return {std::nullopt, usage};
  const auto i = whole(text.substr(0, slash));
  const auto m = whole(text.substr(slash + 1));
  if (!i || !m || *m < 1 || *i < 0 || *i >= *m) return {std::nullopt, usage};
  return {Shard{*i, *m}, ""};
}

LayoutParse parse_layout(std::string_view cases_text, std::string_view runs_text, std::int64_t default_runs) {
  LayoutParse out;
  if (cases_text.empty())
    for (FaultCase c : kAllCases) out.cases.push_back({c, default_runs});
  else
    for (std::string_view name : split(cases_text, ',')) {
      const auto c = parse_case(name);
      if (!c) return {{}, fmt::format("--cases: unknown case '{}' (allowed: {})", name, kCaseNames)};
      for (const CaseRuns& seen : out.cases)
        if (seen.fault_case == *c) return {{}, fmt::format("--cases: case '{}' listed twice", name)};
      out.cases.push_back({*c, default_runs});
    }
  if (runs_text.empty()) return out;
  if (runs_text.find('=') == std::string_view::npos) {  // one count for every case
    const auto n = positive_count(runs_text);
    if (!n) return {{}, fmt::format("--runs: expected a whole number >= 1 or case=N,case=N (got '{}')", runs_text)};
    for (CaseRuns& c : out.cases) c.runs = *n;
    return out;
  }
  if (cases_text.empty()) out.cases.clear();  // the cases are those --runs lists, in its order
  for (std::string_view item : split(runs_text, ',')) {
    const std::size_t eq = item.find('=');
    const auto c = eq == std::string_view::npos ? std::nullopt : parse_case(item.substr(0, eq));
    const auto n = eq == std::string_view::npos ? std::nullopt : positive_count(item.substr(eq + 1));
    if (!c || !n)
      return {{}, fmt::format("--runs: expected case=N with a case in {} and N >= 1 (got '{}')", kCaseNames, item)};
    CaseRuns* target = nullptr;
    for (CaseRuns& seen : out.cases)
      if (seen.fault_case == *c) target = &seen;
    if (cases_text.empty()) {
      if (target) return {{}, fmt::format("--runs: case '{}' given twice", to_string(*c))};
      out.cases.push_back({*c, *n});
      continue;
    }
    if (!target) return {{}, fmt::format("--runs: case '{}' is not in --cases '{}'", to_string(*c), cases_text)};
    target->runs = *n;
  }
  return out;
}

}  // namespace chaser::campaign
