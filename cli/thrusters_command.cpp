// chaser thrusters: what a scenario's thruster set can do (COMRADE 2018, sec. 6: direction and
// compensability analysis). For the set that flies at the start, and for each set a recovery can
// switch to: the configuration matrix, the largest pure force and torque along each signed body
// axis, and the same for every single-thruster loss.
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/output_file.hpp"
#include "cli/scenario_input.hpp"
#include "model/recovery.hpp"
#include "model/thruster_geometry.hpp"
#include "model/thruster_set_analysis.hpp"

namespace chaser::cli {

namespace {

std::vector<std::string> names_of(model::ThrusterMask mask) {
  std::vector<std::string> names;
  const model::ThrusterList list = model::thruster_list(mask);
  for (int k = 0; k < list.count; ++k) names.push_back(model::thruster_name(list.index[k]));
  return names;
}

std::string format_matrix(const model::ThrusterSetMatrix& m, const std::vector<std::string>& names) {
  static const char* kRows[6] = {"Fx [N]", "Fy [N]", "Fz [N]", "Cx [N m]", "Cy [N m]", "Cz [N m]"};
  std::string out = fmt::format("  {:>9}", "");
  for (const std::string& n : names) out += fmt::format(" {:>7}", n);
  out += "\n";
  for (int r = 0; r < 6; ++r) {
    out += fmt::format("  {:>9}", kRows[r]);
    for (int c = 0; c < m.cols(); ++c) out += fmt::format(" {:>7.2f}", m(r, c));
    out += "\n";
  }
  return out;
}

}  // namespace

int thrusters_command(const ThrustersArgs& args) {
  const auto loaded = load_or_report(args.scenario_path, args.overrides);
  if (!loaded) return kExitBadInput;
  const model::Scenario& s = *loaded->scenario;
  nlohmann::json report{{"scenario", s.name}, {"thrusters", s.thrusters.count}, {"sets", nlohmann::json::array()}};
  std::cout << fmt::format("{}: {} thrusters; torques about the centre of mass [{}, {}, {}] m\n", s.name,
                           s.thrusters.count, s.chaser.com_body_m.x(), s.chaser.com_body_m.y(), s.chaser.com_body_m.z());
  for (const model::ReachableConfiguration& r : model::reachable_configurations(s.thrusters, s.fdi.recovery)) {
    const model::ThrusterMask mask = r.configuration.active;
    const std::string label = model::when_it_flies(s.thrusters, r);
    const std::vector<std::string> names = names_of(mask);
    const model::ThrusterSetMatrix m = model::configuration_columns(s.thrusters, mask, s.chaser.com_body_m);
    const model::ThrusterSetAnalysis analysis = model::analyse_thruster_set(m, names);
    std::cout << fmt::format("\n{} ({}):\nconfiguration matrix M (Fonod 2015, eq. 2), one column per thruster "
                             "open for a whole period:\n",
                             label, fmt::join(names, ", "));
    std::cout << format_matrix(m, names) << "\n" << model::format_thruster_set_analysis(analysis);
    nlohmann::json entry = nlohmann::json::parse(model::thruster_set_analysis_json(analysis));
    entry["set"] = label;
    nlohmann::json columns = nlohmann::json::array();
    for (int c = 0; c < m.cols(); ++c)
      columns.push_back(std::vector<double>(m.col(c).data(), m.col(c).data() + 6));
    entry["configuration_matrix_columns"] = columns;  // per thruster: [Fx, Fy, Fz, Cx, Cy, Cz]
    report["sets"].push_back(entry);
  }
  if (!args.json_path.empty()) {
    if (!write_output_file(args.json_path, report.dump(2) + "\n")) return kExitFailure;
    std::cout << fmt::format("\nwrote {}\n", args.json_path);
  }
  return kExitOk;
}

}  // namespace chaser::cli
