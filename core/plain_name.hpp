#pragma once
// A plain name: what a scenario, a case, a phase or a configuration may be called wherever the name
// becomes a file or folder name, a key or a telemetry column. Letters, digits, '_', '-' and '.';
// not empty, not "." or "..". No separator, so a name can never leave the folder it is joined to
// (std::filesystem::path's operator/ would climb out with "..", and an absolute name replaces the
// folder altogether).
#include <algorithm>
#include <string_view>

namespace chaser {

inline bool is_plain_name(std::string_view name) {
  if (name.empty() || name == "." || name == "..") return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
           c == '.';
  });
}

// The rule in words, for error messages.
inline constexpr std::string_view kPlainNameRule = "letters, digits, '_', '-' and '.' only; not '.' or '..'";

}  // namespace chaser
