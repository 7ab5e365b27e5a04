#include "io/scenario_hash.hpp"

#include <algorithm>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "core/random.hpp"

namespace chaser::io {
namespace {

std::string key_text(const YAML::Node& key) {
  if (key.IsScalar()) return key.Scalar();
  YAML::Emitter out;
  out << YAML::Flow << key;
  return out.c_str();
}

bool all_scalars(const YAML::Node& seq) {
  return std::all_of(seq.begin(), seq.end(), [](const YAML::Node& n) { return n.IsScalar(); });
}

void emit(YAML::Emitter& out, const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Map: {
      // Sort indices, never the nodes: assigning a YAML::Node writes through to the document.
      std::vector<std::pair<YAML::Node, YAML::Node>> pairs;
      std::vector<std::pair<std::string, std::size_t>> order;
      for (const auto& kv : node) {
        order.emplace_back(key_text(kv.first), pairs.size());
        pairs.emplace_back(kv.first, kv.second);
      }
      std::stable_sort(order.begin(), order.end(),
                       [](const auto& a, const auto& b) { return a.first < b.first; });
      out << YAML::BeginMap;
      for (const auto& entry : order) {
        out << YAML::Key;
        emit(out, pairs[entry.second].first);
        out << YAML::Value;
        emit(out, pairs[entry.second].second);
      }
      out << YAML::EndMap;
      break;
    }
    case YAML::NodeType::Sequence:
      if (all_scalars(node)) out << YAML::Flow;
      out << YAML::BeginSeq;
      for (const auto& item : node) emit(out, item);
      out << YAML::EndSeq;
      break;
    case YAML::NodeType::Scalar:
      // A quoted scalar is a string, a plain one may be a number: keep the difference.
      if (node.Tag() != "?") out << YAML::DoubleQuoted;
      out << node.Scalar();
      break;
    default:
      out << YAML::Null;
  }
}

}  // namespace

std::string canonical_yaml(const YAML::Node& root) {
  YAML::Emitter out;
  emit(out, root);
  return std::string(out.c_str()) + "\n";
}

std::string hash_text(std::string_view text) { return fmt::format("{:016x}", hash_name(text)); }

}  // namespace chaser::io
