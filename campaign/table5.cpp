#include "campaign/table5.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <numeric>

#include <fmt/format.h>

#include "campaign/csv.hpp"
#include "campaign/proportion_text.hpp"
#include "campaign/table_cells.hpp"

namespace chaser::campaign {

namespace {

// COMRADE 2018 Table 1 (synchronisation requirements at the capture point) and Table 5's
// "Synchronisation H-infinity" column (mean and 1 sigma of 100 runs; its velocity row says [m]: m/s).
struct PaperRow {
  const char* figure;
  const char* unit;
  double limit;
  double paper_mean, paper_sd;
};
constexpr std::array<PaperRow, 4> kPaper = {{
    {"position error", "m", 0.1, 0.067, 0.028},
    {"velocity error", "m/s", 0.01, 0.006, 0.002},
    {"pointing error", "deg", 2.0, 1.544, 0.619},
    {"angular-rate error", "deg/s", 0.5, 0.155, 0.089},
}};
constexpr double kUnsynchronisedClearance_m = 3.0;  // Table 4
constexpr double kSynchronisedClearance_m = 0.5;

const FigureStats& figure(const Table5Column& c, std::size_t k) {
  const std::array<const FigureStats*, 4> all = {&c.position_m, &c.speed_mps, &c.attitude_deg, &c.rate_deg_s};
  return *all[k];
}

}  // namespace

FigureStats figure_stats(std::vector<double> values) {
  std::erase_if(values, [](double v) { return !std::isfinite(v); });
  FigureStats s;
  s.n = static_cast<int>(values.size());
  if (values.empty()) {
    s.mean = s.sd = s.min = s.p95 = s.max = kNaN;
    return s;
  }
  s.mean = std::accumulate(values.begin(), values.end(), 0.0) / s.n;
  double squares = 0.0;
  for (double v : values) squares += (v - s.mean) * (v - s.mean);
  s.sd = s.n > 1 ? std::sqrt(squares / (s.n - 1)) : 0.0;
  std::sort(values.begin(), values.end());
  const auto rank = static_cast<std::size_t>(std::ceil(0.95 * s.n));  // 1-based nearest rank
  s.p95 = values[std::max<std::size_t>(rank, 1) - 1];
  s.min = values.front();
  s.max = values.back();
  return s;
}

std::optional<Table5Column> read_table5_column(const std::string& name, const std::string& runs_csv,
                                               std::string& error) {
  const std::optional<CsvTable> table = read_csv_table(runs_csv, error);
  if (!table) return std::nullopt;
  const auto col = table->columns({"status", "capture", "final_position_error_m", "final_speed_mps",
                                   "final_attitude_error_deg", "final_rate_error_deg_s", "min_clearance_unsynchronised_m",
                                   "min_clearance_synchronised_m", "propellant_kg"},
                                  runs_csv, "(a runs.csv of an older Chaser?)", error);
  if (!col) return std::nullopt;
  Table5Column c;
  c.name = name;
  std::array<std::vector<double>, 4> errors;
  std::vector<double> propellant;
  c.least_clearance_unsynchronised_m = c.least_clearance_synchronised_m = kNaN;
  auto least = [](double& so_far, double v) {
    if (std::isfinite(v) && !(so_far <= v)) so_far = v;
  };
  for (const std::vector<std::string>& f : table->rows) {
    auto field = [&](int k) -> const std::string& { return f[static_cast<std::size_t>((*col)[static_cast<std::size_t>(k)])]; };
    ++c.runs;
    ++c.captured.runs;
    if (field(0) != "ok") continue;  // a diverged or failed run: not captured
    ++c.flown;
    c.captured.events += field(1) == "1";
    auto value = [&](int k) { return parse_number(field(k)).value_or(kNaN); };
    for (int k = 0; k < 4; ++k) errors[static_cast<std::size_t>(k)].push_back(value(2 + k));
    least(c.least_clearance_unsynchronised_m, value(6));
    least(c.least_clearance_synchronised_m, value(7));
    propellant.push_back(value(8));
  }
  c.position_m = figure_stats(errors[0]);
  c.speed_mps = figure_stats(errors[1]);
  c.attitude_deg = figure_stats(errors[2]);
  c.rate_deg_s = figure_stats(errors[3]);
  c.propellant_mean_kg = figure_stats(propellant).mean;
  return c;
}

std::string table5_markdown(const std::vector<Table5Column>& columns) {
  std::string out =
      "# COMRADE 2018 Table 5, synchronisation: the errors at the capture point at the end of each run\n\n"
      "Mean +- 1 sigma over the runs that flew, as the paper gives them, and the 95th percentile (nearest\n"
      "rank) against Table 1. The paper's column is the mean of 100 runs of its synchronisation with\n"
      "H-infinity control; its dispersions are not published (ours: docs/campaigns.md, \"COMRADE Table 5\").\n\n";
  out += "| figure | Table 1 | COMRADE 2018 |";
  for (const Table5Column& c : columns) out += fmt::format(" {} |", c.name);
  out += "\n|---|---|---|";
  for (std::size_t i = 0; i < columns.size(); ++i) out += "---|";
  out += '\n';
  for (std::size_t k = 0; k < kPaper.size(); ++k) {
    const PaperRow& p = kPaper[k];
    out += fmt::format("| {} [{}], mean +- 1 sigma | < {:g} | {:g} +- {:g} |", p.figure, p.unit, p.limit, p.paper_mean,
                       p.paper_sd);
    for (const Table5Column& c : columns)
      out += fmt::format(" {} +- {} |", cell_number(figure(c, k).mean, "{:.3g}"), cell_number(figure(c, k).sd, "{:.2g}"));
    out += fmt::format("\n| {} [{}], 95th percentile | < {:g} | |", p.figure, p.unit, p.limit);
    for (const Table5Column& c : columns) {
      const double v = figure(c, k).p95;
      out += fmt::format(" {}{} |", cell_number(v, "{:.3g}"), std::isfinite(v) ? (v < p.limit ? " (met)" : " (**not met**)") : "");
    }
    out += '\n';
  }
  out += "| captured (all four of Table 1 at the end) | | |";
  for (const Table5Column& c : columns) out += fmt::format(" {} |", proportion_cell(c.captured));
  out += fmt::format("\n| least clearance before the rotation's synchronisation [m] | >= {:g} (Table 4) | |",
                     kUnsynchronisedClearance_m);
  for (const Table5Column& c : columns) out += fmt::format(" {} |", cell_number(c.least_clearance_unsynchronised_m, "{:.3f}"));
  out += fmt::format("\n| least clearance after [m] | >= {:g} (Table 4) | |", kSynchronisedClearance_m);
  for (const Table5Column& c : columns) out += fmt::format(" {} |", cell_number(c.least_clearance_synchronised_m, "{:.3f}"));
  out += "\n| propellant, mean [kg] | | |";
  for (const Table5Column& c : columns) out += fmt::format(" {} |", cell_number(c.propellant_mean_kg, "{:.3f}"));
  out += "\n| runs flown of runs | | 100 |";
  for (const Table5Column& c : columns) out += fmt::format(" {} of {} |", c.flown, c.runs);
  out += "\n\nEach case's runs are in its folder (runs.csv, summary.md).\n";
  return out;
}

std::string table5_csv(const std::vector<Table5Column>& columns) {
  std::string out =
      "case,runs,flown,captured,position_mean_m,position_sd_m,position_p95_m,speed_mean_mps,speed_sd_mps,"
      "speed_p95_mps,attitude_mean_deg,attitude_sd_deg,attitude_p95_deg,rate_mean_deg_s,rate_sd_deg_s,rate_p95_deg_s,"
      "least_clearance_unsynchronised_m,least_clearance_synchronised_m,propellant_mean_kg\n";
  for (const Table5Column& c : columns) {
    out += fmt::format("{},{},{},{}", c.name, c.runs, c.flown, c.captured.events);
    for (std::size_t k = 0; k < kPaper.size(); ++k)
      out += fmt::format(",{:.17g},{:.17g},{:.17g}", figure(c, k).mean, figure(c, k).sd, figure(c, k).p95);
    out += fmt::format(",{:.17g},{:.17g},{:.17g}\n", c.least_clearance_unsynchronised_m, c.least_clearance_synchronised_m,
                       c.propellant_mean_kg);
  }
  return out;
}

}  // namespace chaser::campaign
