// Diagnostics, ranges and the readers of single values (numbers, vectors) of io/yaml_reader.hpp.
#include <charconv>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "io/yaml_reader.hpp"

namespace chaser::io {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

bool starts_with_path(std::string_view path, std::string_view prefix) {
  return path.size() > prefix.size() && path.substr(0, prefix.size()) == prefix &&
         path[prefix.size()] == '.';
}

// A plain (unquoted) YAML scalar that is a finite decimal number. Quoted strings are text, not
// numbers, as in YAML's core schema.
std::optional<double> parse_number(const YAML::Node& node) {
  if (!node.IsScalar() || node.Tag() != "?") return std::nullopt;
  std::string_view text = node.Scalar();
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    return std::nullopt;
  return value;
}

}  // namespace

void Diagnostics::add(std::string key_path, std::string message) {
  errors_.push_back({std::move(key_path), std::move(message)});
}

bool Diagnostics::clean(std::string_view key_path) const {
  for (const ScenarioError& e : errors_) {
    if (e.key_path == key_path || starts_with_path(e.key_path, key_path) ||
        starts_with_path(key_path, e.key_path))
      return false;
  }
  return true;
}

Range Range::any() { return {-kInf, kInf, false, false}; }
Range Range::positive() { return {0.0, kInf, true, false}; }
Range Range::non_negative() { return {0.0, kInf, false, false}; }
Range Range::closed(double lo, double hi) { return {lo, hi, false, false}; }
Range Range::open(double lo, double hi) { return {lo, hi, true, true}; }
Range Range::left_open(double lo, double hi) { return {lo, hi, true, false}; }
Range Range::right_open(double lo, double hi) { return {lo, hi, false, true}; }

bool Range::contains(double value) const {
  const bool above = lo_open ? value > lo : value >= lo;
  const bool below = hi_open ? value < hi : value <= hi;
  return above && below;
}

std::string Range::describe() const {
  if (lo == -kInf && hi == kInf) return "";
  if (hi == kInf) return (lo_open ? "> " : ">= ") + format_number(lo);
  if (lo == -kInf) return (hi_open ? "< " : "<= ") + format_number(hi);
  return fmt::format("in {}{}, {}{}", lo_open ? '(' : '[', format_number(lo), format_number(hi),
                     hi_open ? ')' : ']');
}

std::string join_path(std::string_view parent, std::string_view key) {
  if (parent.empty()) return std::string(key);
  return fmt::format("{}.{}", parent, key);
}

std::string format_number(double value) { return fmt::format("{}", value); }

std::string describe_node(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return "nothing";
  if (node.IsSequence()) return fmt::format("a list of {}", node.size());
  if (node.IsMap()) return "a mapping";
  std::string text = node.Scalar();
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return node.Tag() == "?" ? fmt::format("'{}'", text) : fmt::format("the quoted string \"{}\"", text);
}

bool read_number(const YAML::Node& node, const std::string& key_path, const Range& range,
                 Diagnostics& diag, double& out) {
  const std::string allowed = range.describe();
  const std::optional<double> value = parse_number(node);
  if (!value) {
    diag.add(key_path, fmt::format("must be a number{}{} (got {})", allowed.empty() ? "" : " ",
                                   allowed, describe_node(node)));
    return false;
  }
  if (!range.contains(*value)) {
    diag.add(key_path, fmt::format("must be {} (got {})", allowed, format_number(*value)));
    return false;
  }
  out = *value;
  return true;
}

bool check_list(const YAML::Node& node, const std::string& key_path, std::size_t size,
                std::string_view expected, Diagnostics& diag) {
  if (!node.IsSequence() || node.size() != size) {
    diag.add(key_path, fmt::format("must be {} (got {})", expected, describe_node(node)));
    return false;
  }
  return true;
}

bool read_vec3(const YAML::Node& node, const std::string& key_path, Diagnostics& diag, Vec3& out,
               const Range& element_range) {
  if (!check_list(node, key_path, 3, "a list of 3 numbers [x, y, z]", diag)) return false;
  Vec3 v;
  bool ok = true;
  for (int i = 0; i < 3; ++i)
    ok &= read_number(node[i], join_path(key_path, std::to_string(i)), element_range, diag, v(i));
  if (ok) out = v;
  return ok;
}

}  // namespace chaser::io
