#pragma once
// What the Python module's files share: the loaded scenario, the conversion of JSON documents to
// Python values, and the functions that add each part to the module.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

#include "io/scenario_loader.hpp"
#include "model/scenario.hpp"
#include "sim/telemetry.hpp"

namespace chaser::python {

namespace py = pybind11;

// A scenario that loaded and validated: what `chaser run` holds after load_or_report.
struct Scenario {
  model::Scenario scenario;
  std::string hash;            // of the document after overrides, as in summary.json
  std::string canonical_yaml;  // that document, keys sorted
};

// chaser.RunResult: what chaser.run and chaser.Simulation.result() give.
struct RunResult {
  py::dict summary;    // summary.json's content
  py::dict telemetry;  // channel name -> float64 array, one value per period
  std::string report;  // the text `chaser run` prints
};

// A RunResult from summary.json's text, the report and the rows recorded in memory.
RunResult run_result(const std::string& summary_json, std::string report, const sim::TelemetryRows& rows);

// Raises ValueError naming the channel patterns that match no telemetry channel of the scenario.
void check_channels(const model::Scenario& scenario, const std::vector<std::string>& patterns);

// chaser.ScenarioError with every problem: .errors the (key path, message) pairs, str() the lines
// of io::format_errors, as the command line prints them.
[[noreturn]] void raise_scenario_error(const std::vector<io::ScenarioError>& errors);

// --set strings from overrides as load_scenario takes them: None, a list of "key.path=value", or a
// dict {key.path: value}.
std::vector<std::string> override_strings(const py::object& overrides);

// A chaser.Scenario, or a path (str or os.PathLike) loaded as chaser.load_scenario(path) loads it.
Scenario scenario_argument(const py::handle& value);
// The same document with more --set overrides applied after its own (raises ScenarioError).
Scenario with_overrides(const Scenario& loaded, const std::vector<std::string>& overrides);

// A JSON document as Python values: objects as dicts, and every array of numbers, or of equal-length
// arrays of numbers, as a NumPy array (int64 when every number is an integer, float64 otherwise);
// other arrays as lists.
py::object json_to_python(const nlohmann::json& value);

void add_campaign(py::module_& m);  // campaign.cpp
void add_analyses(py::module_& m);  // analyses.cpp: thrusters, fdi_design, fmea
void add_simulation(py::module_& m);  // simulation.cpp: chaser.Simulation

}  // namespace chaser::python
