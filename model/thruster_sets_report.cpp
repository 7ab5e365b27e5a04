#include "model/thruster_sets_report.hpp"

#include "model/recovery.hpp"
#include "model/thruster_geometry.hpp"

namespace chaser::model {

namespace {

std::vector<std::string> names_of(ThrusterMask mask) {
  std::vector<std::string> names;
  const ThrusterList list = thruster_list(mask);
  for (int k = 0; k < list.count; ++k) names.push_back(thruster_name(list.index[k]));
  return names;
}

}  // namespace

std::vector<ThrusterSetReport> thruster_set_reports(const Scenario& s) {
  std::vector<ThrusterSetReport> reports;
  for (const ReachableConfiguration& r : reachable_configurations(s.thrusters, s.fdi.recovery)) {
    // The sets exclusion flies are the start set's single losses, which its own analysis already
    // tabulates row by row ("without Tn"): said once there instead of a full report per thruster.
    if (r.excluded_thruster != kNoThruster) continue;
    const ThrusterMask mask = r.configuration.active;
    std::string label = when_it_flies(s.thrusters, r);
    if (s.fdi.recovery == RecoveryPolicy::kExclude)
      label += " (fdi.recovery: exclude flies each of its 'without Tn' sets)";
    ThrusterSetReport report{std::move(label), names_of(mask),
                             configuration_columns(s.thrusters, mask, s.chaser.com_body_m), {}};
    report.analysis = analyse_thruster_set(report.matrix, report.names);
    reports.push_back(std::move(report));
  }
  return reports;
}

nlohmann::json thruster_sets_json(const Scenario& s, const std::vector<ThrusterSetReport>& sets) {
  nlohmann::json report{{"scenario", s.name}, {"thrusters", s.thrusters.count}, {"sets", nlohmann::json::array()}};
  for (const ThrusterSetReport& set : sets) {
    nlohmann::json entry = nlohmann::json::parse(thruster_set_analysis_json(set.analysis));
    entry["set"] = set.label;
    nlohmann::json columns = nlohmann::json::array();
    for (int c = 0; c < set.matrix.cols(); ++c)
      columns.push_back(std::vector<double>(set.matrix.col(c).data(), set.matrix.col(c).data() + 6));
    entry["configuration_matrix_columns"] = columns;  // per thruster: [Fx, Fy, Fz, Cx, Cy, Cz]
    report["sets"].push_back(entry);
  }
  return report;
}

}  // namespace chaser::model
