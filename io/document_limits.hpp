#pragma once
// Limits on a YAML document that no legitimate scenario reaches (docs/scenario.md, "Limits"),
// checked before the document is built, so that every file, however hostile, is answered quickly
// and with a key path (internal to io/).
//
// Anchors (&name) and aliases (*name) are refused outright rather than counted: yaml-cpp 0.7 builds
// an alias as a second handle on the anchored node, so nine lines can stand for a billion nodes when
// the document is walked (hashing, reading), and a --set override written through an alias would
// silently change every place that shares the node. No shipped scenario uses them.
#include <cstddef>
#include <string>
#include <string_view>

#include <yaml-cpp/yaml.h>

#include "io/yaml_reader.hpp"

namespace chaser::io {

inline constexpr std::size_t kMaxDocumentBytes = std::size_t{1} << 20;  // [B] shipped scenarios: 11 KB at most
inline constexpr int kMaxNestingDepth = 32;          // lists and mappings inside each other; shipped: 9 at most
inline constexpr std::size_t kMaxDocumentNodes = 100000;  // keys, values and list items; shipped: 774 at most
inline constexpr std::size_t kMaxScalarBytes = 1024;      // [B] one key or value; shipped: 80 at most

// Scans `text` without building it and reports at the key path where each was first found: a
// second document (the scan stops there), an anchor, an alias, nesting deeper than kMaxNestingDepth, a scalar longer
// than kMaxScalarBytes, more than kMaxDocumentNodes nodes (the scan stops there), text longer than
// kMaxDocumentBytes, and invalid YAML (at `source`, with line and column). `path_prefix` is
// prepended to key paths (an override's path). Returns true if the text may be built and walked.
bool check_yaml_text(std::string_view text, const std::string& source, const std::string& path_prefix,
                     Diagnostics& diag);

// The depth and node-count limits on a built document (after --set overrides, which may nest a
// value inside a deep path or add nodes). The walk visits at most kMaxDocumentNodes + 1 nodes and
// kMaxNestingDepth + 1 levels. Problems are reported at `source`.
bool check_document_tree(const YAML::Node& root, const std::string& source, Diagnostics& diag);

}  // namespace chaser::io
