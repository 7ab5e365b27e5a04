#include "campaign/stabilise_tables.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "campaign/csv.hpp"
#include "campaign/proportion_text.hpp"
#include "campaign/table_cells.hpp"
#include "model/arm.hpp"
#include "model/capture.hpp"

namespace chaser::campaign {

namespace {

// COMRADE 2018 Table 8: its H-infinity stabilisation's angular rate [deg/s] per axis (one value each).
constexpr std::array<double, 3> kPaperRateDegps = {-0.023, 0.006, 0.013};
std::string mean_sd(const FigureStats& s, const char* format) {
  if (s.n == 0) return "-";
  return fmt::format("{} +- {}", cell_number(s.mean, format), cell_number(s.sd, format));
}

std::string p95_verdict(const FigureStats& s, double limit, const char* format) {
  if (s.n == 0) return "-";
  return cell_number(s.p95, format) + (s.p95 < limit ? " (met)" : " (**not met**)");
}

}  // namespace

std::optional<StabiliseColumn> read_stabilise_column(const std::string& name, const std::string& runs_csv,
                                                     std::string& error) {
  const std::optional<CsvTable> table = read_csv_table(runs_csv, error);
  if (!table) return std::nullopt;
  const auto col = table->columns({"status", "stabilise_below_goal_s", "stabilise_peak_load_Nm", "stabilise_propellant_kg",
                                   "stabilise_table3_met", "stabilise_final_rate_x_deg_s", "stabilise_final_rate_y_deg_s",
                                   "stabilise_final_rate_z_deg_s"},
                                  runs_csv, "(not a campaign of a scenario with a capture section?)", error);
  if (!col) return std::nullopt;
  enum { kStatus, kBelow, kLoad, kPropellant, kMet, kRateX };

  StabiliseColumn c;
  c.name = name;
  std::array<std::vector<double>, 3> rates;
  std::vector<double> norms, belows, loads, propellants;
  for (const std::vector<std::string>& f : table->rows) {
    auto field = [&](int k) -> const std::string& { return f[static_cast<std::size_t>((*col)[static_cast<std::size_t>(k)])]; };
    auto value = [&](int k) { return parse_number(field(k)).value_or(kNaN); };
    ++c.runs;
    ++c.table3_met.runs;
    const double peak = value(kLoad);
    if (field(kStatus) != "ok" || !std::isfinite(peak)) continue;  // not flown
    ++c.flown;
    c.table3_met.events += field(kMet) == "1";
    double norm2 = 0.0;
    for (int a = 0; a < 3; ++a) {
      const double w = value(kRateX + a);
      rates[static_cast<std::size_t>(a)].push_back(w);
      norm2 += w * w;
    }
    norms.push_back(std::sqrt(norm2));
    if (const double t = value(kBelow); std::isfinite(t)) belows.push_back(t);
    loads.push_back(peak);
    propellants.push_back(value(kPropellant));
  }
  for (std::size_t a = 0; a < 3; ++a) c.final_rate_deg_s[a] = figure_stats(rates[a]);
  c.final_rate_norm_deg_s = figure_stats(norms);
  c.below_goal_s = figure_stats(belows);
  c.peak_load_Nm = figure_stats(loads);
  c.propellant_kg = figure_stats(propellants);
  return c;
}

std::string stabilise_markdown(const std::vector<StabiliseColumn>& columns) {
  std::string out = fmt::format(
      "# COMRADE 2018 Table 8: ENVISAT's detumbling, the stabilisation\n\n"
      "Mean +- 1 sigma at the end of the runs whose stabilisation flew, as the paper gives its rates\n"
      "(one run's, its H-infinity controller), and the 95th percentile (nearest rank) against COMRADE\n"
      "Table 3: the composite's rate below {} deg/s, the braked joints within the drives' repeated peak\n"
      "(docs/servicing.md).\n\n"
      "| figure | Table 3 | COMRADE H-inf |",
      model::kStabilisedRateDegps);
  for (const StabiliseColumn& c : columns) out += fmt::format(" {} |", c.name);
  out += "\n|---|---|---|";
  for (std::size_t i = 0; i < columns.size(); ++i) out += "---|";
  out += '\n';
  for (std::size_t a = 0; a < 3; ++a) {
    out += fmt::format("| angular rate {} at the end [deg/s], mean +- 1 sigma | | {:.3f} |", "XYZ"[a], kPaperRateDegps[a]);
    for (const StabiliseColumn& c : columns) out += fmt::format(" {} |", mean_sd(c.final_rate_deg_s[a], "{:.4f}"));
    out += '\n';
  }
  out += fmt::format("| angular rate at the end, magnitude [deg/s], 95th percentile | < {:g} | |", model::kStabilisedRateDegps);
  for (const StabiliseColumn& c : columns)
    out += fmt::format(" {} |", p95_verdict(c.final_rate_norm_deg_s, model::kStabilisedRateDegps, "{:.4f}"));
  out += fmt::format("\n| below {:g} deg/s for good, after the brakes [s], mean (95th percentile) | | |",
                     model::kStabilisedRateDegps);
  for (const StabiliseColumn& c : columns)
    out += c.below_goal_s.n == 0 ? std::string(" - |")
                                 : fmt::format(" {} ({}) |", cell_number(c.below_goal_s.mean, "{:.1f}"), cell_number(c.below_goal_s.p95, "{:.1f}"));
  out += fmt::format("\n| braked joints' peak load [N m], mean; 95th percentile | < {:g} | |", kRepeatedPeakTorqueNm);
  for (const StabiliseColumn& c : columns)
    out += c.peak_load_Nm.n == 0 ? std::string(" - |")
                                 : fmt::format(" {}; {} |", cell_number(c.peak_load_Nm.mean, "{:.1f}"),
                                               p95_verdict(c.peak_load_Nm, kRepeatedPeakTorqueNm, "{:.1f}"));
  out += "\n| propellant [kg], mean +- 1 sigma | | |";
  for (const StabiliseColumn& c : columns) out += fmt::format(" {} |", mean_sd(c.propellant_kg, "{:.2f}"));
  out += "\n| Table 3 met (runs) | | |";
  for (const StabiliseColumn& c : columns) out += fmt::format(" {} |", proportion_cell(c.table3_met));
  out += "\n| runs flown of runs | | |";
  for (const StabiliseColumn& c : columns) out += fmt::format(" {} of {} |", c.flown, c.runs);
  out += "\n\nEach case's runs are in its folder (runs.csv, summary.md).\n";
  return out;
}

std::string stabilise_csv(const std::vector<StabiliseColumn>& columns) {
  std::string out = "case,figure,n,mean,sd,min,p95,max,limit,paper\n";
  auto row = [&](const StabiliseColumn& c, const std::string& figure, const FigureStats& s, double limit, double paper) {
    out += fmt::format("{},{},{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", c.name, figure, s.n, s.mean,
                       s.sd, s.min, s.p95, s.max, limit, paper);
  };
  for (const StabiliseColumn& c : columns) {
    for (std::size_t a = 0; a < 3; ++a)
      row(c, fmt::format("stabilise_final_rate_{}_deg_s", "xyz"[a]), c.final_rate_deg_s[a], kNaN, kPaperRateDegps[a]);
    row(c, "stabilise_final_rate_norm_deg_s", c.final_rate_norm_deg_s, model::kStabilisedRateDegps, kNaN);
    row(c, "stabilise_below_goal_s", c.below_goal_s, kNaN, kNaN);
    row(c, "stabilise_peak_load_Nm", c.peak_load_Nm, kRepeatedPeakTorqueNm, kNaN);
    row(c, "stabilise_propellant_kg", c.propellant_kg, kNaN, kNaN);
  }
  return out;
}

}  // namespace chaser::campaign
