// MapReader of io/yaml_reader.hpp: typed reads of the keys of one mapping, and the unknown-key and
// duplicate-key checks.
#include "io/yaml_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <unordered_map>

#include <fmt/format.h>

#include "core/constants.hpp"

namespace chaser::io {
namespace {

// Levenshtein distance, to suggest the key a typo meant.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1] ? 1 : 0)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::string unknown_key_message(std::string_view key, const std::vector<std::string>& known) {
  std::string message = fmt::format("unknown key (allowed here: {})", fmt::join(known, ", "));
  std::size_t best = 3;  // suggest only close matches: up to two edits
  std::string_view suggestion;
  for (const std::string& k : known) {
    // Lengths that differ by more than two are more than two edits apart: skip the quadratic work.
    if (key.size() > k.size() + 2 || k.size() > key.size() + 2) continue;
    const std::size_t d = edit_distance(key, k);
    if (d < best) best = d, suggestion = k;
  }
  if (!suggestion.empty()) message += fmt::format("; did you mean '{}'?", suggestion);
  return message;
}

bool plain_scalar(const YAML::Node& node) { return node.IsScalar() && node.Tag() == "?"; }

}  // namespace

MapReader::MapReader(const YAML::Node& node, std::string key_path, Diagnostics& diag)
    : node_(node), path_(std::move(key_path)), diag_(diag), valid_(node.IsMap()) {
  if (!valid_) diag_.add(path_, fmt::format("must be a mapping of keys (got {})", describe_node(node)));
}

std::optional<YAML::Node> MapReader::find(std::string_view key, std::string_view expected) {
  accept(key);
  if (!valid_) return std::nullopt;
  for (const auto& kv : node_)
    if (kv.first.IsScalar() && kv.first.Scalar() == key) return kv.second;
  diag_.add(path_of(key), fmt::format("missing key (expected {})", expected));
  return std::nullopt;
}

bool MapReader::has(std::string_view key) const {
  if (!valid_) return false;
  for (const auto& kv : node_)
    if (kv.first.IsScalar() && kv.first.Scalar() == key) return true;
  return false;
}

void MapReader::accept(std::string_view key) {
  if (std::find(known_.begin(), known_.end(), key) == known_.end()) known_.emplace_back(key);
}

std::optional<YAML::Node> MapReader::child(std::string_view key, std::string_view expected) {
  return find(key, expected);
}

bool MapReader::number(std::string_view key, const Range& range, double& out) {
  const std::string allowed = range.describe();
  const auto node = find(key, allowed.empty() ? "a number" : "a number " + allowed);
  return node && read_number(*node, path_of(key), range, diag_, out);
}

bool MapReader::angle_deg(std::string_view key, const Range& range_deg, double& out_rad) {
  double degrees = 0.0;
  if (!number(key, range_deg, degrees)) return false;
  out_rad = degrees * kDegToRad;
  return true;
}

bool MapReader::count(std::string_view key, std::uint64_t& out) {
  const auto node = find(key, "a non-negative integer");
  if (!node) return false;
  std::string_view text = plain_scalar(*node) ? std::string_view(node->Scalar()) : "";
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  std::uint64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size()) {
    diag_.add(path_of(key), fmt::format("must be a non-negative integer below 2^64 (got {})",
                                        describe_node(*node)));
    return false;
  }
  out = value;
  return true;
}

bool MapReader::boolean(std::string_view key, bool& out) {
  const auto node = find(key, "true or false");
  if (!node) return false;
  const std::string text = plain_scalar(*node) ? node->Scalar() : "";
  if (text == "true" || text == "True" || text == "TRUE") return out = true, true;
  if (text == "false" || text == "False" || text == "FALSE") return out = false, true;
  diag_.add(path_of(key), fmt::format("must be true or false (got {})", describe_node(*node)));
  return false;
}

bool MapReader::text(std::string_view key, std::string& out) {
  const auto node = find(key, "a non-empty string");
  if (!node) return false;
  if (!node->IsScalar() || node->Scalar().empty()) {
    diag_.add(path_of(key), fmt::format("must be a non-empty string (got {})", describe_node(*node)));
    return false;
  }
  out = node->Scalar();
  return true;
}

