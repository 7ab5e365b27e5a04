// fmea.md's sections comparing thruster layouts (Zhou 2018, section 4.2) and the --optimize search.
#include <fmt/format.h>

#include "cli/fmea_report.hpp"
#include "core/constants.hpp"

namespace chaser::cli {
namespace {

double deg(double rad) { return rad / kDegToRad; }

std::string summary_cells(const invsim::LayoutSummary& s) {
  return fmt::format("{} | {} | {} | {} of {} | {} | {} | {:.1f} | {:.1f} | {:.0f} | {:.3f} | {:.2f} | {:.2f}",
                     s.per_class[0], s.per_class[1], s.per_class[2], s.controllable, s.fault_modes,
                     s.most_failed_tolerated, s.fewest_failed_lost == 0 ? std::string("none")
                                                                        : std::to_string(s.fewest_failed_lost),
                     s.propellant_kg, s.attitude_propellant_kg, s.yaw_on_time_s, s.mean_k_p, deg(s.peak_azimuth_rad),
                     deg(s.peak_yaw_rad));
}

constexpr const char* kSummaryHeader =
    "Class I | Class II | Class III | controllable | most failed, controllable | fewest failed, lost | "
    "propellant [kg] | of it attitude [kg] | yaw couple open [s] | mean k_p | peak az [deg] | peak yaw [deg] |\n";

// One cell per layout for a mode: "II: az 8.3, yaw 7.4 deg, 4.16 kg".
std::string mode_cell(const invsim::FmeaRow& row) {
  const auto& r = row.result;
  return fmt::format("{}: az {:.1f}, yaw {:.1f} deg, {:.2f} kg", invsim::risk_class_roman(row.risk),
                     deg(r.peak_azimuth_rad), deg(r.peak_attitude_rad.z()), r.propellant_kg);
}

}  // namespace

void append_reconfiguration(std::string& md, const std::vector<FmeaLayout>& layouts) {
  md += "\n## Reconfiguration: the layouts on the same fault modes (Zhou 2018, section 4.2)\n\n";
  md += "Propellant, opening time and k_p are summed or averaged over every mode (nominal included); peak "
        "azimuth and yaw over the controllable modes.\n\n";
  md += std::string("| Layout | Change | ") + kSummaryHeader + "|---|---|";
  for (int c = 0; c < 12; ++c) md += "---|";
  md += "\n";
  for (const FmeaLayout& layout : layouts)
    md += fmt::format("| {} | {} | {} |\n", layout.name, layout.description.empty() ? "—" : layout.description,
                      summary_cells(invsim::summarize_layout(layout.rows)));

  md += "\n### The baseline's Class II and III modes under each layout\n\n| Mode |";
  for (const FmeaLayout& layout : layouts) md += fmt::format(" {} |", layout.name);
  md += "\n|---|";
  for (std::size_t l = 0; l < layouts.size(); ++l) md += "---|";
  md += "\n";
  const auto& base = layouts.front().rows;
  for (std::size_t i = 0; i < base.size(); ++i) {
    if (base[i].risk == invsim::RiskClass::kSmallDeviation) continue;
    md += fmt::format("| {} |", base[i].fmea_case.mode.label);
    for (const FmeaLayout& layout : layouts) md += fmt::format(" {} |", mode_cell(layout.rows[i]));
    md += "\n";
  }
  for (std::size_t l = 1; l < layouts.size(); ++l)
    append_table6(md, layouts[l].params, layouts[l].rows,
                  fmt::format("\n### Table 6 with layout {}\n\n", layouts[l].name));
}

void append_optimization(std::string& md, const std::vector<FmeaLayout>& layouts,
                         const std::vector<invsim::LayoutCandidate>& optimized, int keep) {
  md += fmt::format("\n## Optimisation (`chaser fmea --optimize`): {} candidate layouts\n\n", optimized.size());
  md += "Every combination of the scenario's free choices (`optimize.choices`) flown through the same fault modes; "
        "best first: the nominal run docks, then the most controllable fault modes, the fewest Class II, the least "
        "propellant, the lowest mean k_p. The scenario's layouts follow for comparison. Every candidate is in "
        "optimize.csv.\n\n";
  md += std::string("| Rank | Layout | ") + kSummaryHeader + "|---|---|";
  for (int c = 0; c < 12; ++c) md += "---|";
  md += "\n";
  const std::size_t shown = std::min<std::size_t>(optimized.size(), static_cast<std::size_t>(std::max(keep, 0)));
  for (std::size_t k = 0; k < shown; ++k)
    md += fmt::format("| {} | {} | {} |\n", k + 1, optimized[k].configuration.name,
                      summary_cells(optimized[k].summary));
  for (const FmeaLayout& layout : layouts)
    md += fmt::format("| — | {} | {} |\n", layout.name, summary_cells(invsim::summarize_layout(layout.rows)));
  if (shown > 0 && !optimized.front().configuration.description.empty())
    md += fmt::format("\nBest candidate: {}.\n", optimized.front().configuration.description);
}

std::string optimize_csv(const std::vector<invsim::LayoutCandidate>& candidates) {
  std::string csv =
      "rank,candidate,nominal_controllable,class_I,class_II,class_III,controllable,fault_modes,"
      "most_failed_tolerated,fewest_failed_lost,propellant_kg,attitude_propellant_kg,yaw_on_time_s,mean_k_p,"
      "peak_azimuth_deg,peak_yaw_deg\n";
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const invsim::LayoutSummary& s = candidates[k].summary;
    csv += fmt::format("{},\"{}\",{},{},{},{},{},{},{},{},{:.4f},{:.4f},{:.2f},{:.4f},{:.4f},{:.4f}\n", k + 1,
                       candidates[k].configuration.name, s.nominal_controllable ? "true" : "false", s.per_class[0],
                       s.per_class[1], s.per_class[2], s.controllable, s.fault_modes, s.most_failed_tolerated,
                       s.fewest_failed_lost, s.propellant_kg, s.attitude_propellant_kg, s.yaw_on_time_s, s.mean_k_p,
                       deg(s.peak_azimuth_rad), deg(s.peak_yaw_rad));
  }
  return csv;
}

}  // namespace chaser::cli
