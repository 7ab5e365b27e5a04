#pragma once
// The figures of `chaser thrusters` (COMRADE 2018, sec. 6): for the set that flies at the start and
// for each set a recovery can switch to, the configuration matrix and its thruster-set analysis.
// Computed here once for the command's text and JSON and for the Python module's chaser.thrusters.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/scenario.hpp"
#include "model/thruster_set_analysis.hpp"

namespace chaser::model {

struct ThrusterSetReport {
  std::string label;               // when_it_flies: "the set that flies at the start", ...
  std::vector<std::string> names;  // its thrusters, "T1".., one per column of `matrix`
  ThrusterSetMatrix matrix;        // Fonod 2015, eq. 2: per thruster [F [N]; C [N m]] about the centre of mass
  ThrusterSetAnalysis analysis;
};

// One report per reachable configuration of the scenario's thrusters under its fdi.recovery.
std::vector<ThrusterSetReport> thruster_set_reports(const Scenario& scenario);

// `chaser thrusters --json`'s document: {"scenario", "thrusters", "sets": [the analysis'
// thruster_set_analysis_json keys, "set": label, "configuration_matrix_columns": per thruster
// [Fx, Fy, Fz, Cx, Cy, Cz]]}.
nlohmann::json thruster_sets_json(const Scenario& scenario, const std::vector<ThrusterSetReport>& sets);

}  // namespace chaser::model
