#include "campaign/reach_tables.hpp"

#include <cmath>
#include <fstream>
#include <limits>

#include <fmt/format.h>

#include "campaign/csv.hpp"
#include "campaign/proportion_text.hpp"
#include "campaign/run_row.hpp"
#include "campaign/table_cells.hpp"
#include "model/arm.hpp"
#include "sim/reach_result.hpp"

namespace chaser::campaign {

namespace {

// A paper's mean +- 1 sigma; sd NaN where the paper prints "< 0.001".
struct PaperValue {
  double mean, sd;
};

// COMRADE 2018 Table 5, its reach columns (the means and 1 sigma of 100 runs; the velocity row
// says [m]: m/s), against Table 2's chaser requirements.
struct ChaserRow {
  const char* figure;
  const char* unit;
  const char* column;  // runs.csv
  double limit;
  PaperValue hinf, compliance;
};
const std::array<ChaserRow, 4> kChaserRows = {{
    {"position error", "m", "final_position_error_m", sim::kTable2ChaserPositionM, {0.023, 0.008}, {0.026, 0.011}},
    {"velocity error", "m/s", "final_speed_mps", sim::kTable2ChaserVelocityMps, {0.002, kNaN}, {0.001, kNaN}},
    {"pointing error", "deg", "final_attitude_error_deg", sim::kTable2ChaserAttitudeDeg, {0.318, 0.153}, {0.105, 0.077}},
    {"angular-rate error", "deg/s", "final_rate_error_deg_s", sim::kTable2ChaserRateDegps, {0.075, 0.041}, {0.114, 0.047}},
}};

// COMRADE 2018 Table 6 (the gripper against the grappling point: means and 1 sigma of its runs, in
// m, m/s, deg and deg/s), per figure and axis.
using PaperAxes = std::array<PaperValue, 3>;
const std::array<PaperAxes, kGripperFigures> kGripperHinf = {{
    {{{-0.001, 0.004}, {0.002, 0.005}, {-0.001, 0.004}}},
    {{{0.001, 0.003}, {0.001, 0.003}, {-0.001, 0.002}}},
    {{{-0.016, 0.105}, {-0.033, 0.140}, {-0.015, 0.293}}},
    {{{0.011, 0.073}, {-0.004, 0.098}, {0.029, 0.191}}},
}};
const std::array<PaperAxes, kGripperFigures> kGripperCompliance = {{
    {{{0.004, 0.003}, {0.005, 0.003}, {0.003, 0.002}}},
    {{{0.004, 0.003}, {0.005, 0.003}, {0.005, 0.003}}},
    {{{0.120, 0.084}, {0.086, 0.054}, {0.182, 0.113}}},
    {{{0.520, 0.335}, {0.286, 0.217}, {0.434, 0.314}}},
}};

// How each gripper figure is shown: position and velocity in mm and mm/s.
struct GripperFigure {
  const char* name;
  const char* unit;
  double scale;  // from runs.csv's unit to the shown one
};
constexpr std::array<GripperFigure, kGripperFigures> kGripperShown = {{
    {"position", "mm", 1e3}, {"velocity", "mm/s", 1e3}, {"attitude", "deg", 1.0}, {"angular rate", "deg/s", 1.0}}};

bool is_hinf(const ReachColumn& c) { return c.law == "hinf"; }
const char* law_label(const ReachColumn& c) { return is_hinf(c) ? "H-infinity" : "compliance"; }
const char* paper_label(const ReachColumn& c) { return is_hinf(c) ? "COMRADE H-inf" : "COMRADE compliant"; }

std::string mean_sd(double mean, double sd, double scale, const char* format) {
  if (!std::isfinite(mean)) return "-";
  const std::string sd_text = std::isfinite(sd) ? cell_number(sd * scale, format) : fmt::format("< {:g}", 0.001 * scale);
  return fmt::format("{} +- {}", cell_number(mean * scale, format), sd_text);
}

std::string p95_verdict(double p95, double limit, double scale, const char* format) {
  if (!std::isfinite(p95)) return "-";
  return cell_number(p95 * scale, format) + (p95 < limit ? " (met)" : " (**not met**)");
}

}  // namespace

std::optional<ReachColumn> read_reach_column(const std::string& law, const std::string& runs_csv, std::string& error) {
  const std::optional<CsvTable> table = read_csv_table(runs_csv, error);
  if (!table) return std::nullopt;
  // Columns: status, the verdict, the torque, the clearance, the chaser's four, then per gripper
  // figure and axis the final and the over-the-hold value.
  std::vector<std::string> names = {"status", "reach_table2_met", "reach_peak_joint_torque_Nm", "reach_min_tool_clearance_m"};
  for (const ChaserRow& row : kChaserRows) names.emplace_back(row.column);
  for (int f = 0; f < kGripperFigures; ++f)
    for (int a = 0; a < 3; ++a) {
      names.push_back(reach_column_name(false, f, a));
      names.push_back(reach_column_name(true, f, a));
    }
  const auto col = table->columns(names, runs_csv, "(not a campaign of a scenario with a capture section?)", error);
  if (!col) return std::nullopt;
  constexpr std::size_t kStatus = 0, kMet = 1, kTorque = 2, kClearance = 3, kChaser = 4, kGripper = 8;
  const auto gripper = [](std::size_t figure, std::size_t axis, bool over_hold) {
    return kGripper + 2 * (3 * figure + axis) + (over_hold ? 1 : 0);
  };

  ReachColumn c;
  c.law = law;
  std::array<std::vector<double>, 4> chaser;
  std::array<std::array<std::vector<double>, 3>, kGripperFigures> finals, maxima;
  std::vector<double> torques, clearances;
  for (const std::vector<std::string>& f : table->rows) {
    auto field = [&](std::size_t k) -> const std::string& { return f[static_cast<std::size_t>((*col)[k])]; };
    auto value = [&](std::size_t k) { return parse_number(field(k)).value_or(kNaN); };
    ++c.runs;
    ++c.table2_met.runs;
    if (field(kStatus) != "ok" || !std::isfinite(value(gripper(0, 0, true)))) continue;
    ++c.flown;
    c.table2_met.events += field(kMet) == "1";
    for (std::size_t k = 0; k < chaser.size(); ++k) chaser[k].push_back(value(kChaser + k));
    for (std::size_t g = 0; g < finals.size(); ++g)
      for (std::size_t a = 0; a < 3; ++a) {
        finals[g][a].push_back(value(gripper(g, a, false)));
        maxima[g][a].push_back(value(gripper(g, a, true)));
      }
    torques.push_back(value(kTorque));
    clearances.push_back(value(kClearance));
  }
  for (std::size_t k = 0; k < chaser.size(); ++k) c.chaser[k] = figure_stats(chaser[k]);
  for (std::size_t g = 0; g < finals.size(); ++g)
    for (std::size_t a = 0; a < 3; ++a) {
      c.gripper_final[g][a] = figure_stats(finals[g][a]);
      c.gripper_max[g][a] = figure_stats(maxima[g][a]);
    }
  c.peak_joint_torque_Nm = figure_stats(torques);
  c.tool_clearance_m = figure_stats(clearances);
  return c;
}

std::string reach_markdown(const std::vector<ReachColumn>& columns) {
  std::string out =
      "# COMRADE 2018 Tables 5 and 6, reach: the chaser and the gripper\n\n"
      "Mean +- 1 sigma at the end of the runs that flew, as the paper gives them (its means of 100 runs),\n"
      "and the 95th percentile (nearest rank) against COMRADE Table 2: the chaser's at the end, the\n"
      "gripper's of the largest |value| per axis over the hold at the pre-grasp pose (docs/servicing.md).\n\n"
      "## Table 5, reach columns: the chaser against the capture point at the end\n\n"
      "| figure | Table 2 |";
  for (const ReachColumn& c : columns) out += fmt::format(" {} | {} |", paper_label(c), law_label(c));
  out += "\n|---|---|";
  for (std::size_t i = 0; i < columns.size(); ++i) out += "---|---|";
  out += '\n';
  for (std::size_t k = 0; k < kChaserRows.size(); ++k) {
    const ChaserRow& row = kChaserRows[k];
    out += fmt::format("| {} [{}], mean +- 1 sigma | < {:g} |", row.figure, row.unit, row.limit);
    for (const ReachColumn& c : columns) {
      const PaperValue& p = is_hinf(c) ? row.hinf : row.compliance;
      out += fmt::format(" {} | {} |", mean_sd(p.mean, p.sd, 1.0, "{:.3f}"),
                         mean_sd(c.chaser[k].mean, c.chaser[k].sd, 1.0, "{:.3f}"));
    }
    out += fmt::format("\n| {} [{}], 95th percentile | < {:g} |", row.figure, row.unit, row.limit);
    for (const ReachColumn& c : columns) out += fmt::format(" | {} |", p95_verdict(c.chaser[k].p95, row.limit, 1.0, "{:.3f}"));
    out += '\n';
  }

  out += "\n## Table 6: the gripper against the grasping point (x the approach)\n\n| figure | Table 2 |";
  for (const ReachColumn& c : columns)
    out += fmt::format(" {} | {}, at the end | {}, over the hold: 95th percentile |", paper_label(c), law_label(c),
                       law_label(c));
  out += "\n|---|---|";
  for (std::size_t i = 0; i < columns.size(); ++i) out += "---|---|---|";
  out += '\n';
  for (int g = 0; g < kGripperFigures; ++g) {
    const GripperFigure& shown = kGripperShown[static_cast<std::size_t>(g)];
    const char* format = shown.scale > 1.0 ? "{:.1f}" : "{:.3f}";
    for (int a = 0; a < 3; ++a) {
      const double limit = sim::table2_gripper_limit(g, a);
      out += fmt::format("| {} {} [{}] | +- {:g} |", shown.name, "xyz"[a], shown.unit, limit * shown.scale);
      const auto gi = static_cast<std::size_t>(g), ai = static_cast<std::size_t>(a);
      for (const ReachColumn& c : columns) {
        const PaperValue& p = (is_hinf(c) ? kGripperHinf : kGripperCompliance)[gi][ai];
        const FigureStats& end = c.gripper_final[gi][ai];
        out += fmt::format(" {} | {} | {} |", mean_sd(p.mean, p.sd, shown.scale, shown.scale > 1.0 ? "{:.0f}" : "{:.3f}"),
                           mean_sd(end.mean, end.sd, shown.scale, format),
                           p95_verdict(c.gripper_max[gi][ai].p95, limit, shown.scale, format));
      }
      out += '\n';
    }
  }

  out += "\n## The runs\n\n| | limit |";
  for (const ReachColumn& c : columns) out += fmt::format(" {} |", law_label(c));
  out += "\n|---|---|";
  for (std::size_t i = 0; i < columns.size(); ++i) out += "---|";
  out += "\n| gripper inside every figure of Table 2 over the hold | |";
  for (const ReachColumn& c : columns) out += fmt::format(" {} |", proportion_cell(c.table2_met));
  out += fmt::format("\n| peak joint torque, largest of the runs [N m] | {:g} (repeated peak) |", kRepeatedPeakTorqueNm);
  for (const ReachColumn& c : columns) out += fmt::format(" {} |", cell_number(c.peak_joint_torque_Nm.max, "{:.1f}"));
  out += "\n| the tool point's least clearance from the keep-out volume, least of the runs [m] | > 0 |";
  for (const ReachColumn& c : columns) out += fmt::format(" {} |", cell_number(c.tool_clearance_m.min, "{:.3f}"));
  out += "\n| runs flown of runs | |";
  for (const ReachColumn& c : columns) out += fmt::format(" {} of {} |", c.flown, c.runs);
  out += "\n\nEach law's runs are in its folder (runs.csv, summary.md).\n";
  return out;
}

std::string reach_csv(const std::vector<ReachColumn>& columns) {
  std::string out = "law,figure,n,mean,sd,min,p95,max,limit,paper_mean,paper_sd\n";
  auto row = [&](const ReachColumn& c, const std::string& figure, const FigureStats& s, double limit, PaperValue paper) {
    out += fmt::format("{},{},{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", c.law, figure, s.n,
                       s.mean, s.sd, s.min, s.p95, s.max, limit, paper.mean, paper.sd);
  };
  const PaperValue none{kNaN, kNaN};
  for (const ReachColumn& c : columns) {
    for (std::size_t k = 0; k < kChaserRows.size(); ++k)
      row(c, kChaserRows[k].column, c.chaser[k], kChaserRows[k].limit,
          is_hinf(c) ? kChaserRows[k].hinf : kChaserRows[k].compliance);
    for (int g = 0; g < kGripperFigures; ++g)
      for (int a = 0; a < 3; ++a) {
        const auto gi = static_cast<std::size_t>(g), ai = static_cast<std::size_t>(a);
        const PaperValue paper = (is_hinf(c) ? kGripperHinf : kGripperCompliance)[gi][ai];
        row(c, reach_column_name(false, g, a), c.gripper_final[gi][ai], sim::table2_gripper_limit(g, a), paper);
        row(c, reach_column_name(true, g, a), c.gripper_max[gi][ai], sim::table2_gripper_limit(g, a), none);
      }
    row(c, "reach_peak_joint_torque_Nm", c.peak_joint_torque_Nm, kRepeatedPeakTorqueNm, none);
    const double met = c.table2_met.runs > 0 ? static_cast<double>(c.table2_met.events) / c.table2_met.runs : kNaN;
    out += fmt::format("{},reach_table2_met,{},{:.17g},nan,nan,nan,nan,nan,nan,nan\n", c.law, c.table2_met.runs, met);
    row(c, "reach_min_tool_clearance_m", c.tool_clearance_m, 0.0, none);
  }
  return out;
}

}  // namespace chaser::campaign
