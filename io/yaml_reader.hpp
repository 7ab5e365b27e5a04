#pragma once
// Strict, key-path-tracking reading of YAML nodes (internal to io/).
//
// Every read knows the key path it reads, the type it expects and the allowed range; a problem is
// recorded in Diagnostics with that path and the read returns false, leaving its output untouched.
// A MapReader remembers which keys were asked for, so that finish() can report every key in the
// file that the schema does not know (typos included) and every duplicated key.
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <utility>
#include <string>
#include <string_view>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "core/types.hpp"
#include "io/scenario_loader.hpp"

namespace chaser::io {

// Quaternions in a file are normalised if their norm is this close to 1, and rejected otherwise.
inline constexpr double kQuaternionNormTolerance = 1e-6;
// A direction's norm must lie where its squares neither overflow nor underflow, so that it
// normalises to a unit vector to full precision: [1e-150, 1e150].
inline constexpr double kMinDirectionNorm = 1e-150;
inline constexpr double kMaxDirectionNorm = 1e150;

class Diagnostics {
 public:
  void add(std::string key_path, std::string message);
  // True if no problem was recorded at `key_path`, below it, or at one of its parents: the value
  // there was read and is valid, so cross-checks that use it can run without cascading errors.
  bool clean(std::string_view key_path) const;
  const std::vector<ScenarioError>& errors() const { return errors_; }

 private:
  std::vector<ScenarioError> errors_;
};

// An interval of allowed numbers; infinite ends are unbounded.
struct Range {
  double lo;
  double hi;
  bool lo_open;
  bool hi_open;

  static Range any();
  static Range positive();                      // > 0
  static Range non_negative();                  // >= 0
  static Range closed(double lo, double hi);    // [lo, hi]
  static Range open(double lo, double hi);      // (lo, hi)
  static Range left_open(double lo, double hi); // (lo, hi]
  static Range right_open(double lo, double hi);// [lo, hi)

  bool contains(double value) const;
  std::string describe() const;  // "> 0", ">= 0", "in (0, 90)", "" for any
};

std::string join_path(std::string_view parent, std::string_view key);
std::string format_number(double value);  // shortest round-trip text
std::string describe_node(const YAML::Node& node);  // what was found, for "(got ...)"

// Value readers for a node already found at key_path.
bool read_number(const YAML::Node& node, const std::string& key_path, const Range& range,
                 Diagnostics& diag, double& out);
// Each element within `element_range`.
bool read_vec3(const YAML::Node& node, const std::string& key_path, Diagnostics& diag, Vec3& out,
               const Range& element_range = Range::any());
// A list node of exactly `size` elements (any element type); reports "must be <expected>".
bool check_list(const YAML::Node& node, const std::string& key_path, std::size_t size,
                std::string_view expected, Diagnostics& diag);

class MapReader {
 public:
  // Reports "must be a mapping" if the node is not one; all reads of an invalid reader then
  // return false silently, so one wrong section gives one error, not one per key.
  MapReader(const YAML::Node& node, std::string key_path, Diagnostics& diag);

  const std::string& path() const { return path_; }
  Diagnostics& diagnostics() { return diag_; }
  std::string path_of(std::string_view key) const { return join_path(path_, key); }
  bool valid() const { return valid_; }

  bool number(std::string_view key, const Range& range, double& out);
  // A key ending in _deg: the range is checked in degrees, the value returned in radians.
  bool angle_deg(std::string_view key, const Range& range_deg, double& out_rad);
  bool count(std::string_view key, std::uint64_t& out);  // non-negative integer
  bool boolean(std::string_view key, bool& out);
  bool text(std::string_view key, std::string& out);     // non-empty scalar
  // One of named values (an enum's spellings, in the order the error lists them): reports "must be
  // one of a, b (got 'x')" for any other text and leaves out unchanged.
  template <class E>
  bool choice(std::string_view key, std::initializer_list<std::pair<std::string_view, E>> options, E& out);
  bool vec3(std::string_view key, Vec3& out);            // [x, y, z]
  bool vec3(std::string_view key, const Range& element_range, Vec3& out);  // each of x, y, z in range
  // [x, y, z], norm in [kMinDirectionNorm, kMaxDirectionNorm], normalised on load.
  bool direction(std::string_view key, Vec3& out);
  bool quaternion(std::string_view key, Quat& out);      // [w, x, y, z], normalised on load
  bool mat3(std::string_view key, Mat3& out);            // 3 rows of 3 numbers

  // A nested node (section or list): marks the key known and reports it if missing.
  std::optional<YAML::Node> child(std::string_view key, std::string_view expected);
  bool has(std::string_view key) const;
  void accept(std::string_view key);  // marks a key known without reading it

  // Reports keys the reads did not ask for (with the allowed keys and a spelling suggestion),
  // non-scalar keys, and duplicated keys.
  void finish();

 private:
  std::optional<YAML::Node> find(std::string_view key, std::string_view expected);

  YAML::Node node_;
  std::string path_;
  Diagnostics& diag_;
  bool valid_ = false;
  std::vector<std::string> known_;
};

template <class E>
bool MapReader::choice(std::string_view key, std::initializer_list<std::pair<std::string_view, E>> options, E& out) {
  std::string text_value;
  if (!text(key, text_value)) return false;
  std::string names;
  for (const auto& [name, value] : options) {
    if (name == text_value) {
      out = value;
      return true;
    }
    names += (names.empty() ? "" : ", ") + std::string(name);
  }
  diag_.add(path_of(key), "must be one of " + names + " (got '" + text_value + "')");
  return false;
}

// Reads the mapping at parent.key with fn(MapReader&), then reports its unknown keys.
template <class Fn>
void read_section(MapReader& parent, std::string_view key, Fn&& fn) {
  if (const auto node = parent.child(key, "a mapping of keys")) {
    MapReader section(*node, parent.path_of(key), parent.diagnostics());
    fn(section);
    section.finish();
  }
}

}  // namespace chaser::io
