#pragma once
// Command-line overrides of scenario keys (the CLI's --set key.path=value), applied to the parsed
// document before it is read, so that an override is validated exactly like the file.
#include <string>

#include <yaml-cpp/yaml.h>

#include "io/yaml_reader.hpp"

namespace chaser::io {

// Parses `text` as "key.path=value" (value as YAML) and replaces the node at the path. Mapping
// keys and list indices ("faults.0.onset_s") address the node; every key but the last must exist.
// A new last key is created here and, if the schema does not know it, reported by the reader as an
// unknown key at that path. Problems (malformed text, invalid YAML value, a path that does not
// exist) are recorded at the override's key path.
void apply_override(YAML::Node& root, const std::string& text, Diagnostics& diag);

}  // namespace chaser::io
