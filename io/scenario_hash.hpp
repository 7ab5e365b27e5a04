#pragma once
// Canonical text and hash of a scenario document. The canonical text sorts mapping keys and drops
// comments and layout, so that a reformatted or reordered file keeps its hash while any change of
// a value (in the file or by an override) changes it.
#include <string>
#include <string_view>

#include <yaml-cpp/yaml.h>

namespace chaser::io {

std::string canonical_yaml(const YAML::Node& root);

// 64-bit FNV-1a (core/random.hpp hash_name) as 16 lower-case hex digits.
std::string hash_text(std::string_view text);

}  // namespace chaser::io
