#pragma once
// Scenario files: parse, apply command-line overrides, validate completely, hash.
//
// Every problem in a file is reported at once, each with the key path where it was found and the
// allowed range or type (docs/architecture.md: "A scenario is validated completely before a run starts").
// Nothing is defaulted: a missing key is an error. The key layout and every rule are documented in
// docs/scenario.md.
#include <optional>
#include <string>
#include <vector>

#include "model/scenario.hpp"

namespace chaser::io {

struct ScenarioError {
  std::string key_path;  // e.g. "chaser.inertia_kgm2", "faults.0.thruster"; the source name for
                         // whole-file problems (missing file, invalid YAML)
  std::string message;   // what is wrong and what is allowed, e.g. "must be > 0 (got -5)"
};

struct LoadResult {
  std::optional<model::Scenario> scenario;  // set only if errors is empty
  std::vector<ScenarioError> errors;        // every problem found, in file order of the checks
  std::string hash;            // 16 hex digits: 64-bit FNV-1a of canonical_yaml; empty if unparsable
  std::string canonical_yaml;  // the document after overrides, map keys sorted, comments dropped
};

// Overrides are "key.path=value" strings (the CLI's --set): the value is parsed as YAML and
// replaces the node at the path; list elements are addressed by index ("faults.0.onset_s=900").
// Only the last key of a path may be new, and it must be a key the schema knows.
LoadResult load_scenario_file(const std::string& path,
                              const std::vector<std::string>& overrides = {});
LoadResult load_scenario_text(const std::string& yaml_text,
                              const std::vector<std::string>& overrides = {});

// One line per problem: "key.path: message".
std::string format_errors(const std::vector<ScenarioError>& errors);

}  // namespace chaser::io
