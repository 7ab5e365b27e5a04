#include "io/overrides.hpp"

#include <charconv>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "io/document_limits.hpp"

namespace chaser::io {
namespace {

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

// The override as echoed in a message: a hostile one may be long.
std::string shown(const std::string& text) { return text.size() <= 200 ? text : text.substr(0, 197) + "..."; }

std::vector<std::string> split_path(std::string_view path) {
  std::vector<std::string> segments;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = path.find('.', start);
    segments.emplace_back(path.substr(start, dot == std::string_view::npos ? dot : dot - start));
    if (dot == std::string_view::npos) return segments;
    start = dot + 1;
  }
}

std::optional<std::size_t> parse_index(const std::string& segment, std::size_t size) {
  std::size_t index = 0;
  const auto [end, ec] = std::from_chars(segment.data(), segment.data() + segment.size(), index);
  if (segment.empty() || ec != std::errc() || end != segment.data() + segment.size() || index >= size)
    return std::nullopt;
  return index;
}

// The child of a mapping or list, or nothing. Never creates a node (yaml-cpp's non-const
// operator[] would, and would turn a list into a mapping when given a name).
std::optional<YAML::Node> existing_child(const YAML::Node& node, const std::string& segment) {
  if (node.IsMap()) {
    for (const auto& kv : node)
      if (kv.first.IsScalar() && kv.first.Scalar() == segment) return kv.second;
  } else if (node.IsSequence()) {
    if (const auto index = parse_index(segment, node.size())) return node[*index];
  }
  return std::nullopt;
}

std::string where(const std::vector<std::string>& segments, std::size_t count) {
  if (count == 0) return "the top level";
  std::vector<std::string> head(segments.begin(), segments.begin() + static_cast<long>(count));
  return fmt::format("'{}'", fmt::join(head, "."));
}

std::string missing_child(const YAML::Node& node, const std::string& segment, const std::string& parent) {
  if (!node.IsSequence())
    return fmt::format("no key '{}' {}{}", segment, parent == "the top level" ? "at " : "in ", parent);
  if (node.size() == 0) return fmt::format("'{}' is not an index of the list {}: it is empty", segment, parent);
  return fmt::format("'{}' is not an index of the list {} (0..{})", segment, parent, node.size() - 1);
}

// Replaces the node at `segments` with `value`; returns an error message or "" on success.
std::string replace_at(YAML::Node& root, const std::vector<std::string>& segments,
                       const YAML::Node& value) {
  YAML::Node node(root);  // a handle on the same document; reset() rebinds it, = would overwrite
  for (std::size_t i = 0; i + 1 < segments.size(); ++i) {
    const auto next = existing_child(node, segments[i]);
    if (!next) return missing_child(node, segments[i], where(segments, i));
    node.reset(*next);
  }
  const std::string& last = segments.back();
  if (node.IsSequence()) {
    const auto index = parse_index(last, node.size());
    if (!index) return missing_child(node, last, where(segments, segments.size() - 1));
    node[*index] = value;
    return "";
  }
  if (!node.IsMap())
    return fmt::format("{} is not a mapping or a list", where(segments, segments.size() - 1));
  if (const auto existing = existing_child(node, last)) {
    YAML::Node target(*existing);
    target = value;  // assigning through the handle replaces the node in the document
  } else {
    node[last] = value;
  }
  return "";
}

}  // namespace

void apply_override(YAML::Node& root, const std::string& text, Diagnostics& diag) {
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos) {
    diag.add(shown(text), fmt::format("malformed override '{}': expected key.path=value", shown(text)));
    return;
  }
  const std::string path(trim(std::string_view(text).substr(0, eq)));
  const std::vector<std::string> segments = split_path(path);
  if (path.size() > kMaxScalarBytes) {
    diag.add(path.substr(0, 40) + "...", fmt::format("override key path of {} bytes: a key path may be at most {} bytes long",
                                                     path.size(), kMaxScalarBytes));
    return;
  }
  if (segments.size() > static_cast<std::size_t>(kMaxNestingDepth)) {
    diag.add(path, fmt::format("override key path of {} parts: a key path may have at most {}", segments.size(),
                               kMaxNestingDepth));
    return;
  }
  for (const std::string& s : segments) {
    if (s.empty()) {
      diag.add(path, fmt::format("malformed override '{}': the key path has an empty part", shown(text)));
      return;
    }
  }
  if (!check_yaml_text(std::string_view(text).substr(eq + 1), path, path, diag)) return;
  YAML::Node value;
  try {
    value = YAML::Load(text.substr(eq + 1));
  } catch (const YAML::Exception& e) {
    diag.add(path, fmt::format("override '{}': the value is not valid YAML (column {}: {})", shown(text),
                               e.mark.column + 1, e.msg));
    return;
  }
  const std::string problem = replace_at(root, segments, value);
  if (!problem.empty()) diag.add(path, fmt::format("override '{}': {}", shown(text), problem));
}

}  // namespace chaser::io
