#pragma once
// Inverse-simulation scenario files (scenarios/manual_rvd.yaml; Zhou 2018): parse, apply
// command-line overrides, validate completely. A separate entry point from load_scenario_file: the
// manual-RVD scenario has its own schema (docs/invsim.md), with the same rules: every problem is
// reported at once with its key path, nothing is defaulted, unknown keys are errors.
#include <optional>
#include <string>
#include <vector>

#include "io/scenario_loader.hpp"
#include "model/invsim.hpp"
#include "model/invsim_study.hpp"

namespace chaser::io {

struct InvSimLoadResult {
  std::optional<model::InvSimParams> params;  // set only if errors is empty
  model::InvSimFaultSet faults;               // the file's `faults` list (thrusters shut down)
  model::InvSimStudy study;                   // `configurations` and `optimize` (empty if absent)
  std::vector<ScenarioError> errors;          // every problem found
};

// Overrides are "key.path=value" strings as for load_scenario_file ("thrusters.1.thrust_N=50").
InvSimLoadResult load_invsim_file(const std::string& path,
                                  const std::vector<std::string>& overrides = {});
InvSimLoadResult load_invsim_text(const std::string& yaml_text,
                                  const std::vector<std::string>& overrides = {});

// Resolves thruster names to a fault set; an unknown or repeated name is an error at
// key_path.<index>. Returns nullopt if any name is wrong.
std::optional<model::InvSimFaultSet> invsim_fault_set(const model::InvSimParams& params,
                                                      const std::vector<std::string>& names,
                                                      const std::string& key_path,
                                                      std::vector<ScenarioError>& errors);

}  // namespace chaser::io
