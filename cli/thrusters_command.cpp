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

#include "cli/commands.hpp"
#include "cli/output_file.hpp"
#include "cli/scenario_input.hpp"
#include "model/thruster_sets_report.hpp"

namespace chaser::cli {

namespace {

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
  std::cout << fmt::format("{}: {} thrusters; torques about the centre of mass [{}, {}, {}] m\n", s.name,
                           s.thrusters.count, s.chaser.com_body_m.x(), s.chaser.com_body_m.y(), s.chaser.com_body_m.z());
  const std::vector<model::ThrusterSetReport> sets = model::thruster_set_reports(s);
  for (const model::ThrusterSetReport& set : sets) {
    std::cout << fmt::format("\n{} ({}):\nconfiguration matrix M (Fonod 2015, eq. 2), one column per thruster "
                             "open for a whole period:\n",
                             set.label, fmt::join(set.names, ", "));
    std::cout << format_matrix(set.matrix, set.names) << "\n" << model::format_thruster_set_analysis(set.analysis);
  }
  if (!args.json_path.empty()) {
    if (!write_output_file(args.json_path, model::thruster_sets_json(s, sets).dump(2) + "\n")) return kExitFailure;
    std::cout << fmt::format("\nwrote {}\n", args.json_path);
  }
  return kExitOk;
}

}  // namespace chaser::cli
