// Loading pipeline: text -> limits (io/document_limits.hpp) -> YAML document -> overrides -> limits
// again -> canonical text and hash -> typed reading of every key -> checks between keys. Exceptions
// of the YAML parser stop here: the caller gets errors as values.
#include "io/scenario_loader.hpp"

#include <sstream>

#include <fmt/format.h>

#include "io/document_limits.hpp"
#include "io/overrides.hpp"
#include "io/scenario_hash.hpp"
#include "io/scenario_sections.hpp"
#include "io/text_file.hpp"

namespace chaser::io {
namespace {

std::optional<YAML::Node> parse_document(const std::string& text, const std::string& source,
                                         Diagnostics& diag) {
  std::vector<YAML::Node> documents;
  try {
    documents = YAML::LoadAll(text);
  } catch (const YAML::Exception& e) {
    diag.add(source, fmt::format("invalid YAML at line {}, column {}: {}", e.mark.line + 1,
                                 e.mark.column + 1, e.msg));
    return std::nullopt;
  }
  if (documents.empty()) {
    diag.add(source, "is empty: expected a mapping of scenario keys");
    return std::nullopt;
  }
  if (documents.size() != 1) {
    diag.add(source, fmt::format("must hold exactly one YAML document (got {})", documents.size()));
    return std::nullopt;
  }
  return documents.front();
}

LoadResult load_document(const std::string& text, const std::string& source,
                         const std::vector<std::string>& overrides) {
  LoadResult result;
  Diagnostics diag;
  std::optional<YAML::Node> root;
  if (check_yaml_text(text, source, "", diag)) root = parse_document(text, source, diag);
  if (root) {
    for (const std::string& o : overrides) apply_override(*root, o, diag);
  }
  if (root && check_document_tree(*root, source, diag)) {
    result.canonical_yaml = canonical_yaml(*root);
    result.hash = hash_text(result.canonical_yaml);
    const model::Scenario scenario = read_scenario(*root, source, diag);
    validate_scenario(scenario, diag);
    if (diag.errors().empty()) result.scenario = scenario;
  }
  result.errors = diag.errors();
  return result;
}

}  // namespace

LoadResult load_scenario_text(const std::string& yaml_text, const std::vector<std::string>& overrides) {
  return load_document(yaml_text, "<text>", overrides);
}

LoadResult load_scenario_file(const std::string& path, const std::vector<std::string>& overrides) {
  const std::optional<std::string> text = read_text_file(path, kMaxDocumentBytes);
  if (!text) {
    LoadResult result;
    result.errors.push_back({path, kUnreadableScenario});
    return result;
  }
  return load_document(*text, path, overrides);
}

std::string format_errors(const std::vector<ScenarioError>& errors) {
  std::string out;
  for (const ScenarioError& e : errors) out += fmt::format("{}: {}\n", e.key_path, e.message);
  return out;
}

}  // namespace chaser::io