bool MapReader::vec3(std::string_view key, Vec3& out) {
  const auto node = find(key, "a list of 3 numbers [x, y, z]");
  return node && read_vec3(*node, path_of(key), diag_, out);
}

bool MapReader::vec3(std::string_view key, const Range& element_range, Vec3& out) {
  const auto node = find(key, fmt::format("a list of 3 numbers [x, y, z], each {}", element_range.describe()));
  return node && read_vec3(*node, path_of(key), diag_, out, element_range);
}

bool MapReader::direction(std::string_view key, Vec3& out) {
  const auto node = find(key, "a nonzero direction [x, y, z]");
  Vec3 v;
  if (!node || !read_vec3(*node, path_of(key), diag_, v)) return false;
  const double norm = v.stableNorm();
  if (!(norm > 0.0)) {
    diag_.add(path_of(key), "must be a nonzero direction [x, y, z] (got [0, 0, 0])");
    return false;
  }
  if (!(norm >= kMinDirectionNorm && norm <= kMaxDirectionNorm)) {
    diag_.add(path_of(key), fmt::format("must be a direction [x, y, z] with a norm in [{}, {}], which normalises "
                                        "to full precision (got norm {})", format_number(kMinDirectionNorm),
                                        format_number(kMaxDirectionNorm), format_number(norm)));
    return false;
  }
  out = v / norm;
  return true;
}

bool MapReader::quaternion(std::string_view key, Quat& out) {
  constexpr std::string_view expected = "a unit quaternion [w, x, y, z]";
  const auto node = find(key, expected);
  const std::string path = path_of(key);
  if (!node || !check_list(*node, path, 4, expected, diag_)) return false;
  Eigen::Vector4d wxyz;
  bool ok = true;
  for (int i = 0; i < 4; ++i)
    ok &= read_number((*node)[i], join_path(path, std::to_string(i)), Range::any(), diag_, wxyz(i));
  if (!ok) return false;
  const double norm = wxyz.norm();
  if (!(std::abs(norm - 1.0) <= kQuaternionNormTolerance)) {
    diag_.add(path, fmt::format("must be a unit quaternion [w, x, y, z] with norm within {} of 1 "
                                "(got norm {})", format_number(kQuaternionNormTolerance),
                                format_number(norm)));
    return false;
  }
  out = Quat(wxyz(0), wxyz(1), wxyz(2), wxyz(3)).normalized();
  return true;
}

bool MapReader::mat3(std::string_view key, Mat3& out) {
  constexpr std::string_view expected = "a 3x3 matrix: a list of 3 rows of 3 numbers";
  const auto node = find(key, expected);
  const std::string path = path_of(key);
  if (!node || !check_list(*node, path, 3, expected, diag_)) return false;
  Mat3 m;
  bool ok = true;
  for (int i = 0; i < 3; ++i) {
    Vec3 row;
    const bool row_ok = read_vec3((*node)[i], join_path(path, std::to_string(i)), diag_, row);
    if (row_ok) m.row(i) = row.transpose();
    ok &= row_ok;
  }
  if (ok) out = m;
  return ok;
}

void MapReader::finish() {
  if (!valid_) return;
  std::unordered_map<std::string, int> seen;  // key -> its first line (1-based); a hostile mapping may have many
  for (const auto& kv : node_) {
    if (!kv.first.IsScalar()) {
      diag_.add(path_.empty() ? "(top level)" : path_,
                fmt::format("keys must be plain names (got {} as a key at line {})",
                                   describe_node(kv.first), kv.first.Mark().line + 1));
      continue;
    }
    const std::string& key = kv.first.Scalar();
    const auto [first, inserted] = seen.try_emplace(key, kv.first.Mark().line + 1);
    if (!inserted)
      diag_.add(path_of(key), fmt::format("duplicate key (first at line {})", first->second));
    else if (std::find(known_.begin(), known_.end(), key) == known_.end())
      diag_.add(path_of(key), unknown_key_message(key, known_));
  }
}

}  // namespace chaser::io
