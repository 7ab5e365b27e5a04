// Loading pipeline: text -> limits (io/document_limits.hpp) -> YAML document -> overrides -> limits
// again -> canonical text and hash -> typed reading of every key -> checks between keys. Exceptions
// of the YAML parser stop here: the caller gets errors as values.
#include "io/scenario_loader.hpp"

#include <algorithm>
#include <filesystem>
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

// A scenario may start from another: `base: FILE` (relative to the folder of the file that names
// it) is that file's document with this one's keys laid over it, mapping into mapping; a scalar or
// a list replaces the base's whole. A base may have its own, up to kMaxBases deep, never in a cycle.
constexpr int kMaxBases = 4;

// The file's identity in a chain of bases (no exception: an unresolvable path is compared as written).
std::string file_key(const std::filesystem::path& path) {
  std::error_code error;
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, error);
  return (error ? path.lexically_normal() : canonical).string();
}

void lay_over(YAML::Node& into, const YAML::Node& from) {
  for (const auto& entry : from) {
    if (!entry.first.IsScalar()) {  // not a key of the schema: kept, for the reader to name
      into[entry.first] = YAML::Clone(entry.second);
      continue;
    }
    const std::string& key = entry.first.Scalar();
    const YAML::Node& existing = static_cast<const YAML::Node&>(into)[key];
    if (existing && existing.IsMap() && entry.second.IsMap()) {
      YAML::Node child = into[key];
      lay_over(child, entry.second);
    } else {
      into[key] = YAML::Clone(entry.second);
    }
  }
}

std::optional<YAML::Node> with_base(const YAML::Node& root, const std::string& source,
                                    const std::filesystem::path& folder, std::vector<std::string>& chain,
                                    Diagnostics& diag) {
  if (!root.IsMap() || !root["base"]) return root;
  const YAML::Node& name = root["base"];
  if (!name.IsScalar() || name.Scalar().empty()) {
    diag.add("base", fmt::format("in {} must name a scenario file, relative to its folder", source));
    return std::nullopt;
  }
  const std::filesystem::path path = folder / name.Scalar();
  const std::string key = file_key(path);
  if (std::ranges::find(chain, key) != chain.end()) {
    diag.add("base", fmt::format("in {}: {} is already a base of it (a cycle)", source, path.string()));
    return std::nullopt;
  }
  if (static_cast<int>(chain.size()) > kMaxBases) {
    diag.add("base", fmt::format("in {}: more than {} bases in a chain", source, kMaxBases));
    return std::nullopt;
  }
  const std::optional<std::string> text = read_text_file(path.string(), kMaxDocumentBytes);
  if (!text) {
    diag.add("base", fmt::format("in {}: cannot read {}", source, path.string()));
    return std::nullopt;
  }
  std::optional<YAML::Node> base;
  if (check_yaml_text(*text, path.string(), "", diag)) base = parse_document(*text, path.string(), diag);
  if (!base) return std::nullopt;
  chain.push_back(key);
  base = with_base(*base, path.string(), path.parent_path(), chain, diag);
  if (!base) return std::nullopt;
  YAML::Node merged = YAML::Clone(*base);
  YAML::Node own(YAML::NodeType::Map);
  for (const auto& entry : root)
    if (!entry.first.IsScalar() || entry.first.Scalar() != "base") own[entry.first] = entry.second;
  lay_over(merged, own);
  return merged;
}

LoadResult load_document(const std::string& text, const std::string& source,
                         const std::vector<std::string>& overrides, const std::filesystem::path& folder) {
  LoadResult result;
  Diagnostics diag;
  std::optional<YAML::Node> root;
  if (check_yaml_text(text, source, "", diag)) root = parse_document(text, source, diag);
  if (root) {
    std::vector<std::string> chain;
    if (!source.empty() && source != "<text>") chain.push_back(file_key(source));
    root = with_base(*root, source, folder, chain, diag);
  }
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
  return load_document(yaml_text, "<text>", overrides, std::filesystem::current_path());
}

LoadResult load_scenario_file(const std::string& path, const std::vector<std::string>& overrides) {
  const std::optional<std::string> text = read_text_file(path, kMaxDocumentBytes);
  if (!text) {
    LoadResult result;
    result.errors.push_back({path, kUnreadableScenario});
    return result;
  }
  return load_document(*text, path, overrides, std::filesystem::path(path).parent_path());
}

std::string format_errors(const std::vector<ScenarioError>& errors) {
  std::string out;
  for (const ScenarioError& e : errors) out += fmt::format("{}: {}\n", e.key_path, e.message);
  return out;
}

}  // namespace chaser::io
