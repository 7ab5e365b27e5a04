#include "campaign/summary.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include <fmt/format.h>

#include "campaign/confidence.hpp"
#include "campaign/csv.hpp"
#include "campaign/proportion_text.hpp"
#include "campaign/run_row.hpp"
#include "campaign/table_cells.hpp"
#include "campaign/target_report.hpp"

namespace chaser::campaign {

namespace {

// Column indices of what the summary reads, found by name in the header.
struct FactColumns {
  int fault_case, status, fault_thruster, capture, corridor, propellant;
  std::array<std::array<int, 5>, kMaxStatisticsSchemes> scheme;  // detection, isolation, isolated, false alarm, missed
  bool complete() const {
    bool ok = fault_case >= 0 && status >= 0 && fault_thruster >= 0 && capture >= 0 && corridor >= 0 && propellant >= 0;
    for (const auto& s : scheme)
      for (int i : s) ok &= i >= 0;
    return ok;
  }
};

FactColumns fact_columns(const std::vector<std::string_view>& h) {
  FactColumns c{column_index(h, "case"), column_index(h, "status"), column_index(h, "fault_thruster"),
                column_index(h, "capture"), column_index(h, "corridor_kept"), column_index(h, "propellant_kg"), {}};
  for (std::size_t k = 0; k < statistics_schemes().size(); ++k) {
    const std::string& s = statistics_schemes()[k];
    c.scheme[k] = {column_index(h, s + "_detection_s"), column_index(h, s + "_isolation_s"),
                   column_index(h, s + "_isolated"), column_index(h, s + "_false_alarm"), column_index(h, s + "_missed")};
  }
  return c;
}

std::optional<RowFacts> row_facts(const std::vector<std::string_view>& f, const FactColumns& c, std::size_t width) {
  if (f.size() != width) return std::nullopt;
  const auto fault_case = parse_case(f[c.fault_case]);
  const auto thruster = parse_integer(f[c.fault_thruster]);
  const auto propellant = parse_number(f[c.propellant]);
  if (!fault_case || !thruster || !propellant) return std::nullopt;
  RowFacts r{};
  r.fault_case = *fault_case;
  r.diverged = f[c.status] == "diverged";
  r.error = f[c.status] == "error";
  r.counted = !r.error;
  r.fault_thruster = model::thruster_index_from_number(*thruster);
  r.capture = f[c.capture] == "1";
  r.corridor_kept = f[c.corridor] == "1";
  r.propellant_kg = *propellant;
  for (std::size_t k = 0; k < statistics_schemes().size(); ++k) {
    const auto& i = c.scheme[k];
    const auto td = parse_number(f[i[0]]), ti = parse_number(f[i[1]]);
    const auto isolated = parse_integer(f[i[2]]);
    if (!td || !ti || !isolated) return std::nullopt;
    r.schemes[k] = SchemeFacts{*td, *ti, model::thruster_index_from_number(*isolated), f[i[3]] == "1", f[i[4]] == "1"};
  }
  return r;
}

double ratio(std::int64_t part, std::int64_t whole) {
  return whole > 0 ? static_cast<double>(part) / static_cast<double>(whole) : kNaN;
}

// The values of one summary row, in the column order of summary.csv after scheme and case.
std::vector<double> row_values(const SchemeCaseStats& s, bool fault) {
  return {static_cast<double>(s.runs), static_cast<double>(s.detected),
          fault ? s.detection_s.mean() : kNaN, fault ? s.detection_s.sample_std() : kNaN,
          fault ? s.isolation_s.mean() : kNaN, fault ? s.isolation_s.sample_std() : kNaN,
          fault ? ratio(s.missed, s.runs) : kNaN, ratio(s.false_alarms, s.runs),
          fault ? ratio(s.right_isolations, s.runs) : kNaN, ratio(s.captures, s.runs),
          ratio(s.corridors_kept, s.runs), s.propellant_kg.mean()};
}

std::string cell(double v, const char* spec) {
  return std::isnan(v) ? std::string("-") : fmt::format(fmt::runtime(spec), v);
}

// A proportion of summary.md with its 95 % bounds (proportion_text.hpp); "-" where it means nothing.
std::string rate_cell(const SchemeCaseStats& s, RateIndex index, FaultCase fault_case) {
  const auto p = proportion_of(s, index, fault_case);
  return p ? proportion_cell(*p) : std::string("-");
}

// summary.csv's last columns: the two-sided 95 % Clopper-Pearson interval of each proportion, in
// kRateNames order, appended after the older columns so that readers by name or position still work.
void append_intervals(std::string& out, const SchemeCaseStats& s, FaultCase fault_case) {
  for (RateIndex index : kRateIndices) {
    const auto p = proportion_of(s, index, fault_case);
    const ProportionInterval ci =
        p ? clopper_pearson(p->events, p->runs, kSummaryConfidence) : ProportionInterval{kNaN, kNaN};
    out += ',';
    append_number(out, ci.lower);
    out += ',';
    append_number(out, ci.upper);
  }
}

void markdown_scheme(std::string& out, const CampaignStats& stats, std::size_t k) {
  fmt::format_to(std::back_inserter(out), "\n### Scheme: {}\n\n| criterion |", statistics_schemes()[k]);
  for (FaultCase c : stats.cases()) fmt::format_to(std::back_inserter(out), " {} |", to_string(c));
  out += "\n|---|";
  for (std::size_t i = 0; i < stats.cases().size(); ++i) out += "---|";
  out += '\n';
  static constexpr std::array<const char*, 6> kRows = {"runs", "detected", "mean t_d [s]", "std t_d [s]",
                                                       "mean t_i [s]", "std t_i [s]"};
  static constexpr std::array<const char*, 6> kSpecs = {"{:.0f}", "{:.0f}", "{:.2f}", "{:.2f}", "{:.2f}", "{:.2f}"};
  for (std::size_t row = 0; row < kRows.size(); ++row) {
    fmt::format_to(std::back_inserter(out), "| {} |", kRows[row]);
    for (std::size_t c = 0; c < stats.cases().size(); ++c) {
      const std::vector<double> v = row_values(stats.at(c, k), stats.cases()[c] != FaultCase::kNone);
      fmt::format_to(std::back_inserter(out), " {} |", cell(v[row], kSpecs[row]));
    }
    out += '\n';
  }
  for (RateIndex index : {RateIndex::kPNd, RateIndex::kPF, RateIndex::kPI}) {
    fmt::format_to(std::back_inserter(out), "| {} |", to_string(index));
    for (std::size_t c = 0; c < stats.cases().size(); ++c)
      fmt::format_to(std::back_inserter(out), " {} |", rate_cell(stats.at(c, k), index, stats.cases()[c]));
    out += '\n';
  }
}

void markdown_mission(std::string& out, const CampaignStats& stats) {
  out += "\n### Mission outcome\n\n| outcome |";
  for (FaultCase c : stats.cases()) fmt::format_to(std::back_inserter(out), " {} |", to_string(c));
  out += "\n|---|";
  for (std::size_t i = 0; i < stats.cases().size(); ++i) out += "---|";
  out += '\n';
  const auto line = [&](const char* name, auto value) {
    fmt::format_to(std::back_inserter(out), "| {} |", name);
    for (std::size_t c = 0; c < stats.cases().size(); ++c) fmt::format_to(std::back_inserter(out), " {} |", value(c));
    out += '\n';
  };
  const auto rate = [&](RateIndex index) {
    return [&stats, index](std::size_t c) { return rate_cell(stats.at(c, 0), index, stats.cases()[c]); };
  };
  line("capture rate", rate(RateIndex::kCaptureRate));
  line("corridor kept", rate(RateIndex::kCorridorRate));
  line("mean propellant [kg]", [&](std::size_t c) { return cell(stats.at(c, 0).propellant_kg.mean(), "{:.4f}"); });
  line("diverged runs", [&](std::size_t c) { return fmt::format("{}", stats.diverged(c)); });
  line("error runs", [&](std::size_t c) { return fmt::format("{}", stats.errors(c)); });
}

void markdown_threshold(std::string& out, const SummaryContext& ctx, const GlrEnvelope& envelope) {
  const std::array<double, 2> peak = envelope.overall_max();
  fmt::format_to(std::back_inserter(out),
                 "\n### Threshold selection (Fonod 2015, Fig. 8)\n\n"
                 "Envelope of the GLR statistic S over the {} fault-free runs (glr_envelope.csv); suggested "
                 "J_th = margin x envelope maximum, margin = {} (campaign.threshold_margin). The campaign flew "
                 "fdi.glr_threshold = {}.\n\n| scheme | envelope max | suggested J_th |\n|---|---|---|\n",
                 envelope.runs(), ctx.threshold_margin, ctx.glr_threshold);
  for (int k = 0; k < 2; ++k)
    fmt::format_to(std::back_inserter(out), "| {} | {:.4g} | {:.4g} |\n", statistics_schemes()[k], peak[k],
                   ctx.threshold_margin * peak[k]);
}

}  // namespace

StatsRead read_campaign_stats(const std::string& runs_path, const std::vector<FaultCase>& cases) {
  std::ifstream in(runs_path, std::ios::binary);
  std::string line;
  if (!in || !std::getline(in, line)) return {std::nullopt, fmt::format("cannot read {}", runs_path)};
  const std::string header_text = line;
  const std::vector<std::string_view> header = split_fields(header_text);
  const FactColumns columns = fact_columns(header);
  if (!columns.complete()) return {std::nullopt, fmt::format("{}: not a campaign runs file (header)", runs_path)};
  CampaignStats stats(cases);
  for (std::int64_t n = 1; std::getline(in, line); ++n) {
    const auto facts = row_facts(split_fields(line), columns, header.size());
    if (!facts) return {std::nullopt, fmt::format("{}: row {} is malformed", runs_path, n)};
    stats.add(*facts);
  }
  return {std::move(stats), ""};
}

std::string summary_csv(const CampaignStats& stats) {
  std::string out =
      "scheme,case,runs,detected,mean_td_s,std_td_s,mean_ti_s,std_ti_s,P_nd,P_f,P_i,capture_rate,corridor_rate,"
      "mean_propellant_kg";
  for (std::string_view name : kRateNames) fmt::format_to(std::back_inserter(out), ",{0}_lo95,{0}_hi95", name);
  out += '\n';
  for (std::size_t k = 0; k < statistics_schemes().size(); ++k)
    for (std::size_t c = 0; c < stats.cases().size(); ++c) {
      const std::vector<double> v = row_values(stats.at(c, k), stats.cases()[c] != FaultCase::kNone);
      fmt::format_to(std::back_inserter(out), "{},{},{},{}", statistics_schemes()[k], to_string(stats.cases()[c]),
                     stats.at(c, k).runs, stats.at(c, k).detected);
      for (std::size_t i = 2; i < v.size(); ++i) {
        out += ',';
        append_number(out, v[i]);
      }
      append_intervals(out, stats.at(c, k), stats.cases()[c]);
      out += '\n';
    }
  return out;
}

std::string summary_markdown(const CampaignStats& stats, const SummaryContext& context,
                             const std::optional<GlrEnvelope>& envelope) {
  std::string out = fmt::format(
      "# Campaign summary: {}\n\nFonod 2015, Table 2 layout. t_d, t_i: detection and isolation time from the "
      "onset (t_i over right isolations only); P_nd = missed / runs, P_f = false alarms / runs, P_i = right "
      "isolations / runs. Runs with status error are left out of every figure.\n\n"
      "Each proportion is given with its exact (Clopper-Pearson) 95 % confidence bounds: as value [lower, upper], "
      "the two-sided 95 % interval; with no event in n runs as '0 of n (<= u)', u = 1 - 0.05^(1/n) the one-sided "
      "95 % upper bound; with an event in every run as 'n of n (>= l)', l = 0.05^(1/n) the one-sided 95 % lower "
      "bound. Bounds are rounded outward. summary.csv has the two-sided interval of each (columns `*_lo95`, "
      "`*_hi95`).\n",
      context.scenario);
  for (std::size_t k = 0; k < statistics_schemes().size(); ++k) markdown_scheme(out, stats, k);
  markdown_mission(out, stats);
  if (envelope && !envelope->empty()) markdown_threshold(out, context, *envelope);
  out += targets_markdown(stats, context.targets);
  return out;
}

std::string write_summaries(const std::string& dir, const std::vector<FaultCase>& cases,
                            const SummaryContext& context) {
  const std::filesystem::path d(dir);
  const StatsRead read = read_campaign_stats((d / "runs.csv").string(), cases);
  if (!read.stats) return read.error;
  std::optional<GlrEnvelope> envelope;
  const bool fault_free = std::find(cases.begin(), cases.end(), FaultCase::kNone) != cases.end();
  if (fault_free) {
    envelope = read_glr_envelope((d / "glr_runs.csv").string());
    if (!envelope) return fmt::format("cannot read {}", (d / "glr_runs.csv").string());
    if (!write_glr_envelope(*envelope, (d / "glr_envelope.csv").string()))
      return fmt::format("cannot write {}", (d / "glr_envelope.csv").string());
  }
  std::ofstream csv(d / "summary.csv", std::ios::binary);
  csv << summary_csv(*read.stats);
  std::ofstream md(d / "summary.md", std::ios::binary);
  md << summary_markdown(*read.stats, context, envelope);
  if (!csv || !md) return fmt::format("cannot write the summaries in {}", dir);
  return "";
}

}  // namespace chaser::campaign
